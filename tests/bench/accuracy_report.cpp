#include "accuracy_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "regions.hpp"
#include "sweep_summary.hpp"
#include "timing.hpp"

namespace sss_bench {

namespace {

namespace fs = std::filesystem;

std::string fmt(double v, const char* spec) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, spec, v);
  return buffer;
}

std::string link_to(const std::string& file, const std::string& doc) {
  return fs::relative(fs::absolute(file), fs::absolute(fs::path(doc).parent_path())).generic_string();
}

// Series i is on the Pareto front of a band when no other timed series (`timed`) is both no slower
// and no less accurate there, and better in one of the two.
bool on_front(std::size_t i, const std::vector<BandSummary>& all, const std::vector<bool>& timed) {
  const BandSummary& b = all[i];
  for (std::size_t k = 0; k < all.size(); ++k) {
    const BandSummary& o = all[k];
    if (k == i || !timed[k] || o.count == 0) continue;
    const bool no_worse = o.median_time_ratio <= b.median_time_ratio && o.median_miss <= b.median_miss;
    const bool better = o.median_time_ratio < b.median_time_ratio || o.median_miss < b.median_miss;
    if (no_worse && better) return false;
  }
  return true;
}

// "| method | 0.05 | ... |" and its alignment row: a table with a column per footprint.
void footprint_table_header(std::ostream& out, const std::vector<double>& footprints) {
  out << "| method |";
  for (double f : footprints) out << " " << fmt(f, "%.3g") << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < footprints.size(); ++i) out << "---:|";
  out << "\n";
}

}  // namespace

const char* const kErrorTableHeader =
    "| method | passes | ms | × copy | **miss interior** | R | G | B | miss silhouette | miss border | rel. RMSE "
    "interior | rel. RMSE | p99 abs | max abs | SSIM |\n"
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";

const char* const kConservingErrorTableHeader =
    "| method | passes | ms | × copy | **miss interior** | R | G | B | miss interior, conserving reference | miss "
    "silhouette | miss border | rel. RMSE interior | rel. RMSE | p99 abs | max abs | SSIM |\n"
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";

void write_error_row(std::ostream& out, const ResultRow& r, bool conserving) {
  const RegionScore& in = r.interior();
  out << "| " << method_label(r) << " | " << r.passes << " | "
      << (r.method == "no-scattering" ? std::string("–") : fmt(r.time_ms, "%.2f")) << " | "
      << (r.method == "no-scattering" ? std::string("–") : fmt(r.time_ratio_to_copy, "%.2f")) << " | **"
      << miss_text(in.miss) << "** | " << miss_text(in.miss_channel[0]) << " | " << miss_text(in.miss_channel[1]) << " | "
      << miss_text(in.miss_channel[2]) << " | "
      << (conserving ? miss_text(r.interior_conserving.miss) + " | " : std::string()) << miss_text(r.region[1].miss)
      << " | " << miss_text(r.region[2].miss)
      << " | " << (std::isnan(r.relative_rmse_interior) ? std::string("–") : fmt(r.relative_rmse_interior, "%.4f"))
      << " | " << fmt(r.relative_rmse, "%.4f") << " | " << fmt(r.p99_abs_error, "%.4f") << " | "
      << fmt(r.max_abs_error, "%.3f") << " | " << fmt(r.ssim, "%.4f") << " |\n";
}

void write_error_definitions(std::ostream& out, const RunInfo& info) {
  out << "## How errors are measured\n\n"
      << "- **miss** = ‖result − exact‖ / ‖input − exact‖ (L2 norms over the pixels of a region, per channel and "
         "pooled over R, G and B; tests/bench/metrics.hpp): the share of the change scattering needs that a method "
         "leaves undone. 0 is exact, 1 is as wrong as doing nothing (the `no-scattering` row of every table, the "
         "input itself), above 1 is worse than doing nothing. Relative RMSE divides by the image's own energy, "
         "most of which no filter moves, so it stays small (a few per cent) even for a filter that does almost "
         "nothing; `miss` is read against doing nothing.\n"
      << "- **Regions** (tests/bench/regions.hpp), reported apart: *border*, translucent pixels nearer to the frame "
         "edge than the profile's reach; *silhouette*, the others within the reach of a non-translucent pixel or of "
         "a depth step (a translucent neighbour more than four pixel widths nearer or farther); *interior*, every "
         "other translucent pixel. The reach is "
      << fmt(info.reach_mm, "%.2f")
      << " mm, the radius beyond which at most 1e-3 of a point's light lands in any channel of d'Eon's skin "
         "profile, in pixels at each pixel's own depth. **The headline is the interior.**\n"
      << "- **Past the frame edge** the exact references take the surface to end, as at a silhouette: no light "
         "comes from beyond the frame and light scattered beyond it is lost. The frame holds nothing else to go "
         "on (what lies beyond is not rendered), and it is the only choice that needs no invented pixels. A "
         "normalised filter instead reads the edge pixels again (clamp), so within the reach of the edge the two "
         "differ by construction, for every method alike; that band is the *border* region, left out of the "
         "headline. The same holds at silhouettes, where the surface really ends.\n"
      << "- **References**: the canonical scenes and the head use the exact 2D surface convolution "
         "(module/src/math/exact_reference.hpp); the footprint sweep's planes face the camera, where that "
         "convolution factors into one horizontal and one vertical 1D convolution per Gaussian of the profile with "
         "each source pixel integrated (erf differences; module/src/math/plane_reference.hpp): exact in double "
         "at any size and footprint, and equal to the 2D one to 1e-9 (tests/unit/plane_reference_test.cpp).\n"
      << "- **The conserving reference** (the head scenes, beside the exact one): on a faceted mesh the exact 2D "
         "convolution does not conserve light, as the surface rebuilt from depth holds less area within the "
         "profile's reach along the triangles' edges and in concavities than a plane: a uniform irradiance of 1 "
         "comes back a few per cent darker there, which no normalised filter can reproduce. So each head scene's "
         "rows are scored once more against the exact result divided, per channel and receiver, by that mass (the "
         "same convolution of a uniform irradiance on the same pixels, receivers and method): `miss_interior_conserving` "
         "in results.csv, a column of the head close-up's table, and the mass itself as a picture "
         "(`head-close-*-mass.png`: |mass − 1|, the top of the ramp 0.05). The existing columns keep the exact "
         "reference.\n"
      << "- `mm/px` is the pixel footprint: the sweep's by construction, elsewhere the median over the "
         "translucent pixels of the footprint on a plane facing the camera at their depth.\n\n";
}

