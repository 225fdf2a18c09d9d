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
//   sss_docs names ROOT HEADER GUIDE   every public name HEADER declares (and the headers it includes
//                                      with "..."): function, type, field, enumerator, macro but the
//                                      include guard, is written as code in GUIDE; a field as
//                                      `struct.field`, or as a field in a paragraph, table or code block
//                                      that names its struct
//   sss_docs names-selftest            the parser on a packed and a one-declaration-a-line header
//   sss_docs quickstart ROOT GUIDE SOURCE
//                                      the numbered steps between "<!-- quick-start: begin" and
//                                      "<!-- quick-start: end" in GUIDE ("N. **Title**" and one code
//                                      block each) are SOURCE's, in order: the lines between
//                                      "quick-start N: Title" and "quick-start N: end", same title
//
// Exit status 0 when everything holds (or was written), 1 when something does not (each problem on
// stderr), 2 for bad usage or unreadable inputs. No dependency beyond the C++17 standard library.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
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

// ---------------------------------------------------------------------------------------------
// names: every public name of a C header is in the guide

// One public name of the header: a function, a type, a struct's field, an enumerator or a macro.
struct PublicName {
  std::string name;   // the identifier
  std::string kind;   // "function", "type", "field", "enumerator", "macro", "variable"
  std::string owner;  // a field's struct (its typedef name, else its tag); empty otherwise
  std::string where;  // file:line
  std::string display() const { return owner.empty() ? name : owner + "." + name; }
};

struct Token {
  std::string text;
  int line = 0;
  bool identifier() const {
    return !text.empty() && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_');
  }
};

// The text with its comments blanked out (newlines kept, so that line numbers hold); string and
// character literals are kept whole.
std::string without_comments(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i < out.size();) {
    const char c = out[i];
    if (c == '"' || c == '\'') {
      for (++i; i < out.size() && out[i] != c && out[i] != '\n'; ++i) {
        if (out[i] == '\\') ++i;
      }
      ++i;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
      const std::size_t end = out.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (std::size_t j = i; j < stop; ++j) {
        if (out[j] != '\n') out[j] = ' ';
      }
      i = stop;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    } else {
      ++i;
    }
  }
  return out;
}

std::vector<Token> tokenize(const std::string& code, int first_line) {
  std::vector<Token> tokens;
  int line = first_line;
  for (std::size_t i = 0; i < code.size();) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(c)) {
      ++i;
    } else if (std::isalnum(c) || c == '_') {  // identifiers and numbers (a pp-number: 0x1u, 1e6f)
      std::size_t e = i;
      while (e < code.size() && (std::isalnum(static_cast<unsigned char>(code[e])) || code[e] == '_' ||
                                 (std::isdigit(c) && code[e] == '.'))) {
        ++e;
      }
      tokens.push_back({code.substr(i, e - i), line});
      i = e;
    } else if (c == '"' || c == '\'') {
      std::size_t e = i + 1;
      for (; e < code.size() && code[e] != static_cast<char>(c) && code[e] != '\n'; ++e) {
        if (code[e] == '\\') ++e;
      }
      tokens.push_back({code.substr(i, e + 1 - i), line});
      i = e + 1;
    } else {
      tokens.push_back({std::string(1, static_cast<char>(c)), line});
      ++i;
    }
  }
  return tokens;
}

using Tokens = std::vector<Token>;

// The tokens split at `separator` outside (), [] and {}.
std::vector<Tokens> split_top_level(const Tokens& tokens, const std::string& separator) {
  std::vector<Tokens> parts(1);
  int depth = 0;
  for (const Token& t : tokens) {
    if (t.text == "(" || t.text == "[" || t.text == "{") ++depth;
    if (t.text == ")" || t.text == "]" || t.text == "}") --depth;
    if (depth == 0 && t.text == separator) {
      parts.emplace_back();
      continue;
    }
    parts.back().push_back(t);
  }
  if (parts.back().empty()) parts.pop_back();
  return parts;
}

