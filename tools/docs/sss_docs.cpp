// sss_docs: what keeps the README and docs/ true, and the README's generated numbers.
//
//   sss_docs links ROOT PATH...        every relative link and image in the markdown files (a folder:
//                                      every *.md under it) names a file or folder that exists, and a
//                                      #anchor into a markdown file names one of its headings
//   sss_docs example ROOT README       each fenced block that follows "<!-- example: PATH ... -->" in
//                                      README equals the lines of ROOT/PATH between the lines holding
//                                      "readme-example: begin" and "readme-example: end"
//   sss_docs headline ROOT README [--write]
//                                      the lines between "<!-- headline: begin" and "<!-- headline: end -->"
//                                      in README equal the table made from the committed benchmark
//                                      results (ROOT/docs/benchmarks/results.csv and .json, and
//                                      ROOT/docs/benchmarks-gpu/ when present); --write rewrites them
//                                      (scripts/update-readme-numbers.sh)
//
// Exit status 0 when everything holds (or was written), 1 when something does not (each problem on
// stderr), 2 for bad usage or unreadable inputs. No dependency beyond the C++17 standard library.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Failure {};  // unreadable input: exit status 2

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "sss_docs: cannot read " << path.generic_string() << "\n";
    throw Failure{};
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// A fence line (``` or ~~~, possibly indented): opens or closes a code block.
bool is_fence(const std::string& line) {
  const std::string t = trim(line);
  return starts_with(t, "```") || starts_with(t, "~~~");
}

// ---------------------------------------------------------------------------------------------
// links

// GitHub's heading anchor: lower case, spaces to hyphens, punctuation and symbols dropped (letters,
// digits, '-' and '_' kept; other non-ASCII characters kept but for the common symbols below).
std::string slug(const std::string& heading) {
  static const std::vector<std::string> dropped = {"×", "—", "–", "·", "’", "‘", "“", "”", "…", "→", "←", "≤", "≥",
                                                   "±", "‖", "°", "§", "²", "³", "¹"};
  std::string out;
  for (std::size_t i = 0; i < heading.size();) {
    const unsigned char c = static_cast<unsigned char>(heading[i]);
    if (c < 0x80) {
      if (std::isalnum(c) || c == '-' || c == '_') out += static_cast<char>(std::tolower(c));
      else if (c == ' ') out += '-';
      ++i;
      continue;
    }
    std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
    const std::string ch = heading.substr(i, n);
    if (std::find(dropped.begin(), dropped.end(), ch) == dropped.end()) out += ch;
    i += n;
  }
  return out;
}

// The anchors of a markdown file: its headings' slugs (a repeated one gets -1, -2, ...), and the
// name/id of HTML anchors.
std::set<std::string> anchors_of(const fs::path& file) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  bool in_code = false;
  for (const std::string& line : split_lines(read_text(file))) {
    if (is_fence(line)) {
      in_code = !in_code;
      continue;
    }
    if (in_code) continue;
    if (starts_with(line, "#")) {
      std::size_t level = 0;
      while (level < line.size() && line[level] == '#') ++level;
      if (level <= 6 && level < line.size() && line[level] == ' ') {
        std::string text = trim(line.substr(level));
        while (!text.empty() && text.back() == '#') text.pop_back();
        const std::string base = slug(trim(text));
        const int n = seen[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
      }
    }
    for (const char* attr : {"name=\"", "id=\""}) {
      for (std::size_t at = line.find(attr); at != std::string::npos; at = line.find(attr, at + 1)) {
        const std::size_t b = at + std::string(attr).size(), e = line.find('"', b);
        if (e != std::string::npos) anchors.insert(line.substr(b, e - b));
      }
    }
  }
  return anchors;
}

// The line with its inline code spans removed (links inside `...` are examples, not links).
std::string without_code_spans(const std::string& line) {
  std::string out;
  for (std::size_t i = 0; i < line.size();) {
    if (line[i] != '`') {
      out += line[i++];
      continue;
    }
    std::size_t ticks = 0;
    while (i + ticks < line.size() && line[i + ticks] == '`') ++ticks;
    const std::size_t close = line.find(std::string(ticks, '`'), i + ticks);
    if (close == std::string::npos) {
      out += line.substr(i);
      break;
    }
    i = close + ticks;
  }
  return out;
}

