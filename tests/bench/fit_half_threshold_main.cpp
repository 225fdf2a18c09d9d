// sss_fit_half_threshold: measures the half-resolution path's threshold (the smallest kernel reach,
// in full-size pixels on both axes, that SSS_PATH_HALF_RESOLUTION hands to its upsample) on the
// footprint sweep (half_threshold.hpp): every sweep scene at footprints from a 4K close-up to a far
// crowd, the CPU model of the full-size passes and of the half path at each candidate threshold,
// scored by interior miss against the exact plane reference. The threshold is the smallest
// candidate at which every case keeps the half path's miss within kHalfResolutionMissMargin of the
// full-size passes' (half_keeps_margin). Writes
//   module/src/math/half_resolution_threshold.hpp   kHalfResolutionMinReachPixels
//   tests/bench/half_threshold_fit.json              the pick and the cases bench.half_threshold re-checks
//   docs/benchmarks/half-resolution.md (+ a plot)   the report
// scripts/fit-half-threshold.sh runs it; a change to the path, the kernels or the instrument that
// moves a miss needs a rerun (bench.half_threshold says so).
#include <getopt.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "half_threshold.hpp"
#include "math/half_resolution.hpp"

namespace {

using sss_bench::HalfCaseScore;

struct Fit {
  std::vector<HalfCaseScore> scores;
  std::vector<float> candidates;
  int chosen = -1;         // index into candidates; -1: none keeps the margin
  double reach_mm = 0.0;   // the kernel's smaller reach
};

std::string fixed(double v, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? NAN : (n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

std::vector<double> footprints_of(const Fit& fit) {
  std::set<double> f;
  for (const HalfCaseScore& s : fit.scores) f.insert(s.footprint_mm);
  return {f.begin(), f.end()};
}

// What the report and the plot show of one footprint, over the scenes.
struct FootprintSummary {
  double footprint_mm = 0.0, reach_px = 0.0;
  double full = 0.0, half_chosen = 0.0, half_zero = 0.0;        // medians
  double excess_chosen = -1e9, excess_zero = -1e9;              // largest half - full
  std::string worst_chosen, worst_zero;                         // its scene
  double share_chosen = 0.0, share_zero = 0.0;                  // mean upsampled share
};

std::vector<FootprintSummary> summarise(const Fit& fit) {
  std::vector<FootprintSummary> out;
  const std::size_t k = static_cast<std::size_t>(std::max(fit.chosen, 0));
  for (double f : footprints_of(fit)) {
    FootprintSummary r;
    r.footprint_mm = f;
    std::vector<double> full, chosen, zero;
    int n = 0;
    for (const HalfCaseScore& s : fit.scores) {
      if (s.footprint_mm != f) continue;
      ++n;
      r.reach_px = s.reach_px;
      full.push_back(s.full.pooled);
      chosen.push_back(s.half[k].pooled);
      zero.push_back(s.half[0].pooled);
      if (s.half[k].pooled - s.full.pooled > r.excess_chosen) {
        r.excess_chosen = s.half[k].pooled - s.full.pooled;
        r.worst_chosen = s.scene;
      }
      if (s.half[0].pooled - s.full.pooled > r.excess_zero) {
        r.excess_zero = s.half[0].pooled - s.full.pooled;
        r.worst_zero = s.scene;
      }
      r.share_chosen += s.upsampled_share[k];
      r.share_zero += s.upsampled_share[0];
    }
    r.full = median(full);
    r.half_chosen = median(chosen);
    r.half_zero = median(zero);
    r.share_chosen /= n;
    r.share_zero /= n;
    out.push_back(r);
  }
  return out;
}

// The case that rules out the candidate below the chosen one (the narrowest kernel it would hand to
// the upsample that misses by more than the margin): the one with the largest reach among those
// failing there. nullptr when the chosen threshold is the first candidate.
const HalfCaseScore* deciding_case(const Fit& fit) {
  if (fit.chosen <= 0) return nullptr;
  const auto below = static_cast<std::size_t>(fit.chosen - 1);
  const HalfCaseScore* best = nullptr;
  for (const HalfCaseScore& s : fit.scores) {
    if (sss_bench::half_keeps_margin(s.full, s.half[below])) continue;
    if (best == nullptr || s.reach_px > best->reach_px) best = &s;
  }
  return best;
}

// The cases bench.half_threshold re-checks: the close-up, the narrowest kernel the chosen threshold
// upsamples and the deciding case's footprint, on the deciding scene and the scene with the least
// slack at the chosen threshold (and plane-edge-45 when they coincide: a hard edge at an angle).
nlohmann::json guard_cases(const Fit& fit) {
  const auto k = static_cast<std::size_t>(fit.chosen);
  const HalfCaseScore* decider = deciding_case(fit);
  std::set<std::string> scenes;
  std::set<double> footprints = {footprints_of(fit).front()};
  const HalfCaseScore* tightest = nullptr;
  for (const HalfCaseScore& s : fit.scores) {
    if (s.upsampled_share[k] <= 0.0) continue;
    if (tightest == nullptr || s.half[k].pooled - s.full.pooled > tightest->half[k].pooled - tightest->full.pooled) tightest = &s;
  }
  double narrowest = 1e9;
  for (const HalfCaseScore& s : fit.scores) {
    if (s.upsampled_share[k] > 0.0 && s.reach_px < narrowest) narrowest = s.reach_px;
  }
  for (const HalfCaseScore& s : fit.scores) {
    if (s.reach_px == narrowest) footprints.insert(s.footprint_mm);
  }
  if (tightest != nullptr) scenes.insert(tightest->scene);
  if (decider != nullptr) {
    scenes.insert(decider->scene);
    footprints.insert(decider->footprint_mm);
  }
  if (scenes.size() < 2) scenes.insert(scenes.count("plane-edge-45") != 0 ? "plane-albedo" : "plane-edge-45");
  return {{"scenes", scenes}, {"footprints_mm", footprints}};
}

void write_header(const Fit& fit, const std::string& path) {
  const HalfCaseScore* d = deciding_case(fit);
  std::ofstream h(path);
  h << "// Generated by sss_fit_half_threshold (tests/bench/fit_half_threshold_main.cpp,\n"
       "// scripts/fit-half-threshold.sh); do not edit by hand. Measured on the footprint sweep: the\n"
       "// smallest candidate at which the half-resolution path's interior miss stays within\n"
       "// kHalfResolutionMissMargin of the full-size passes' on every scene and footprint\n"
       "// (docs/benchmarks/half-resolution.md; the cases in tests/bench/half_threshold_fit.json).\n";
  if (d != nullptr) {
    const auto below = static_cast<std::size_t>(fit.chosen - 1);
    h << "// The candidate below it, " << fixed(fit.candidates[below], 0) << ", upsamples " << d->scene << " at "
      << fixed(d->footprint_mm) << " mm per pixel\n// (a " << fixed(d->reach_px, 1) << "-pixel reach): miss "
      << fixed(d->half[below].pooled) << " against the full-size passes' " << fixed(d->full.pooled) << ".\n";
  }
  h << "#pragma once\n\nnamespace sss::math {\n\n"
    << "// The smallest kernel reach (full-size pixels, on both axes) the upsample serves.\n"
    << "inline constexpr float kHalfResolutionMinReachPixels = " << fixed(fit.candidates[static_cast<std::size_t>(fit.chosen)], 1)
    << "f;\n\n}  // namespace sss::math\n";
}

void write_expectation(const Fit& fit, const std::string& path) {
  nlohmann::json j;
  j["criterion"] = "half miss <= full miss + kHalfResolutionMissMargin (interior, pooled) and every channel's half miss <= max(1, the full-size passes')";
  j["margin"] = sss::math::kHalfResolutionMissMargin;
  j["candidates"] = fit.candidates;
  j["chosen"] = fit.chosen >= 0 ? nlohmann::json(fit.candidates[static_cast<std::size_t>(fit.chosen)]) : nlohmann::json(nullptr);
  j["kernel_reach_mm"] = fit.reach_mm;
  j["interior_px"] = sss_bench::kCalibrationInteriorPx;
  if (fit.chosen >= 0) j["guard"] = guard_cases(fit);
  std::ofstream(path) << j.dump(1) << "\n";
}

// The plot: left, the median interior miss over the scenes against the footprint; right, the largest
// excess of the half path's miss over the full-size passes', with the margin.
std::string write_plot(const Fit& fit, const std::vector<FootprintSummary>& rows, const std::string& directory) {
  const std::string stem = directory + "/half-resolution-miss";
  const std::string t = fixed(fit.candidates[static_cast<std::size_t>(std::max(fit.chosen, 0))], 0);
  {
    std::ofstream data(stem + ".dat");
    data << "# footprint_mm full half_T half_0 excess_T excess_0\n";
    for (const FootprintSummary& r : rows) {
      data << r.footprint_mm << ' ' << r.full << ' ' << r.half_chosen << ' ' << r.half_zero << ' ' << r.excess_chosen << ' '
           << r.excess_zero << "\n";
    }
  }
  std::ofstream gp(stem + ".gp");
  gp << "set terminal pngcairo size 1400,640 noenhanced\nset output '" << stem << ".png'\n"
     << "set multiplot layout 1,2\nset logscale x\nset grid\nset key top left\nset samples 200\n"
     << "set xrange [" << rows.front().footprint_mm * 0.8 << ":" << rows.back().footprint_mm * 1.25 << "]\n"
     << "set xlabel 'millimetres per pixel (kernel reach " << fixed(fit.reach_mm, 2) << " mm / footprint = pixels)'\n"
     << "set title 'interior miss, median over the sweep scenes'\nset ylabel 'miss (0 = exact, 1 = no scattering)'\n"
     << "set yrange [0:*]\n"
     << "plot '" << stem << ".dat' using 1:2 with linespoints lw 2 title 'full-size passes', '' using 1:3 with linespoints lw 2 "
     << "title 'half path, threshold " << t << " px', '' using 1:4 with linespoints lw 2 dashtype 3 title 'half path, threshold 0'\n"
     << "set title 'half path miss - full-size miss, largest over the scenes'\nset ylabel 'miss difference'\n"
     << "set yrange [*:*]\n"
     << "plot '" << stem << ".dat' using 1:5 with linespoints lw 2 title 'threshold " << t << " px', '' using 1:6 with linespoints "
     << "lw 2 dashtype 3 title 'threshold 0', " << sss::math::kHalfResolutionMissMargin
     << " with lines dashtype 2 lc rgb 'black' lw 2 title 'margin'\nunset multiplot\n";
  gp.close();
  if (std::system(("gnuplot '" + stem + ".gp'").c_str()) != 0) {
    std::fprintf(stderr, "sss_fit_half_threshold: gnuplot could not draw %s.gp\n", stem.c_str());
  }
  return stem + ".png";
}

// The failing candidates of one case, as "0-24" style text ("none" when it keeps the margin at all).
std::string failing(const Fit& fit, const HalfCaseScore& s) {
  std::string out;
  for (std::size_t k = 0; k < fit.candidates.size(); ++k) {
    if (sss_bench::half_keeps_margin(s.full, s.half[k])) continue;
    out += (out.empty() ? "" : ", ") + fixed(fit.candidates[k], 0);
  }
  return out.empty() ? "none" : out;
}

void write_result(const Fit& fit, std::ofstream& md) {
  if (fit.chosen < 0) {
    md << "**No candidate keeps the margin**: the half path's miss exceeds the full-size passes' by more than "
       << sss::math::kHalfResolutionMissMargin << " at some footprint whichever threshold; the per-case table shows where.\n\n";
    return;
  }
  const std::string t = fixed(fit.candidates[static_cast<std::size_t>(fit.chosen)], 0);
  md << "**Threshold: " << t << " pixels** (`kHalfResolutionMinReachPixels`, "
     << "module/src/math/half_resolution_threshold.hpp): kernels reaching at least " << t
     << " full-size pixels on both axes run at half size; on a face in skin's default kernel (reach "
     << fixed(fit.reach_mm, 2) << " mm) that is " << fixed(fit.reach_mm / fit.candidates[static_cast<std::size_t>(fit.chosen)], 3)
     << " mm per pixel or finer.";
  if (const HalfCaseScore* d = deciding_case(fit)) {
    const auto below = static_cast<std::size_t>(fit.chosen - 1);
    md << " The candidate below, " << fixed(fit.candidates[below], 0) << ", fails on " << d->scene << " at "
       << fixed(d->footprint_mm) << " mm per pixel (reach " << fixed(d->reach_px, 1) << " px): miss "
       << fixed(d->half[below].pooled) << " against " << fixed(d->full.pooled) << ".";
  }
  md << "\n\n";
}

void write_report(const Fit& fit, const std::string& path) {
  const std::vector<FootprintSummary> rows = summarise(fit);
  const std::size_t slash = path.find_last_of('/');
  const std::string png = write_plot(fit, rows, slash == std::string::npos ? "." : path.substr(0, slash));
  const std::string t = fixed(fit.candidates[static_cast<std::size_t>(std::max(fit.chosen, 0))], 0);
  std::ofstream md(path);
  md << "# Half resolution: where it may run\n\n"
     << "Generated by scripts/fit-half-threshold.sh (tests/bench/fit_half_threshold_main.cpp); do not edit by hand.\n\n"
     << "SSS_PATH_HALF_RESOLUTION runs the passes at half size for the pixels whose kernel reaches at least "
     << "`kHalfResolutionMinReachPixels` full-size pixels on both axes, and the full-size passes elsewhere "
     << "(module/src/math/half_resolution.hpp). The threshold is measured here: the footprint sweep's scenes "
     << "(planes of skin under edges, a spot, a disk and an albedo pattern; the default kernel) at footprints from "
     << "0.05 mm per pixel (a 4K close-up) to 2 mm (a far crowd), plus for every candidate the footprint where the kernel "
     << "reaches just that many pixels (the narrowest kernel it hands to the upsample). Each case is filtered by the CPU "
     << "model of the full-size passes (cpu_pass_kernel_filter) and of the half path at every candidate "
     << "(cpu_half_resolution_filter) and scored by interior miss against the exact reference (tests/bench/metrics.hpp: "
     << "||result - reference|| / ||input - reference||, silhouettes and borders excluded). The threshold is the smallest "
     << "candidate at which every case keeps the half path's miss within `kHalfResolutionMissMargin` = "
     << sss::math::kHalfResolutionMissMargin << " of the full-size passes' and leaves no channel above 1 (worse than no "
     << "scattering) where theirs is not. Candidates: ";
  for (std::size_t k = 0; k < fit.candidates.size(); ++k) md << (k == 0 ? "" : ", ") << fixed(fit.candidates[k], 0);
  md << " pixels (0: every translucent pixel with a half-size neighbour on its surface is upsampled).\n\n";
  write_result(fit, md);
  md << "What it costs: instructions per frame on llvmpipe against the masked passes in "
        "[half-resolution-cost.md](half-resolution-cost.md) (scripts/half-cost.sh); time against a two-pass copy, "
        "the `separable-half` rows of [benchmarks-passes.md](../benchmarks-passes.md) "
        "(scripts/update-pass-benchmark.sh).\n\n";
  md << "## Per footprint\n\nMedians over the " << fit.scores.size() / rows.size() << " scenes; the largest difference "
     << "names its scene; the upsampled share is the mean share of translucent pixels the upsample wrote (the work moved "
     << "to half size).\n\n"
     << "| mm/px | reach (px) | full-size miss | half miss, " << t << " px | half miss, 0 px | largest half - full, " << t
     << " px | largest half - full, 0 px | upsampled, " << t << " px | upsampled, 0 px |\n"
     << "|---:|---:|---:|---:|---:|---|---|---:|---:|\n";
  for (const FootprintSummary& r : rows) {
    md << "| " << fixed(r.footprint_mm) << " | " << fixed(r.reach_px, 1) << " | " << fixed(r.full) << " | " << fixed(r.half_chosen)
       << " | " << fixed(r.half_zero) << " | "
       << (r.share_chosen > 0.0 ? fixed(r.excess_chosen) + " (" + r.worst_chosen + ")" : std::string("0 (full size)")) << " | " << fixed(r.excess_zero)
       << " (" << r.worst_zero << ") | " << fixed(100.0 * r.share_chosen, 0) << " % | " << fixed(100.0 * r.share_zero, 0) << " % |\n";
  }
  md << "\n![interior miss against footprint](" << png.substr(png.find_last_of('/') + 1) << ")\n\n"
     << "## Per case\n\n| scene | mm/px | reach (px) | full-size miss | half miss, " << t << " px | half miss, 0 px | "
     << "worst channel, 0 px | thresholds that fail it |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  const auto k = static_cast<std::size_t>(std::max(fit.chosen, 0));
  for (const HalfCaseScore& s : fit.scores) {
    md << "| " << s.scene << " | " << fixed(s.footprint_mm) << " | " << fixed(s.reach_px, 1) << " | " << fixed(s.full.pooled) << " | "
       << fixed(s.half[k].pooled) << " | " << fixed(s.half[0].pooled) << " | " << fixed(s.half[0].worst_channel()) << " | "
       << failing(fit, s) << " |\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string header = "module/src/math/half_resolution_threshold.hpp", expectation = "tests/bench/half_threshold_fit.json",
              doc = "docs/benchmarks/half-resolution.md";
  enum { kHeader = 1000, kExpectation, kDoc, kHelp };
  static const option long_options[] = {{"header", required_argument, nullptr, kHeader},
                                        {"expectation", required_argument, nullptr, kExpectation},
                                        {"doc", required_argument, nullptr, kDoc},
                                        {"help", no_argument, nullptr, kHelp},
                                        {nullptr, 0, nullptr, 0}};
  const char* usage = "usage: sss_fit_half_threshold [--header PATH] [--expectation PATH] [--doc PATH]\n";
  for (int c; (c = getopt_long(argc, argv, "", long_options, nullptr)) != -1;) {
    switch (c) {
      case kHeader: header = optarg; break;
      case kExpectation: expectation = optarg; break;
      case kDoc: doc = optarg; break;
      case kHelp: std::fputs(usage, stdout); return 0;
      default: std::fputs(usage, stderr); return 2;
    }
  }
  if (optind < argc) {
    std::fputs(usage, stderr);
    return 2;
  }
  const sss::math::FilterSettings settings;  // the library's default kernel
  Fit fit;
  fit.candidates = sss_bench::half_threshold_candidates();
  fit.reach_mm = sss_bench::half_threshold_reach_mm(settings);
  const auto cases = sss_bench::make_calibration_cases(sss_bench::half_threshold_footprints(settings), sss_bench::kCalibrationInteriorPx);
  std::fprintf(stderr, "%zu cases, %zu candidates\n", cases.size(), fit.candidates.size());
  fit.scores = sss_bench::score_half_resolution(settings, cases, fit.candidates);
  fit.chosen = sss_bench::smallest_passing_threshold(fit.scores, fit.candidates.size());
  write_expectation(fit, expectation);
  write_report(fit, doc);
  if (fit.chosen < 0) {
    std::fprintf(stderr, "no candidate keeps the margin: %s left as it was (see %s)\n", header.c_str(), doc.c_str());
    return 1;
  }
  write_header(fit, header);
  std::fprintf(stderr, "threshold %.0f px\n", double(fit.candidates[static_cast<std::size_t>(fit.chosen)]));
  return 0;
}