void write_footprint_sweep(std::ostream& out, const std::vector<ResultRow>& rows,
                           const std::vector<std::string>& footprint_plots, const std::vector<std::string>& band_plots,
                           const std::string& doc_path) {
  const std::vector<SweepSeries> series = sweep_series(rows);
  const std::vector<double> footprints = sweep_footprints(rows);
  const std::vector<std::string> scenes = sweep_scenes(rows);
  if (series.empty()) return;
  out << "## Accuracy across pixel footprints\n\n"
      << "The footprint sweep: " << scenes.size() << " planes facing the camera (";
  for (std::size_t i = 0; i < scenes.size(); ++i) out << (i ? ", " : "") << "`" << scenes[i] << "`";
  out << "; tests/bench/scenes/scenes.hpp: shadow edges at several angles, a small spot and a disk of light, "
         "per-pixel albedo) at "
      << footprints.size() << " footprints from " << fmt(footprints.front(), "%.3g") << " to "
      << fmt(footprints.back(), "%.3g")
      << " mm per pixel, each in a frame of the interior plus the reach on every side. Each method runs once per "
         "kernel (the depth test and the paths change nothing on a plane facing the camera).\n\n";
  // The headline: the library's default (eq. 1, 17 taps, follow-surface) over every sweep row, and
  // the most accurate method of each band.
  for (const SweepSeries& s : series) {
    if (s.method != "separable" || s.taps != 17 || !s.follow_surface) continue;
    std::vector<double> misses;
    for (const std::string& scene : scenes) {
      for (double f : footprints) {
        if (const ResultRow* r = sweep_row(rows, s, scene, f); r != nullptr && !std::isnan(r->interior().miss)) {
          misses.push_back(r->interior().miss);
        }
      }
    }
    if (misses.empty()) break;
    out << "**Headline.** The default filter (`" << s.label << "`) leaves between "
        << miss_text(*std::min_element(misses.begin(), misses.end())) << " and "
        << miss_text(*std::max_element(misses.begin(), misses.end())) << " of the needed change undone on the "
        << "interior of these scenes (median " << miss_text(median(misses)) << "; 0 is exact, 1 is no scattering).";
    for (const FootprintBand& band : footprint_bands()) {
      std::size_t best = series.size();
      double best_miss = 0.0;
      for (std::size_t i = 0; i < series.size(); ++i) {
        if (series[i].method == "no-scattering") continue;
        const BandSummary b = band_summary(rows, series[i], band);
        if (b.count > 0 && (best == series.size() || b.median_miss < best_miss)) best = i, best_miss = b.median_miss;
      }
      if (best < series.size()) {
        out << " Most accurate at " << band.name << " footprints: `" << series[best].label << "` ("
            << miss_text(best_miss) << ").";
      }
    }
    out << "\n\n";
  }
  out << "**Median interior miss over the scenes**, per footprint (mm per pixel; 1 = no better than doing "
         "nothing):\n\n";
  footprint_table_header(out, footprints);
  for (const SweepSeries& s : series) {
    out << "| " << s.label << " |";
    for (double f : footprints) out << " " << miss_text(median_miss_at(rows, s, f)) << " |";
    out << "\n";
  }
  out << "\n**Worst channel**: the largest per-channel interior miss over the scenes, per footprint (above 1: "
         "that channel ends up further from the exact result than the unfiltered input):\n\n";
  footprint_table_header(out, footprints);
  for (const SweepSeries& s : series) {
    if (s.method == "no-scattering") continue;
    out << "| " << s.label << " |";
    for (double f : footprints) {
      double worst = -1.0;
      for (const std::string& scene : scenes) {
        if (const ResultRow* r = sweep_row(rows, s, scene, f)) {
          for (double c : r->interior().miss_channel) {
            if (!std::isnan(c)) worst = std::max(worst, c);
          }
        }
      }
      out << " " << (worst < 0.0 ? std::string("–") : (worst > 1.0 ? "**" + miss_text(worst) + "**" : miss_text(worst)))
          << " |";
    }
    out << "\n";
  }

  out << "\n### Per footprint band\n\nMedians over the band's scenes and footprints (time as a multiple of the "
         "two-pass copy of the same frame, so frames of different sizes compare); *front*: no other method is both "
         "as fast and as accurate there (the Pareto front of the plots below).\n";
  for (const FootprintBand& band : footprint_bands()) {
    std::vector<BandSummary> summaries;
    for (const SweepSeries& s : series) summaries.push_back(band_summary(rows, s, band));
    if (std::all_of(summaries.begin(), summaries.end(), [](const BandSummary& b) { return b.count == 0; })) continue;
    std::size_t best = summaries.size();
    for (std::size_t i = 0; i < series.size(); ++i) {
      if (series[i].method == "no-scattering" || summaries[i].count == 0) continue;
      if (best == summaries.size() || summaries[i].median_miss < summaries[best].median_miss) best = i;
    }
    out << "\n**" << band.name << "** (" << fmt(band.lo, "%.2g") << " to "
        << (band.hi > 100.0 ? std::string("∞") : fmt(band.hi, "%.2g")) << " mm per pixel: " << band.what << ")"
        << (best < series.size() ? ": most accurate `" + series[best].label + "`" : std::string()) << "\n\n"
        << "| method | median miss | worst miss | worst channel | median × copy | front |\n"
           "|---|---:|---:|---:|---:|---|\n";
    std::vector<bool> timed(series.size());
    for (std::size_t i = 0; i < series.size(); ++i) timed[i] = series[i].method != "no-scattering";
    for (std::size_t i = 0; i < series.size(); ++i) {
      const BandSummary& b = summaries[i];
      if (b.count == 0) continue;
      const bool none = !timed[i];
      const bool front = !none && on_front(i, summaries, timed);
      out << "| " << series[i].label << " | " << miss_text(b.median_miss) << " | " << miss_text(b.worst_miss) << " | "
          << miss_text(b.worst_channel) << " | " << (none ? std::string("–") : fmt(b.median_time_ratio, "%.2f")) << " | "
          << (front ? "front" : "") << " |\n";
    }
  }
  if (!footprint_plots.empty() || !band_plots.empty()) {
    out << "\n### Plots\n\nMiss against footprint, one curve per method and tap count (the median over the "
           "scenes first, then each scene):\n\n";
    for (const std::string& plot : footprint_plots) {
      out << "![" << fs::path(plot).stem().string() << "](" << link_to(plot, doc_path) << ")\n\n";
    }
    out << "Miss against time per footprint band (the Pareto front: down and left is better; the labels are taps "
           "per pass):\n\n";
    for (const std::string& plot : band_plots) {
      out << "![" << fs::path(plot).stem().string() << "](" << link_to(plot, doc_path) << ")\n\n";
    }
  }
}