// Link targets of one line: [text](target "title"), ![alt](target), <img src="target">.
std::vector<std::string> link_targets(const std::string& raw) {
  const std::string line = without_code_spans(raw);
  std::vector<std::string> targets;
  for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
    std::size_t b = at + 2, depth = 1, e = b;
    for (; e < line.size(); ++e) {
      if (line[e] == '(') ++depth;
      if (line[e] == ')' && --depth == 0) break;
    }
    if (e >= line.size()) continue;
    std::string target = trim(line.substr(b, e - b));
    if (const std::size_t space = target.find(' '); space != std::string::npos) target = target.substr(0, space);
    if (target.size() >= 2 && target.front() == '<' && target.back() == '>') target = target.substr(1, target.size() - 2);
    targets.push_back(target);
  }
  for (std::size_t at = line.find("src=\""); at != std::string::npos; at = line.find("src=\"", at + 1)) {
    const std::size_t b = at + 5, e = line.find('"', b);
    if (e != std::string::npos) targets.push_back(line.substr(b, e - b));
  }
  return targets;
}

int check_links(const fs::path& root, const std::vector<std::string>& paths) {
  std::vector<fs::path> files;
  for (const std::string& p : paths) {
    const fs::path full = root / p;
    if (fs::is_directory(full)) {
      for (const auto& entry : fs::recursive_directory_iterator(full)) {
        if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
      }
    } else if (fs::is_regular_file(full)) {
      files.push_back(full);
    } else {
      std::cerr << "sss_docs: no such file or folder: " << full.generic_string() << "\n";
      throw Failure{};
    }
  }
  std::sort(files.begin(), files.end());
  std::map<fs::path, std::set<std::string>> anchor_cache;
  auto anchors = [&](const fs::path& f) -> const std::set<std::string>& {
    auto it = anchor_cache.find(f);
    if (it == anchor_cache.end()) it = anchor_cache.emplace(f, anchors_of(f)).first;
    return it->second;
  };
  int problems = 0, links = 0;
  for (const fs::path& file : files) {
    const std::vector<std::string> lines = split_lines(read_text(file));
    bool in_code = false;
    for (std::size_t n = 0; n < lines.size(); ++n) {
      if (is_fence(lines[n])) {
        in_code = !in_code;
        continue;
      }
      if (in_code) continue;
      for (const std::string& target : link_targets(lines[n])) {
        if (target.empty() || target.find("://") != std::string::npos || starts_with(target, "mailto:")) continue;
        ++links;
        const std::size_t hash = target.find('#');
        const std::string path_part = target.substr(0, hash);
        const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
        const fs::path resolved = path_part.empty() ? file : (file.parent_path() / path_part).lexically_normal();
        const std::string where = fs::relative(file, root).generic_string() + ":" + std::to_string(n + 1) + ": ";
        if (!fs::exists(resolved)) {
          std::cerr << where << "link to a missing file: " << target << "\n";
          ++problems;
          continue;
        }
        if (!anchor.empty() && resolved.extension() == ".md" && anchors(resolved).count(anchor) == 0) {
          std::cerr << where << "no heading for the anchor #" << anchor << " in "
                    << fs::relative(resolved, root).generic_string() << "\n";
          ++problems;
        }
      }
    }
  }
  std::cout << "sss_docs links: " << files.size() << " files, " << links << " relative links, " << problems
            << " broken\n";
  return problems == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// example

int check_examples(const fs::path& root, const fs::path& readme) {
  const std::vector<std::string> lines = split_lines(read_text(root / readme));
  const std::string marker = "<!-- example: ";
  int examples = 0, problems = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (!starts_with(trim(lines[n]), marker)) continue;
    ++examples;
    std::string rest = trim(lines[n]).substr(marker.size());
    const std::string source = rest.substr(0, rest.find(' '));
    // The README's block: the first fence after the marker up to its closing fence.
    std::size_t open = n + 1;
    while (open < lines.size() && !is_fence(lines[open])) ++open;
    std::size_t close = open + 1;
    while (close < lines.size() && !is_fence(lines[close])) ++close;
    if (close >= lines.size()) {
      std::cerr << readme.generic_string() << ":" << n + 1 << ": no fenced block after the example marker\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> block(lines.begin() + static_cast<long>(open) + 1,
                                         lines.begin() + static_cast<long>(close));
    // The source's region.
    const std::vector<std::string> code = split_lines(read_text(root / source));
    std::size_t begin = code.size(), end = code.size();
    for (std::size_t i = 0; i < code.size(); ++i) {
      if (begin == code.size() && code[i].find("readme-example: begin") != std::string::npos) begin = i;
      else if (begin != code.size() && code[i].find("readme-example: end") != std::string::npos) {
        end = i;
        break;
      }
    }
    if (begin == code.size() || end == code.size()) {
      std::cerr << source << ": no \"readme-example: begin\" ... \"readme-example: end\" lines\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> region(code.begin() + static_cast<long>(begin) + 1,
                                          code.begin() + static_cast<long>(end));
    if (region == block) continue;
    ++problems;
    std::size_t i = 0;
    while (i < region.size() && i < block.size() && region[i] == block[i]) ++i;
    std::cerr << readme.generic_string() << ":" << open + 2 + i << ": the example differs from " << source << ":"
              << begin + 2 + i << "\n  README: " << (i < block.size() ? block[i] : "(the block ends here)")
              << "\n  source: " << (i < region.size() ? region[i] : "(the region ends here)") << "\n";
  }
  if (examples == 0) {
    std::cerr << readme.generic_string() << ": no \"" << marker << "PATH -->\" marker\n";
    ++problems;
  }
  std::cout << "sss_docs example: " << examples << " examples, " << problems << " differ\n";
  return problems == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// headline

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  }
};

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