// Index of the first `open` at depth 0 and its matching close, or npos.
std::pair<std::size_t, std::size_t> top_level_group(const Tokens& tokens, const std::string& open,
                                                    const std::string& close) {
  int depth = 0;
  std::size_t begin = std::string::npos;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& s = tokens[i].text;
    if (s == "(" || s == "[" || s == "{") {
      if (depth == 0 && s == open && begin == std::string::npos) begin = i;
      ++depth;
    } else if (s == ")" || s == "]" || s == "}") {
      --depth;
      if (depth == 0 && s == close && begin != std::string::npos) return {begin, i};
    }
  }
  return {std::string::npos, std::string::npos};
}

class HeaderNames {
 public:
  std::vector<PublicName> names;

  void read(const fs::path& header, const std::string& shown) {
    if (!visited_.insert(fs::weakly_canonical(header).generic_string()).second) return;
    const std::string text = without_comments(read_text(header));
    const std::vector<std::string> lines = split_lines(text);
    std::string code;  // the lines outside directives and C++-only blocks; blank lines keep the count
    // #if nesting: whether each level is a `#ifdef __cplusplus`-like block, and whether it is skipped.
    struct Level {
      bool cplusplus;
      bool skipped;
    };
    std::vector<Level> levels;
    const auto skipping = [&levels] { return !levels.empty() && levels.back().skipped; };
    std::string guard;  // the include guard: the first directive is `#ifndef X`, the second `#define X`
    int directives = 0;
    for (std::size_t n = 0; n < lines.size(); ++n) {
      std::string line = lines[n];
      const int line_number = static_cast<int>(n) + 1;
      std::size_t joined = 0;
      while (!line.empty() && line.back() == '\\' && n + 1 < lines.size()) {
        line.pop_back();
        line += " " + lines[++n];
        ++joined;
      }
      const std::string t = trim(line);
      if (!starts_with(t, "#")) {
        code += skipping() ? "" : line;
        code += std::string(joined + 1, '\n');
        continue;
      }
      code += std::string(joined + 1, '\n');
      std::istringstream words(t.substr(1));
      std::string directive, argument;
      words >> directive >> argument;
      const bool is_cplusplus = argument.find("__cplusplus") != std::string::npos;
      ++directives;
      if (directives == 1 && directive == "ifndef") guard = argument;
      if (directives == 2 && !(directive == "define" && argument == guard)) guard.clear();
      if (directive == "if" || directive == "ifdef" || directive == "ifndef") {
        const bool parent = skipping();
        // `#ifdef __cplusplus` / `#if defined(__cplusplus)`: C++ only, not the C API; its #else is.
        const bool cpp_only = is_cplusplus && directive != "ifndef" && t.find('!') == std::string::npos;
        levels.push_back({is_cplusplus, parent || cpp_only});
      } else if (directive == "else" || directive == "elif") {
        if (!levels.empty() && levels.back().cplusplus) {
          const bool parent = levels.size() > 1 && levels[levels.size() - 2].skipped;
          levels.back().skipped = parent || !levels.back().skipped;
        }
      } else if (directive == "endif") {
        if (!levels.empty()) levels.pop_back();
      } else if (directive == "include" && !skipping()) {
        const std::size_t q = t.find('"');
        const std::size_t e = q == std::string::npos ? q : t.find('"', q + 1);
        if (e != std::string::npos) {  // "..." only: <...> is a system header
          const std::string included = t.substr(q + 1, e - q - 1);
          const fs::path dir = header.parent_path();
          const std::string shown_dir = fs::path(shown).parent_path().generic_string();
          read(dir / included, shown_dir.empty() ? included : shown_dir + "/" + included);
        }
      } else if (directive == "define" && !skipping()) {
        std::string name;
        for (char c : argument) {
          if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) break;
          name += c;
        }
        const bool is_guard = directives == 2 && name == guard;
        if (!name.empty() && !is_guard) add(name, "macro", "", shown, line_number);
        if (name.size() < argument.size() && argument[name.size()] == '(') function_macros_.insert(name);
      }
    }
    parse_declarations(tokenize(code, 1), shown);
  }

 private:
  std::set<std::string> visited_;
  std::set<std::string> seen_;
  std::set<std::string> function_macros_;  // a `NAME(` of these in a declaration is not its name

  void add(const std::string& name, const std::string& kind, const std::string& owner, const std::string& file,
           int line) {
    if (!seen_.insert(kind + " " + owner + "." + name).second) return;
    names.push_back({name, kind, owner, file + ":" + std::to_string(line)});
  }

  static bool keyword(const std::string& s) {
    static const std::set<std::string> k = {"struct", "union",  "enum",     "typedef", "const",  "volatile",
                                            "extern", "static", "unsigned", "signed",  "inline", "restrict"};
    return k.count(s) != 0;
  }

  // The name a declarator (without its type, or with it) declares: `*b`, `viewport[4]`,
  // `const struct x *kernel`, `(*fn)(int)`.
  static std::optional<Token> declarator_name(const Tokens& piece) {
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      if (piece[i].text == "(" && piece[i + 1].text == "*") {
        for (std::size_t j = i + 2; j < piece.size() && piece[j].text != ")"; ++j) {
          if (piece[j].identifier() && !keyword(piece[j].text)) return piece[j];
        }
      }
    }
    std::optional<Token> last;
    for (const Token& t : piece) {
      if (t.text == "[" || t.text == ":" || t.text == "=" || t.text == "(") break;
      if (t.identifier() && !keyword(t.text)) last = t;
    }
    return last;
  }

  void fields(const Tokens& body, const std::string& owner, const std::string& file) {
    for (const Tokens& member : split_top_level(body, ";")) {
      const auto [open, close] = top_level_group(member, "{", "}");
      Tokens declarators = member;
      if (open != std::string::npos) {  // a nested struct or union: its members, then its declarators
        fields(Tokens(member.begin() + static_cast<long>(open) + 1, member.begin() + static_cast<long>(close)), owner,
               file);
        declarators.assign(member.begin() + static_cast<long>(close) + 1, member.end());
      }
      for (const Tokens& piece : split_top_level(declarators, ",")) {
        if (const auto name = declarator_name(piece)) add(name->text, "field", owner, file, name->line);
      }
    }
  }

  void enumerators(const Tokens& body, const std::string& file) {
    for (const Tokens& piece : split_top_level(body, ",")) {
      if (!piece.empty() && piece[0].identifier()) add(piece[0].text, "enumerator", "", file, piece[0].line);
    }
  }

  void parse_declarations(const Tokens& tokens, const std::string& file) {
    for (const Tokens& d : split_top_level(tokens, ";")) {
      if (d.empty()) continue;
      const bool is_typedef = d[0].text == "typedef";
      const auto [open, close] = top_level_group(d, "{", "}");
      if (open != std::string::npos) {
        // struct/union/enum TAG { BODY } NAMES: the keyword and tag are the tokens before '{'.
        std::string kind, tag;
        for (std::size_t i = 0; i < open; ++i) {
          const std::string& s = d[i].text;
          if (s == "struct" || s == "union" || s == "enum") {
            kind = s;
            if (i + 1 < open && d[i + 1].identifier()) tag = d[i + 1].text;
          }
        }
        std::string owner = tag;
        for (std::size_t i = close + 1; i < d.size(); ++i) {
          if (d[i].identifier() && !keyword(d[i].text) && is_typedef) {
            if (owner == tag) owner = d[i].text;
            add(d[i].text, "type", "", file, d[i].line);
          }
        }
        if (!tag.empty()) add(tag, "type", "", file, d[open > 0 ? open - 1 : 0].line);
        const Tokens body(d.begin() + static_cast<long>(open) + 1, d.begin() + static_cast<long>(close));
        if (kind == "enum") enumerators(body, file);
        else if (kind == "struct" || kind == "union") fields(body, owner, file);
        continue;
      }
      if (!is_typedef && d.size() == 2 && (d[0].text == "struct" || d[0].text == "union" || d[0].text == "enum")) {
        continue;  // a forward declaration: another header's type
      }
      if (is_typedef) {
        if (const auto name = declarator_name(Tokens(d.begin() + 1, d.end()))) {
          add(name->text, "type", "", file, name->line);
        }
        continue;
      }
      // A function: the identifier before the first top-level '(' that is not a macro's (an
      // attribute or export macro taking arguments) nor `(*` (a pointer to a function).
      const Token* function = nullptr;
      int depth = 0;
      for (std::size_t i = 0; i < d.size() && function == nullptr; ++i) {
        const std::string& s = d[i].text;
        if (s == "(" && depth == 0 && i > 0 && d[i - 1].identifier() && function_macros_.count(d[i - 1].text) == 0 &&
            !(i + 1 < d.size() && d[i + 1].text == "*")) {
          function = &d[i - 1];
        }
        if (s == "(" || s == "[" || s == "{") ++depth;
        if (s == ")" || s == "]" || s == "}") --depth;
      }
      if (function != nullptr) {
        add(function->text, "function", "", file, function->line);
      } else if (const auto name = declarator_name(d)) {
        add(name->text, "variable", "", file, name->line);
      }
    }
  }
};

