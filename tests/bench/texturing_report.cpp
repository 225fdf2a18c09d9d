// sss_bench_texturing's outputs (texturing_bench.hpp): results.csv, and the Markdown document with
// the bounds per plane frame, what the run measured where a frame is over one, and every
// row of the planes and the head.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "texturing_bench.hpp"

namespace sss_bench::texturing {

namespace {

// A miss is a share of the needed change: where a mode needs none (uniform light, post-scatter: the
// answer is the input), it has no meaning, and the tables say so.
bool needs_change(const Row& r) { return r.needed >= 1e-3; }
bool has_untextured(const Row& r) { return r.light != "uniform" && needs_change(r); }

std::string number(double v, const char* otherwise) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", v);
  return std::isfinite(v) ? std::string(text) : std::string(otherwise);
}

// The plane frames (footprint, turn) in the order they ran.
std::vector<const Row*> plane_frames(const std::vector<Row>& rows) {
  std::vector<const Row*> firsts;
  for (const Row& r : rows) {
    if (r.scene != "plane") continue;  // the bounds are the planes' (the head's rows have a table of their own)
    bool seen = false;
    for (const Row* f : firsts) seen = seen || (f->footprint_mm == r.footprint_mm && f->turn_deg == r.turn_deg);
    if (!seen) firsts.push_back(&r);
  }
  return firsts;
}

bool same_frame(const Row& a, const Row& b) {
  return a.scene == b.scene && a.footprint_mm == b.footprint_mm && a.turn_deg == b.turn_deg;
}

// A frame's worst row of `method` by `score` (the rows it scores are those where `score` is finite),
// or nullptr.
template <typename Score>
const Row* worst_row(const std::vector<Row>& rows, const Row& frame, const char* method, Score score) {
  const Row* worst = nullptr;
  for (const Row& r : rows) {
    if (!same_frame(r, frame) || r.method != method || !std::isfinite(score(r))) continue;
    if (worst == nullptr || score(r) > score(*worst)) worst = &r;
  }
  return worst;
}

// The frame's row of `method` in `like`'s mode, light and albedo, or nullptr.
const Row* find_row(const std::vector<Row>& rows, const Row& frame, const std::string& method, const Row& like,
                    const std::string& light) {
  for (const Row& r : rows) {
    if (same_frame(r, frame) && r.method == method && r.mode == like.mode && r.light == light && r.albedo == like.albedo) {
      return &r;
    }
  }
  return nullptr;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
// The default's textured miss over its untextured one (the bound: 0.02).
double default_gap(const Row& r) { return has_untextured(r) ? r.miss.pooled - r.untextured : kNaN; }
// A sum of Gaussians' miss wherever a change is needed (the bound: 0.05).
double textured_miss(const Row& r) { return needs_change(r) ? r.miss.pooled : kNaN; }
constexpr double kDefaultGapBound = 0.02, kSumOfGaussiansBound = 0.05;

// Where a frame is over a bound, what the run measured of why: for the default, its detail kept in
// the same mode under the uniform light beside the exact answer's (a blur of the albedo that differs
// from the profile's); for the sum of Gaussians, its two controls' misses on the same row.
void write_over_bounds(std::ofstream& d, const std::vector<Row>& rows) {
  std::string text;
  bool default_over = false, sum_of_gaussians_over = false;
  char line[800];
  for (const Row* f : plane_frames(rows)) {
    const Row* gap = worst_row(rows, *f, "separable", default_gap);
    if (gap != nullptr && default_gap(*gap) > kDefaultGapBound) {
      const Row* uniform = find_row(rows, *f, "separable", *gap, "uniform");
      std::snprintf(line, sizeof line,
                    "- %.3f mm/px, turned %g°, the default: %s over the %s albedo misses %.3f, %.3f over its "
                    "untextured %.3f. Under the uniform light the same albedo keeps %s of its detail in that mode "
                    "where the exact answer keeps %s.\n",
                    f->footprint_mm, f->turn_deg, gap->mode.c_str(), gap->albedo.c_str(), gap->miss.pooled,
                    default_gap(*gap), gap->untextured, uniform != nullptr ? number(uniform->detail, "—").c_str() : "—",
                    uniform != nullptr ? number(uniform->detail_exact, "—").c_str() : "—");
      text += line;
      default_over = true;
    }
    const Row* sog = worst_row(rows, *f, "sum-of-gaussians", textured_miss);
    if (sog != nullptr && textured_miss(*sog) > kSumOfGaussiansBound) {
      const auto control_miss = [&](const char* control) {
        const Row* r = find_row(rows, *f, control, *sog, sog->light);
        return r != nullptr ? number(r->miss.pooled, "—") : std::string("—");
      };
      std::snprintf(line, sizeof line,
                    "- %.3f mm/px, turned %g°, the sum of Gaussians: %s, %s light over the %s albedo, misses %.3f at "
                    "17 taps, %s at 33, and %s at 17 with jitter 0.5.\n",
                    f->footprint_mm, f->turn_deg, sog->mode.c_str(), sog->light.c_str(), sog->albedo.c_str(),
                    sog->miss.pooled, control_miss(kDenserControl).c_str(), control_miss(kJitteredControl).c_str());
      text += line;
      sum_of_gaussians_over = true;
    }
  }
  d << "### Where a frame is over a bound\n\n";
  if (text.empty()) {
    d << "None.\n\n";
    return;
  }
  d << text << "\n";
  if (default_over) {
    d << "The default is one separable product k ⊗ k of a kernel that is not a Gaussian, so along the screen's "
         "diagonals it is not the profile's radial blur: at an albedo's diagonal frequencies (a checker's) it "
         "blurs more than the profile, by what the detail-kept figures above say. Pre-scatter hands the kernel "
         "the light times the albedo as the library always did (bit-identical, by requirement), so this is the "
         "default kernel's own figure on such an albedo, not a texturing mode's.\n\n";
  }
  if (sum_of_gaussians_over) {
    d << "The sum of Gaussians is exact per term, but each term's passes read at most 17 whole pixels: its widest "
         "term (d'Eon's 7.41 mm² variance) spreads them over several millimetres, so they sample a periodic "
         "albedo of about their own spacing (the checker's 1 mm period) coherently; the 33-tap control shows the "
         "miss leave with denser taps. At 17 taps the settings' jitter (the outer half of the taps moved within "
         "their cells per pixel) breaks the coherence, at the price of per-pixel noise (its own column: its worst "
         "frame is then the soft-edged light's, not the checker's). Reading the wider terms from an image already "
         "blurred by the narrower ones (d'Eon and Luebke's cascade) would remove it at 17 taps without noise; the "
         "passes do not do that today.\n\n";
  }
}

// The bounds per frame (footprint, turn): the default's worst textured miss over its
// untextured one per mode, the sum of Gaussians' worst textured miss (and each control's), and
// post-scatter's detail kept under the uniform light over the exact answer's, worst over the
// albedos.
void write_bounds(std::ofstream& d, const std::vector<Row>& rows) {
  d << "## The issue's bounds\n\n"
       "Per plane frame, the worst over both lights and both albedos: the "
       "default's textured miss minus its untextured miss in each mode (bound: 0.02), the sum of Gaussians' "
       "largest textured miss in any mode (bound: 0.05; beside it two controls: at 33 taps, and at 17 with "
       "jitter 0.5), and "
       "post-scatter's detail kept over the exact answer's under the uniform light (bound: within 2 % of 1; the "
       "run fails otherwise). A cell is — where nothing was measurable (no change needed, or no detail above 1 "
       "cycle/mm).\n\n"
       "| mm/px | turn | default pre | default post | default pre and post | sum of Gaussians | "
       "sum of Gaussians, 33 taps | sum of Gaussians, jitter 0.5 | post detail / exact |\n"
       "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto worst = [](double current, double v) { return std::isfinite(current) ? std::max(current, v) : v; };
  char line[400];
  for (const Row* f : plane_frames(rows)) {
    double gap[3] = {kNaN, kNaN, kNaN}, sum_of_gaussians = kNaN, denser = kNaN, jittered = kNaN, detail = kNaN;
    for (const Row& r : rows) {
      if (!same_frame(r, *f)) continue;
      for (int m = 0; m < 3; ++m) {
        if (r.method == "separable" && r.mode == mode_name(kModes[m]) && has_untextured(r)) {
          gap[m] = worst(gap[m], default_gap(r));
        }
      }
      if (r.method == "sum-of-gaussians" && needs_change(r)) sum_of_gaussians = worst(sum_of_gaussians, r.miss.pooled);
      if (r.method == kDenserControl && needs_change(r)) denser = worst(denser, r.miss.pooled);
      if (r.method == kJitteredControl && needs_change(r)) jittered = worst(jittered, r.miss.pooled);
      if (r.method != kDenserControl && r.method != kJitteredControl && r.light == "uniform" &&
          r.mode == mode_name(SSS_TEXTURING_POST_SCATTER) && std::isfinite(r.detail_exact)) {
        const double off = r.detail / r.detail_exact;
        if (!std::isfinite(detail) || std::fabs(off - 1.0) > std::fabs(detail - 1.0)) detail = off;
      }
    }
    std::snprintf(line, sizeof line, "| %.3f | %g | %s | %s | %s | %s | %s | %s | %s |\n", f->footprint_mm,
                  f->turn_deg, number(gap[0], "—").c_str(), number(gap[1], "—").c_str(), number(gap[2], "—").c_str(),
                  number(sum_of_gaussians, "—").c_str(), number(denser, "—").c_str(), number(jittered, "—").c_str(),
                  number(detail, "—").c_str());
    d << line;
  }
  d << "\n";
  write_over_bounds(d, rows);
}

void write_rows(std::ofstream& d, const std::vector<Row>& rows, bool head) {
  d << "| " << (head ? "median mm/px" : "mm/px") << " | turn | light | albedo | method | mode | miss | untextured | "
    << "miss − untextured | detail kept | exact | kept / exact |\n"
    << "|---:|---:|---|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  char line[400];
  for (const Row& r : rows) {
    if ((r.scene != "plane") != head) continue;
    const auto miss_text = [&](double miss) { return needs_change(r) ? number(miss, "—") : std::string("— (none needed)"); };
    std::snprintf(line, sizeof line, "| %.3f | %g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.footprint_mm,
                  r.turn_deg, r.light.c_str(), r.albedo.c_str(), r.method.c_str(), r.mode.c_str(),
                  miss_text(r.miss.pooled).c_str(), has_untextured(r) ? number(r.untextured, "—").c_str() : "—",
                  has_untextured(r) ? number(r.miss.pooled - r.untextured, "—").c_str() : "—",
                  number(r.detail, "— (no detail)").c_str(), number(r.detail_exact, "— (no detail)").c_str(),
                  number(r.detail / r.detail_exact, "— (no detail)").c_str());
    d << line;
  }
  d << "\n";
}

}  // namespace

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream f(path);
  f << "scene,footprint_mm,turn_deg,light,albedo,method,mode,miss,miss_r,miss_g,miss_b,untextured_miss,needed,"
       "detail_kept,detail_exact\n";
  for (const Row& r : rows) {
    f << r.scene << ',' << r.footprint_mm << ',' << r.turn_deg << ',' << r.light << ',' << r.albedo << ',' << r.method
      << ',' << r.mode << ',' << r.miss.pooled << ',' << r.miss.channel[0] << ',' << r.miss.channel[1] << ','
      << r.miss.channel[2] << ',' << r.untextured << ',' << r.needed << ',' << r.detail << ',' << r.detail_exact << '\n';
  }
}