Csv read_csv(const fs::path& path) {
  Csv csv;
  const std::vector<std::string> lines = split_lines(read_text(path));
  if (lines.empty()) return csv;
  csv.header = split_csv(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (!trim(lines[i]).empty()) csv.rows.push_back(split_csv(lines[i]));
  }
  return csv;
}

// The string value of "key": "..." in the run description at the end of results.json (the last one).
std::string json_string(const std::string& json, const std::string& key) {
  const std::string needle = "\"" + key + "\": \"";
  const std::size_t at = json.rfind(needle);
  if (at == std::string::npos) return "";
  const std::size_t b = at + needle.size(), e = json.find('"', b);
  return e == std::string::npos ? "" : json.substr(b, e - b);
}

double number(const std::string& s) {
  if (s.empty() || s == "nan" || s == "-nan") return std::nan("");
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() ? std::nan("") : v;
}

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

// Three significant digits, never an exponent: 1765, 341, 14.8, 2.29, 0.101.
std::string sig3(double v) {
  if (std::isnan(v)) return "–";
  if (v <= 0.0) return fixed(v, 0);
  return fixed(v, std::max(0, 2 - static_cast<int>(std::floor(std::log10(v)))));
}

std::string miss3(double v) { return std::isnan(v) ? "–" : fixed(v, 3); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One benchmark series: a method of sss_bench at a tap count, follow-surface on or off.
struct Series {
  const char* label;
  const char* method;
  int taps;
  int follow_surface;
};

// The rows of the README's table: what a host meets first (the default's filter, the default as a
// host's frame runs it, fewer taps, the host's region), the exact-profile baseline and the
// silhouette-safe mode, and doing nothing. The default path is SSS_PATH_AUTO: without a timer it
// trusts (a software rasteriser, where these results are made) it takes the masked passes, or the
// plain ones given a region; the filter's own rows are the plain passes into a separate output.
const Series kRows[] = {
    {"no scattering (the input)", "no-scattering", 0, 0},
    {"**the default** filter: eq. (1), 17 taps (plain fragment passes)", "separable", 17, 1},
    {"the default in place (`SSS_PATH_AUTO`: on a software rasteriser the masked passes)", "separable-masked", 17,
     1},
    {"eq. (1), 9 taps", "separable", 9, 1},
    {"the default in place, with the host's region (there the plain passes)", "separable-region", 17, 1},
    {"d'Eon's six Gaussians, 17 taps (sum of Gaussians)", "sum-of-gaussians", 17, 1},
    {"cross-bilateral (Mikkelsen 2010), 13 taps", "cross-bilateral", 13, 0},
};

const char* const kShot = "head-close";
const int kShotWidth = 1920, kShotHeight = 1080;

struct Columns {
  int scene, width, height, method, taps, follow, passes, time_ms, ratio, sweep, miss;
  explicit Columns(const Csv& c)
      : scene(c.column("scene")), width(c.column("width")), height(c.column("height")), method(c.column("method")),
        taps(c.column("taps")), follow(c.column("follow_surface")), passes(c.column("passes")),
        time_ms(c.column("time_ms")), ratio(c.column("time_ratio_to_copy")), sweep(c.column("sweep")),
        miss(c.column("miss_interior")) {}
  bool timing_ok() const {
    return scene >= 0 && width >= 0 && height >= 0 && method >= 0 && taps >= 0 && follow >= 0 && passes >= 0 &&
           time_ms >= 0 && ratio >= 0;
  }
};

std::string field(const std::vector<std::string>& row, int column) {
  return column >= 0 && static_cast<std::size_t>(column) < row.size() ? row[static_cast<std::size_t>(column)] : "";
}

bool is_series(const std::vector<std::string>& row, const Columns& c, const Series& s) {
  return field(row, c.method) == s.method && number(field(row, c.taps)) == s.taps &&
         number(field(row, c.follow)) == s.follow_surface;
}

const std::vector<std::string>* shot_row(const Csv& csv, const Columns& c, const Series& s) {
  for (const auto& row : csv.rows) {
    if (field(row, c.scene) == kShot && number(field(row, c.width)) == kShotWidth &&
        number(field(row, c.height)) == kShotHeight && is_series(row, c, s)) {
      return &row;
    }
  }
  return nullptr;
}

// The turn sweep's interior miss (docs/benchmarks/turn-sweep/results.csv, sss_bench_turns) for a
// series on the planes turned 60 degrees: every footprint, axis and projection it ran. Empty where
// the sweep did not run the series (it runs the default, the sum of Gaussians and the
// cross-bilateral mode at their tap counts, and no scattering).
std::vector<double> turned_60(const Csv& turns, const Series& s) {
  const int scene = turns.column("scene"), turn = turns.column("turn_deg"), method = turns.column("method"),
            taps = turns.column("taps"), miss = turns.column("miss_interior");
  std::vector<double> out;
  if (scene < 0 || turn < 0 || method < 0 || taps < 0 || miss < 0) return out;
  for (const auto& row : turns.rows) {
    const double m = number(field(row, miss));
    if (field(row, scene) == "plane" && number(field(row, turn)) == 60.0 && field(row, method) == s.method &&
        number(field(row, taps)) == s.taps && !std::isnan(m)) {
      out.push_back(m);
    }
  }
  return out;
}

// "median (low–high)", or "–" for none.
std::string median_and_range(const std::vector<double>& v) {
  if (v.empty()) return "–";
  return miss3(median(v)) + " (" + miss3(*std::min_element(v.begin(), v.end())) + "–" +
         miss3(*std::max_element(v.begin(), v.end())) + ")";
}

std::string headline(const fs::path& root) {
  const fs::path results = root / "docs/benchmarks";
  const Csv csv = read_csv(results / "results.csv");
  const std::string json = read_text(results / "results.json");
  const Columns c(csv);
  if (!c.timing_ok() || c.sweep < 0 || c.miss < 0) {
    std::cerr << "sss_docs: docs/benchmarks/results.csv lacks a column the headline needs\n";
    throw Failure{};
  }
  const fs::path turn_csv = results / "turn-sweep/results.csv";
  const Csv turns = fs::exists(turn_csv) ? read_csv(turn_csv) : Csv{};
  std::ostringstream out;
  out << "| method | passes | interior `miss`, footprint sweep: median (range) | interior `miss`, planes turned "
         "60°: median (range) | interior `miss`, head close-up "
      << kShotWidth << "×" << kShotHeight << " | ms, same shot | × copy |\n"
      << "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const Series& s : kRows) {
    std::vector<double> sweep;
    for (const auto& row : csv.rows) {
      const double miss = number(field(row, c.miss));
      if (number(field(row, c.sweep)) == 1 && is_series(row, c, s) && !std::isnan(miss)) sweep.push_back(miss);
    }
    const std::vector<std::string>* shot = shot_row(csv, c, s);
    const bool timed = shot != nullptr && std::string(s.method) != "no-scattering";
    out << "| " << s.label << " | " << (shot ? field(*shot, c.passes) : "–") << " | " << median_and_range(sweep)
        << " | " << median_and_range(turned_60(turns, s))
        << " | " << (shot ? miss3(number(field(*shot, c.miss))) : "–") << " | "
        << (timed ? sig3(number(field(*shot, c.time_ms))) : "–") << " | "
        << (timed ? sig3(number(field(*shot, c.ratio))) : "–") << " |\n";
  }
  const std::string renderer = json_string(json, "renderer");
  out << "\nMeasured on `" << renderer << "` (" << json_string(json, "version")
      << (renderer.find("llvmpipe") != std::string::npos ? "; Mesa's CPU rasteriser: read its times as ratios" : "")
      << ") on " << json_string(json, "date") << "; how: [docs/benchmarks.md](docs/benchmarks.md)";
  if (!turns.rows.empty()) {
    out << "; the turned planes (0.1-1 mm per facing pixel, turned about three screen axes, orthographic and "
           "perspective): [docs/benchmarks/turn-sweep.md](docs/benchmarks/turn-sweep.md)";
  }
  out << ".";
  // The same shot on a GPU, where a run is committed (scripts/gpu/).
  const fs::path gpu = root / "docs/benchmarks-gpu";
  if (fs::exists(gpu / "results.csv") && fs::exists(gpu / "results.json")) {
    const Csv g = read_csv(gpu / "results.csv");
    const std::string gjson = read_text(gpu / "results.json");
    const Columns gc(g);
    const Series fragment = {"", "separable", 17, 1}, compute = {"", "separable-compute", 17, 1};
    const std::vector<std::string>* f = gc.timing_ok() ? shot_row(g, gc, fragment) : nullptr;
    const std::vector<std::string>* k = gc.timing_ok() ? shot_row(g, gc, compute) : nullptr;
    if (f != nullptr) {
      out << "\nOn `" << json_string(gjson, "renderer") << "` (" << json_string(gjson, "version") << ") on "
          << json_string(gjson, "date") << " the default filter's plain fragment passes took "
          << sig3(number(field(*f, gc.time_ms))) << " ms on that shot";
      if (k != nullptr) {
        out << ", " << sig3(number(field(*k, gc.time_ms)))
            << " ms on the compute path (the one `SSS_PATH_AUTO`, the default, times fastest there)";
      }
      out << " ([docs/benchmarks-gpu.md](docs/benchmarks-gpu.md)"
          << (gc.miss < 0 ? "; an earlier build, before `miss` was measured" : "") << ").";
    }
  }
  out << "\n";
  return out.str();
}

