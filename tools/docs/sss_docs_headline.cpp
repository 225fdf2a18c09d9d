// sss_docs headline: the README's headline table (interior miss, passes and times of each method)
// is generated from the committed benchmark results, docs/benchmarks/results.csv and .json, the
// turn sweep's results and a committed GPU run where there is one (ctest
// docs.readme_headline_numbers; scripts/update-readme-numbers.sh runs it with --write). Why: numbers
// typed by hand go stale with the next benchmark run; made from the results, a table that differs
// from them fails the check.
#include "sss_docs_headline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "sss_docs_text.hpp"

namespace sss_docs {
namespace {

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

// The whole-surface study (docs/benchmarks/whole-surface.csv, sss_whole_surface): a method's
// interior miss on the 960x540 close-up against the pixel-consistent whole-surface answer; NaN where
// the study did not run it (it runs eq. (1) at its tap counts, the sum of Gaussians at 17, no scattering).
const char* const kWholeSurfaceShot = "close-up";

// The study's CSV names a method by its label's slug (whole_surface_report.hpp's file_slug).
std::string whole_surface_method(const Series& s) {
  const std::string method = s.method;
  if (method == "no-scattering") return "no-scattering-the-input";
  if (method == "separable" && s.follow_surface == 1) return "default-" + std::to_string(s.taps) + "-taps";
  if (method == "sum-of-gaussians" && s.follow_surface == 1) return "sum-of-Gaussians-" + std::to_string(s.taps) + "-taps";
  return "";
}

double whole_surface_miss(const Csv& study, const std::string& method) {
  const int shot = study.column("shot"), name = study.column("method"), answer = study.column("answer"),
            region = study.column("region"), pooled = study.column("pooled");
  if (method.empty() || shot < 0 || name < 0 || answer < 0 || region < 0 || pooled < 0) return std::nan("");
  for (const auto& row : study.rows) {
    if (field(row, shot) == kWholeSurfaceShot && field(row, name) == method && field(row, answer) == "pixel-consistent" &&
        field(row, region) == "interior") {
      return number(field(row, pooled));
    }
  }
  return std::nan("");
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
  const fs::path whole_csv = results / "whole-surface.csv";
  const Csv whole = fs::exists(whole_csv) ? read_csv(whole_csv) : Csv{};
  std::ostringstream out;
  out << "| method | passes | interior `miss`, footprint sweep: median (range) | interior `miss`, planes turned "
         "60°: median (range) | interior `miss`, head close-up "
      << kShotWidth << "×" << kShotHeight << " | interior `miss`, head, whole surface 960×540 | ms, same shot | × copy |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
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
        << miss3(whole_surface_miss(whole, whole_surface_method(s))) << " | "
        << (timed ? sig3(number(field(*shot, c.time_ms))) : "–") << " | "
        << (timed ? sig3(number(field(*shot, c.ratio))) : "–") << " |\n";
  }
  if (!whole.rows.empty()) {
    // What no screen-space method can do better than there (whole_surface_study.cpp): detail finer
    // than a pixel, and the light of the surface the camera does not see.
    out << "| the floor there: detail finer than a pixel / light from hidden surface | – | – | – | – | "
        << miss3(whole_surface_miss(whole, "the-input-s-floor-the-exact-light-answer")) << " / "
        << miss3(whole_surface_miss(whole, "hidden-light-the-visible-surface-alone")) << " | – | – |\n";
  }
  const std::string renderer = json_string(json, "renderer");
  out << "\nMeasured on `" << renderer << "` (" << json_string(json, "version")
      << (renderer.find("llvmpipe") != std::string::npos ? "; Mesa's CPU rasteriser: read its times as ratios" : "")
      << ") on " << json_string(json, "date") << "; how: [docs/benchmarks.md](docs/benchmarks.md)";
  if (!whole.rows.empty()) {
    out << "; the head against its whole surface, hidden parts included (the close-up under a soft-edged "
           "key, CPU model of the passes): [docs/benchmarks/whole-surface.md](docs/benchmarks/whole-surface.md)";
  }
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

}  // namespace

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

}  // namespace sss_docs