// What a markdown file writes as code (inline code spans and fenced blocks): the identifiers, the
// qualified names `a.b`, and by block (a paragraph, a table, a list item's text or a fenced code
// block: what blank lines, headings and fences separate) the identifiers and the names written as
// a field there: after `.` or `->`, or leading an inline code span (`viewport[4]`,
// `cbf_r_max_mm = 8`; not `f(ctx, projection)`).
struct GuideCode {
  struct Block {
    int line = 0;
    std::set<std::string> identifiers, fields;
  };
  std::vector<Block> blocks;
  std::set<std::string> identifiers, qualified;

  explicit GuideCode(const std::string& text) {
    blocks.push_back({1, {}, {}});
    bool in_code = false;
    int n = 0;
    for (const std::string& line : split_lines(text)) {
      ++n;
      if (is_fence(line)) {
        in_code = !in_code;
        blocks.push_back({n, {}, {}});
        continue;
      }
      if (in_code) {
        add_code(line, false);
        continue;
      }
      if (trim(line).empty() || starts_with(line, "#")) {
        blocks.push_back({n, {}, {}});
        continue;
      }
      for (std::size_t i = 0; i < line.size();) {
        if (line[i] != '`') {
          ++i;
          continue;
        }
        std::size_t ticks = 0;
        while (i + ticks < line.size() && line[i + ticks] == '`') ++ticks;
        const std::size_t close = line.find(std::string(ticks, '`'), i + ticks);
        if (close == std::string::npos) break;
        add_code(line.substr(i + ticks, close - i - ticks), true);
        i = close + ticks;
      }
    }
  }

