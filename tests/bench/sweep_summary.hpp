// The footprint sweep's rows summarised: per method configuration, its interior miss across the
// footprints and scenes, and per footprint band the medians the Pareto plots and tables show.
#pragma once

#include <string>
#include <vector>

#include "results.hpp"

namespace sss_bench {

// Footprint bands of the sweep (millimetres per pixel, [lo, hi)).
struct FootprintBand {
  std::string name;  // "fine", "medium", "coarse"
  double lo = 0.0, hi = 0.0;
  std::string what;  // "4K close-ups", ...
};
const std::vector<FootprintBand>& footprint_bands();

// One method configuration of the sweep (a curve in the plots).
struct SweepSeries {
  std::string label;  // method_label of its rows
  std::string method;
  int taps = 0;
  bool follow_surface = false;
};
// The configurations with sweep rows, in the order they first appear.
std::vector<SweepSeries> sweep_series(const std::vector<ResultRow>& rows);
// The sweep's scene names and footprints, in order of appearance / ascending.
std::vector<std::string> sweep_scenes(const std::vector<ResultRow>& rows);
std::vector<double> sweep_footprints(const std::vector<ResultRow>& rows);

// The sweep row of a configuration on one scene at one footprint, or nullptr.
const ResultRow* sweep_row(const std::vector<ResultRow>& rows, const SweepSeries& s, const std::string& scene, double footprint_mm);

struct BandSummary {
  int count = 0;                  // rows (scenes × footprints) in the band
  double median_miss = 0.0;       // interior, pooled
  double worst_miss = 0.0;        // the largest pooled interior miss
  double worst_channel = 0.0;     // the largest per-channel interior miss
  double median_time_ratio = 0.0; // × copy
};
BandSummary band_summary(const std::vector<ResultRow>& rows, const SweepSeries& s, const FootprintBand& band);

// The median of the pooled interior miss over the sweep's scenes at one footprint (NaN when none).
double median_miss_at(const std::vector<ResultRow>& rows, const SweepSeries& s, double footprint_mm);

}  // namespace sss_bench