int run_headline(const fs::path& root, const fs::path& readme, bool write) {
  const std::string text = read_text(root / readme);
  const std::string begin_marker = "<!-- headline: begin", end_marker = "<!-- headline: end -->";
  const std::size_t begin = text.find(begin_marker);
  const std::size_t begin_line_end = begin == std::string::npos ? begin : text.find('\n', begin);
  const std::size_t end = begin_line_end == std::string::npos ? begin_line_end : text.find(end_marker, begin_line_end);
  if (end == std::string::npos) {
    std::cerr << readme.generic_string() << ": no \"" << begin_marker << " ... -->\" and \"" << end_marker
              << "\" lines\n";
    return 1;
  }
  const std::string generated = headline(root);
  const std::string current = text.substr(begin_line_end + 1, end - begin_line_end - 1);
  if (current == generated) {
    std::cout << "sss_docs headline: " << readme.generic_string() << " holds the generated table\n";
    return 0;
  }
  if (write) {
    std::ofstream out(root / readme, std::ios::binary);
    out << text.substr(0, begin_line_end + 1) << generated << text.substr(end);
    if (!out) {
      std::cerr << "sss_docs: cannot write " << readme.generic_string() << "\n";
      return 2;
    }
    std::cout << "sss_docs headline: rewrote the table in " << readme.generic_string() << "\n";
    return 0;
  }
  std::cerr << readme.generic_string()
            << ": the headline table differs from what the committed benchmark results give; run "
               "scripts/update-readme-numbers.sh. Expected:\n"
            << generated;
  return 1;
}

int usage() {
  std::cerr << "usage: sss_docs links ROOT PATH...\n"
               "       sss_docs example ROOT README\n"
               "       sss_docs headline ROOT README [--write]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string command = argv[1];
  const fs::path root = argv[2];
  try {
    if (command == "links" && argc >= 4) return check_links(root, std::vector<std::string>(argv + 3, argv + argc));
    if (command == "example" && argc == 4) return check_examples(root, argv[3]);
    if (command == "headline" && (argc == 4 || (argc == 5 && std::string(argv[4]) == "--write"))) {
      return run_headline(root, argv[3], argc == 5);
    }
  } catch (const Failure&) {
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sss_docs: " << e.what() << "\n";
    return 2;
  }
  return usage();
}