  bool has(const std::string& name) const { return identifiers.count(name) != 0; }

  // A field is documented where it is written qualified (`sss_frame.region`), or written as a
  // field in a block that names its struct (a table of the struct's fields, a code block that
  // declares one and sets them).
  bool has_field(const std::string& owner, const std::string& field) const {
    if (qualified.count(owner + "." + field) != 0) return true;
    for (const Block& b : blocks) {
      if (b.identifiers.count(owner) != 0 && b.fields.count(field) != 0) return true;
    }
    return false;
  }

 private:
  void add_code(const std::string& code, bool inline_span) {
    std::string previous;  // the identifier just before a '.', for `a.b`
    bool first = inline_span;
    for (std::size_t i = 0; i < code.size();) {
      const unsigned char c = static_cast<unsigned char>(code[i]);
      if (std::isalpha(c) || c == '_') {
        std::size_t e = i;
        while (e < code.size() && (std::isalnum(static_cast<unsigned char>(code[e])) || code[e] == '_')) ++e;
        const std::string word = code.substr(i, e - i);
        identifiers.insert(word);
        blocks.back().identifiers.insert(word);
        const bool member = (i >= 1 && code[i - 1] == '.') || (i >= 2 && code.compare(i - 2, 2, "->") == 0);
        const bool leading = first && (e >= code.size() || code[e] != '(');
        if (member || leading) blocks.back().fields.insert(word);
        first = false;
        if (!previous.empty()) qualified.insert(previous + "." + word);
        previous.clear();
        if (e < code.size() && code[e] == '.') {
          previous = word;
          ++e;
        }
        i = e;
      } else if (std::isdigit(c)) {  // a number (0x881A, 1e6f) names nothing
        while (i < code.size() && (std::isalnum(static_cast<unsigned char>(code[i])) || code[i] == '_' || code[i] == '.')) {
          ++i;
        }
        previous.clear();
        first = false;
      } else {
        previous.clear();
        ++i;
      }
    }
  }
};