void write_scene_tables(std::ostream& out, const std::vector<ResultRow>& rows) {
  out << "\n## Every scene, size and footprint\n\nOne table each, the `no-scattering` row (the input) first; "
         "*miss* per region (regions.hpp), the interior's per channel, and relative RMSE on the interior and over "
         "every translucent pixel. Click a line to open its table.\n";
  std::vector<std::string> keys;
  std::map<std::string, std::vector<const ResultRow*>> by_key;
  for (const ResultRow& r : rows) {
    const std::string key = r.scene + " at " + std::to_string(r.width) + "×" + std::to_string(r.height) + ", " +
                            fmt(r.footprint_mm, "%.3g") + " mm/px";
    if (by_key.count(key) == 0) keys.push_back(key);
    by_key[key].push_back(&r);
  }
  for (const std::string& key : keys) {
    const std::vector<const ResultRow*>& scene_rows = by_key[key];
    const ResultRow* none = nullptr;
    for (const ResultRow* r : scene_rows) {
      if (r->method == "no-scattering") none = r;
    }
    out << "\n<details><summary>" << key;
    if (none != nullptr) {
      out << ": " << none->region[0].pixels << " interior, " << none->region[1].pixels << " silhouette, "
          << none->region[2].pixels << " border pixels";
    }
    out << "</summary>\n\n" << kErrorTableHeader;
    if (none != nullptr) write_error_row(out, *none);
    for (const ResultRow* r : scene_rows) {
      if (r != none && r->method != "copy" && r->method != "copy-compute") write_error_row(out, *r);
    }
    out << "\n</details>\n";
  }
}

}  // namespace sss_bench