void write_document(const Options& o, const std::string& renderer, const std::vector<Row>& rows) {
  std::filesystem::create_directories(std::filesystem::path(o.doc).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(o.doc).parent_path());
  std::ofstream d(o.doc);
  const std::time_t t = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  d << "# Texturing modes on textured planes and on the head\n\n"
    << "Generated by `sss_bench_texturing` (tests/bench/texturing_bench.cpp, texturing_head.cpp, texturing_report.cpp; "
       "`scripts/run-texturing-bench.sh`) on "
    << renderer << ", " << date << ": `" << o.command_line << "`.\n\n"
    << "**Planes**: the turn sweep's orthographic plane, facing the camera or turned about screen x (17 taps, the "
       "library's default settings on the fragment path; mm/px is the footprint where it faces the camera, so a "
       "plane turned 60° measures twice that along y), its colour the light times an albedo at pore scale laid "
       "out on the surface (a checker of 0.5 mm cells, or value noise of 0.2 mm cells, on skin-like base "
       "colours). Each mode is scored against its own exact answer A_post ⊙ (R ∗ (colour / A_post)), R d'Eon's "
       "skin convolved on the plane in closed form: **miss** (the interior's share of the needed change left "
       "undone: 0 exact, 1 no better than the input), beside the same method on the light alone (**untextured**, "
       "pre-scatter: the mode's own accuracy apart from the albedo). **Detail kept**: the image's power above 1 "
       "cycle per surface millimetre (its spectrum over the interior, Hann-windowed: "
       "tests/bench/texturing_detail.hpp) in the output over the input's, beside the exact answer's "
       "(post-scatter's answer keeps nearly all of it; pre-scatter's blurs it).\n\n"
    << "Under the **uniform** light the detail is the albedo's alone, and post-scatter's exact answer is the "
       "input (kept / exact = 1 is the whole albedo kept); under the **soft edges** (the plane's own light, with "
       "its own per-pixel albedo) the light adds detail of its own that every mode blurs. At 1 mm per pixel "
       "facing the camera the pixels hold no frequency above 1 cycle per mm: no detail to measure.\n\n"
    << "**Head**: the close-up with its scan's albedo map, lit as the benchmark lights it; each mode against A_post ⊙ (R ∗ "
       "(colour / A_post)) over the visible surface rebuilt from depth (the benchmark's reference, "
       "tests/bench/reference.hpp), on the interior apart from silhouettes and depth edges. A curved surface has "
       "no one spectrum: its detail kept is the power of each pixel minus its mean over a box 1 mm wide at the "
       "pixel's footprint (its view distance; the slope is not counted), which passes about what lies above 1 "
       "cycle per mm. A scanned albedo already holds the skin's own scattering, so post-scatter's answer is the "
       "right one for it; the other modes' rows say how far each is from its own answer. Head scan: \"Infinite, 3D "
       "Head Scan\" by Lee Perry-Smith is licensed under a Creative Commons Attribution 3.0 Unported License. Based "
       "on a work at www.triplegangers.com. Permissions beyond the scope of this license may be available at "
       "http://www.ir-ltd.net/\n\n";
  write_bounds(d, rows);
  d << "## Planes\n\n";
  write_rows(d, rows, false);
  if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.scene != "plane"; })) {
    d << "## Head\n\n";
    write_rows(d, rows, true);
  }
}

}  // namespace sss_bench::texturing