// The names of `header` the guide lacks, each explained on `report`.
std::vector<std::string> missing_names(const HeaderNames& h, const GuideCode& code, const std::string& guide,
                                       std::ostream& report) {
  std::vector<std::string> missing;
  for (const PublicName& p : h.names) {
    const bool found = p.kind == "field" ? code.has_field(p.owner, p.name) : code.has(p.name);
    if (found) continue;
    missing.push_back(p.kind + " " + p.display());
    report << guide << ": the " << p.kind << " " << p.display() << " (" << p.where << ") is not in the guide: ";
    if (p.kind == "field") {
      report << "write `" << p.display() << "`, or `" << p.name << "` as a field (leading a code span, or after '.' "
             << "or '->') in a paragraph, table or code block that names `" << p.owner << "`\n";
    } else {
      report << "write `" << p.name << "` (in backticks or a code block) where the guide documents it\n";
    }
  }
  return missing;
}

// Every name `header` (and the headers it includes with "...") declares, against the guide.
int check_names(const fs::path& root, const std::string& header, const std::string& guide) {
  HeaderNames h;
  h.read(root / header, header);
  const GuideCode code(read_text(root / guide));
  const std::vector<std::string> missing = missing_names(h, code, guide, std::cerr);
  std::map<std::string, int> kinds;
  for (const PublicName& p : h.names) ++kinds[p.kind];
  std::cout << "sss_docs names: " << h.names.size() << " public names in " << header << " and what it includes (";
  const char* sep = "";
  for (const auto& [kind, count] : kinds) {
    std::cout << sep << count << " " << kind << (count == 1 ? "" : "s");
    sep = ", ";
  }
  std::cout << "), " << missing.size() << " missing from " << guide << "\n";
  if (h.names.empty()) {
    std::cerr << header << ": no public name found\n";
    return 1;
  }
  return missing.empty() ? 0 : 1;
}

// The parser on two layouts of one small header (several declarations, fields and enumerators a
// line, as sss.h 0.4 packs them; one a line, with /**< comments, as a header may be rewritten), and
// the guide's rules on a small guide. No files of the tree are read.
int names_selftest() {
  const std::string common = R"(/* fx_common.h: included by both layouts */
#ifndef FX_COMMON_H
#define FX_COMMON_H
#if defined(_WIN32)
#  define FX_API __declspec(dllexport)
#else
#  define FX_API
#endif
typedef enum fx_result { FX_OK = 0, FX_ERROR } fx_result;
#endif
)";
  const std::string packed = R"(/*
 * A fixture in the packed layout. Its example is no declaration:
 *   int not_a_name(void); typedef struct no_type { int no_field; } no_type;
 */
#ifndef FIX_H
#define FIX_H
#include <stdint.h>
#include "fx_common.h"
#ifdef __cplusplus
extern "C" {
#endif
typedef struct fx_context fx_context;
typedef void *(*fx_loader_fn)(const char *name, void *user); /**< loader: dlsym... */
typedef enum fx_level { FX_A, FX_B = 2, /**< two */ FX_C } fx_level;
#define FX_FLAG 0x1u /**< a flag; FX_NOT_A_MACRO in a comment */
#define FX_MAX(a, b) \
  ((a) > (b) ? (a) : (b))
struct fx_forward;
typedef struct fx_desc {
  uint32_t struct_size; fx_loader_fn load; void *load_user; /**< required; its user pointer */
  uint32_t ref, mask; /**< [0, 255] */ int32_t box[4]; const struct fx_forward *next; } fx_desc;
typedef enum fx_flag /* fx_desc.flags */ {
  FX_FLAG_X = 0x1, FX_FLAG_Y = 0x2, /**< x; y */
  FX_FLAG_Z = (1 << 2) /**< z */ } fx_flag;
FX_API fx_result fx_run(fx_context *ctx, const fx_desc *desc); /**< runs: fx_fake(1) */
FX_API const char *fx_name(fx_result r); void fx_two(void);
#ifdef __cplusplus
}
#endif
#endif
)";
  const std::string one_a_line = R"(#ifndef FIX_H
#define FIX_H

#include <stdint.h>

#include "fx_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** opaque */
typedef struct fx_context fx_context;
/** loader */
typedef void *(*fx_loader_fn)(const char *name,
                              void *user);

typedef enum fx_level {
  FX_A,     /**< a */
  FX_B = 2, /**< two */
  FX_C,     /**< c */
} fx_level;

#define FX_FLAG 0x1u /**< a flag */
#define FX_MAX(a, b) ((a) > (b) ? (a) : (b)) /**< the larger */

struct fx_forward;

