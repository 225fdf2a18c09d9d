#include "sweep_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "timing.hpp"

namespace sss_bench {

const std::vector<FootprintBand>& footprint_bands() {
  static const std::vector<FootprintBand> bands = {
      {"fine", 0.0, 0.2, "4K and 1080p close-ups of a face"},
      {"medium", 0.2, 0.6, "a face filling part of a 1080p frame"},
      {"coarse", 0.6, 1e9, "full figures and crowds"}};
  return bands;
}

std::vector<SweepSeries> sweep_series(const std::vector<ResultRow>& rows) {
  std::vector<SweepSeries> series;
  for (const ResultRow& r : rows) {
    if (!r.sweep || r.method == "copy" || r.method == "copy-compute") continue;
    const std::string label = method_label(r);
    if (std::none_of(series.begin(), series.end(), [&](const SweepSeries& s) { return s.label == label; })) {
      series.push_back({label, r.method, r.taps, r.follow_surface});
    }
  }
  return series;
}

std::vector<std::string> sweep_scenes(const std::vector<ResultRow>& rows) {
  std::vector<std::string> scenes;
  for (const ResultRow& r : rows) {
    if (r.sweep && std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  }
  return scenes;
}

std::vector<double> sweep_footprints(const std::vector<ResultRow>& rows) {
  std::vector<double> footprints;
  for (const ResultRow& r : rows) {
    if (r.sweep && std::find(footprints.begin(), footprints.end(), r.footprint_mm) == footprints.end()) {
      footprints.push_back(r.footprint_mm);
    }
  }
  std::sort(footprints.begin(), footprints.end());
  return footprints;
}

const ResultRow* sweep_row(const std::vector<ResultRow>& rows, const SweepSeries& s, const std::string& scene, double footprint_mm) {
  for (const ResultRow& r : rows) {
    if (r.sweep && r.scene == scene && r.footprint_mm == footprint_mm && r.method == s.method && r.taps == s.taps &&
        r.follow_surface == s.follow_surface) {
      return &r;
    }
  }
  return nullptr;
}

BandSummary band_summary(const std::vector<ResultRow>& rows, const SweepSeries& s, const FootprintBand& band) {
  std::vector<double> misses, ratios;
  BandSummary b;
  for (const ResultRow& r : rows) {
    if (!r.sweep || r.method != s.method || r.taps != s.taps || r.follow_surface != s.follow_surface) continue;
    if (r.footprint_mm < band.lo || r.footprint_mm >= band.hi || std::isnan(r.interior().miss)) continue;
    misses.push_back(r.interior().miss);
    ratios.push_back(r.time_ratio_to_copy);
    b.worst_miss = std::max(b.worst_miss, r.interior().miss);
    for (double c : r.interior().miss_channel) b.worst_channel = std::max(b.worst_channel, c);
  }
  b.count = static_cast<int>(misses.size());
  b.median_miss = median(misses);
  b.median_time_ratio = median(ratios);
  return b;
}

double median_miss_at(const std::vector<ResultRow>& rows, const SweepSeries& s, double footprint_mm) {
  std::vector<double> misses;
  for (const std::string& scene : sweep_scenes(rows)) {
    const ResultRow* r = sweep_row(rows, s, scene, footprint_mm);
    if (r != nullptr && !std::isnan(r->interior().miss)) misses.push_back(r->interior().miss);
  }
  return misses.empty() ? std::numeric_limits<double>::quiet_NaN() : median(misses);
}

}  // namespace sss_bench