/** A desc. */
typedef struct fx_desc {
  uint32_t struct_size;          /**< sizeof(fx_desc) */
  fx_loader_fn load;             /**< required */
  void *load_user;               /**< its user pointer */
  uint32_t ref;                  /**< [0, 255] */
  uint32_t mask;                 /**< [0, 255] */
  int32_t box[4];                /**< x, y, w, h */
  const struct fx_forward *next; /**< NULL */
} fx_desc;

typedef enum fx_flag {
  FX_FLAG_X = 0x1,      /**< x */
  FX_FLAG_Y = 0x2,      /**< y */
  FX_FLAG_Z = (1 << 2)  /**< z */
} fx_flag;

/**
 * Runs.
 * @retval FX_OK done
 */
FX_API fx_result fx_run(fx_context *ctx,
                        const fx_desc *desc);
/** A name. */
FX_API const char *fx_name(fx_result r);
void fx_two(void);

#ifdef __cplusplus
}
#endif

#endif /* FIX_H */
)";
  const std::set<std::string> expected = {
      "enumerator FX_A",       "enumerator FX_B",       "enumerator FX_C",       "enumerator FX_ERROR",
      "enumerator FX_FLAG_X",  "enumerator FX_FLAG_Y",  "enumerator FX_FLAG_Z",  "enumerator FX_OK",
      "field fx_desc.box",     "field fx_desc.load",    "field fx_desc.load_user", "field fx_desc.mask",
      "field fx_desc.next",    "field fx_desc.ref",     "field fx_desc.struct_size", "function fx_name",
      "function fx_run",       "function fx_two",       "macro FX_API",          "macro FX_FLAG",
      "macro FX_MAX",          "type fx_context",       "type fx_desc",          "type fx_flag",
      "type fx_level",         "type fx_loader_fn",     "type fx_result"};
  const fs::path dir = fs::temp_directory_path() /
                       ("sss_docs_selftest_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(dir);
  const auto write = [&dir](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  };
  write("fx_common.h", common);
  write("packed.h", packed);
  write("one_a_line.h", one_a_line);
  int problems = 0;
  for (const char* layout : {"packed.h", "one_a_line.h"}) {
    HeaderNames h;
    h.read(dir / layout, layout);
    std::set<std::string> got;
    for (const PublicName& p : h.names) got.insert(p.kind + " " + p.display());
    for (const std::string& e : expected) {
      if (got.count(e) == 0) {
        std::cerr << "names-selftest: " << layout << ": the parser missed " << e << "\n";
        ++problems;
      }
    }
    for (const std::string& g : got) {
      if (expected.count(g) == 0) {
        std::cerr << "names-selftest: " << layout << ": the parser found " << g << ", which is no public name\n";
        ++problems;
      }
    }
  }
  // The guide's rules: code only (backticks, fenced blocks); a field qualified, or written as a
  // field in a block that names its struct.
  const std::string guide = R"(# Guide
Intro naming `fx_run`, `fx_context`, `fx_two()` and `fx_result` (`FX_OK`, `FX_ERROR`).
## The desc
`fx_desc` holds `struct_size`, `load` and `load_user`; `fx_run(ctx, next)` has next as an argument
only, which is no field.
## Other
`ref` and `mask` here are not fx_desc's (no struct named in this section); FX_A in prose is no code.
## Qualified
The name in the block's comment is qualified.

```c
fx_name(FX_B); x = FX_MAX(1, 2); d.flags = FX_FLAG_X | FX_FLAG_Y | FX_FLAG_Z; /* fx_desc.box */
```
## Members
A member access names a field where the same block names the struct.

```c
fx_desc *d = get();
d->ref = 1;
```

`mask` alone, a paragraph after the one naming fx_desc, is not enough.
)";
  const std::set<std::string> expected_missing = {"type fx_loader_fn", "type fx_level",     "enumerator FX_A",
                                                  "enumerator FX_C",   "macro FX_FLAG",      "macro FX_API",
                                                  "type fx_flag",      "field fx_desc.mask", "field fx_desc.next"};
  HeaderNames h;
  h.read(dir / "one_a_line.h", "one_a_line.h");
  std::ostringstream ignored;
  const std::vector<std::string> missing = missing_names(h, GuideCode(guide), "guide.md", ignored);
  const std::set<std::string> got_missing(missing.begin(), missing.end());
  if (got_missing != expected_missing) {
    std::cerr << "names-selftest: the guide check reported as missing:";
    for (const std::string& m : got_missing) std::cerr << " [" << m << "]";
    std::cerr << "\n  expected:";
    for (const std::string& m : expected_missing) std::cerr << " [" << m << "]";
    std::cerr << "\n";
    ++problems;
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  std::cout << "sss_docs names-selftest: " << expected.size() << " names in two layouts, " << problems
            << " problems\n";
  return problems == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// quickstart: the guide's checklist is the program ctest runs

std::string rtrim(const std::string& s) {
  std::size_t e = s.size();
  while (e > 0 && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(0, e);
}

// The lines without their common indentation and trailing blanks (a list item's block is indented
// for the list, a function's body for the function).
std::vector<std::string> dedent(const std::vector<std::string>& lines) {
  std::size_t common = std::string::npos;
  for (const std::string& l : lines) {
    if (trim(l).empty()) continue;
    common = std::min(common, l.find_first_not_of(" \t"));
  }
  std::vector<std::string> out;
  for (const std::string& l : lines) out.push_back(trim(l).empty() ? "" : rtrim(l.substr(common)));
  return out;
}

struct Step {
  int number = 0;
  std::string title;
  std::size_t line = 0;       // where the step begins (1-based)
  std::size_t code_line = 0;  // where its code begins
  std::vector<std::string> code;
  int blocks = 0;
};

// The checklist between "<!-- quick-start: begin" and "<!-- quick-start: end": items "N. **Title**
// ..." each followed by one fenced block.
bool guide_steps(const std::vector<std::string>& lines, const std::string& guide, std::vector<Step>* steps) {
  std::size_t begin = lines.size(), end = lines.size();
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (begin == lines.size() && starts_with(trim(lines[n]), "<!-- quick-start: begin")) begin = n;
    else if (begin != lines.size() && starts_with(trim(lines[n]), "<!-- quick-start: end")) {
      end = n;
      break;
    }
  }
  if (end == lines.size()) {
    std::cerr << guide << ": no \"<!-- quick-start: begin ... -->\" and \"<!-- quick-start: end -->\" lines\n";
    return false;
  }
  bool in_code = false;
  for (std::size_t n = begin + 1; n < end; ++n) {
    const std::string& line = lines[n];
    if (is_fence(line)) {
      in_code = !in_code;
      if (steps->empty()) continue;
      Step& s = steps->back();
      if (in_code) {
        ++s.blocks;
        s.code_line = n + 2;
      }
      continue;
    }
    if (in_code) {
      if (!steps->empty() && steps->back().blocks == 1) steps->back().code.push_back(line);
      continue;
    }
    // "N. **Title**" at the start of a line.
    std::size_t digits = 0;
    while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
    if (digits == 0 || line.compare(digits, 4, ". **") != 0) continue;
    const std::size_t close = line.find("**", digits + 4);
    if (close == std::string::npos) continue;
    Step s;
    s.number = std::atoi(line.substr(0, digits).c_str());
    s.title = line.substr(digits + 4, close - digits - 4);
    s.line = n + 1;
    steps->push_back(s);
  }
  return true;
}

// The program's steps: the lines between "quick-start N: TITLE" and "quick-start N: end".
bool source_steps(const std::vector<std::string>& lines, const std::string& source, std::vector<Step>* steps) {
  const std::string marker = "quick-start ";
  Step* open = nullptr;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::size_t at = lines[n].find(marker);
    if (at == std::string::npos) {
      if (open != nullptr) open->code.push_back(lines[n]);
      continue;
    }
    const std::string rest = lines[n].substr(at + marker.size());
    std::size_t digits = 0;
    while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
    if (digits == 0 || rest.compare(digits, 2, ": ") != 0) {
      if (open != nullptr) open->code.push_back(lines[n]);
      continue;
    }
    const int number = std::atoi(rest.substr(0, digits).c_str());
    std::string title = rest.substr(digits + 2);
    if (const std::size_t comment_end = title.rfind("*/"); comment_end != std::string::npos) title.resize(comment_end);
    title = trim(title);
    if (title == "end") {
      if (open == nullptr || open->number != number) {
        std::cerr << source << ":" << n + 1 << ": \"quick-start " << number << ": end\" closes no open step\n";
        return false;
      }
      open = nullptr;
      continue;
    }
    if (open != nullptr) {
      std::cerr << source << ":" << n + 1 << ": step " << number << " begins inside step " << open->number << "\n";
      return false;
    }
    Step s;
    s.number = number;
    s.title = title;
    s.line = n + 1;
    s.code_line = n + 2;
    s.blocks = 1;
    steps->push_back(s);
    open = &steps->back();
  }
  if (open != nullptr) {
    std::cerr << source << ":" << open->line << ": step " << open->number << " has no \"quick-start "
              << open->number << ": end\" line\n";
    return false;
  }
  return true;
}

int check_quickstart(const fs::path& root, const std::string& guide, const std::string& source) {
  std::vector<Step> in_guide, in_source;
  if (!guide_steps(split_lines(read_text(root / guide)), guide, &in_guide) ||
      !source_steps(split_lines(read_text(root / source)), source, &in_source)) {
    return 1;
  }
  int problems = 0;
  const auto numbered = [&](const std::vector<Step>& steps, const std::string& file) {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (steps[i].number != static_cast<int>(i) + 1) {
        std::cerr << file << ":" << steps[i].line << ": step " << steps[i].number << " where step " << i + 1
                  << " belongs: steps are numbered 1, 2, 3... in order\n";
        ++problems;
      }
    }
  };
  numbered(in_guide, guide);
  numbered(in_source, source);
  if (in_guide.empty()) {
    std::cerr << guide << ": the quick start has no steps (\"N. **Title** ...\" lines)\n";
    ++problems;
  }
  if (in_guide.size() != in_source.size()) {
    std::cerr << guide << " has " << in_guide.size() << " quick-start steps, " << source << " "
              << in_source.size() << "\n";
    ++problems;
  }
  for (std::size_t i = 0; i < std::min(in_guide.size(), in_source.size()); ++i) {
    const Step& g = in_guide[i];
    const Step& s = in_source[i];
    if (g.title != s.title) {
      std::cerr << guide << ":" << g.line << ": step " << g.number << " is \"" << g.title << "\" but " << source << ":"
                << s.line << " calls it \"" << s.title << "\"\n";
      ++problems;
    }
    if (g.blocks != 1) {
      std::cerr << guide << ":" << g.line << ": step " << g.number << " has " << g.blocks
                << " code blocks; each step has one, its code in " << source << "\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> a = dedent(g.code), b = dedent(s.code);
    if (a == b) continue;
    ++problems;
    std::size_t k = 0;
    while (k < a.size() && k < b.size() && a[k] == b[k]) ++k;
    std::cerr << guide << ":" << g.code_line + k << ": step " << g.number << "'s code differs from " << source << ":"
              << s.code_line + k << "\n  guide:  " << (k < a.size() ? a[k] : "(the block ends here)")
              << "\n  source: " << (k < b.size() ? b[k] : "(the step ends here)") << "\n";
  }
  std::cout << "sss_docs quickstart: " << in_guide.size() << " steps in " << guide << ", " << in_source.size()
            << " in " << source << ", " << problems << " problems\n";
  return problems == 0 ? 0 : 1;
}

int usage() {
  std::cerr << "usage: sss_docs links ROOT PATH...\n"
               "       sss_docs example ROOT README\n"
               "       sss_docs headline ROOT README [--write]\n"
               "       sss_docs names ROOT HEADER GUIDE\n"
               "       sss_docs names-selftest\n"
               "       sss_docs quickstart ROOT GUIDE SOURCE\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "names-selftest") {
    try {
      return names_selftest();
    } catch (const std::exception& e) {
      std::cerr << "sss_docs: " << e.what() << "\n";
      return 2;
    }
  }
  if (argc < 3) return usage();
  const std::string command = argv[1];
  const fs::path root = argv[2];
  try {
    if (command == "links" && argc >= 4) return check_links(root, std::vector<std::string>(argv + 3, argv + argc));
    if (command == "example" && argc == 4) return check_examples(root, argv[3]);
    if (command == "names" && argc == 5) return check_names(root, argv[3], argv[4]);
    if (command == "quickstart" && argc == 5) return check_quickstart(root, argv[3], argv[4]);
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
