// The half-resolution path's threshold (module/src/math/half_resolution.hpp,
// kHalfResolutionMinReachPixels) measured on the footprint sweep (calibration.hpp): every sweep
// case filtered by the CPU model of the full-size passes and of the half path at candidate
// thresholds, scored by interior miss against the exact plane reference. sss_fit_half_threshold
// (fit_half_threshold_main.cpp, scripts/fit-half-threshold.sh) picks the threshold with it;
// bench.half_threshold re-checks the pick on a few cases.
#pragma once

#include <string>
#include <vector>

#include "calibration.hpp"

namespace sss_bench {

// The thresholds tried (full-size pixels of kernel reach on both axes). 0: every translucent pixel
// with a half-size neighbour on its surface is upsampled.
// Up to 16 the steps a threshold is usually set in; 24 to 64 for kernels the half-size passes only
// serve when they are wide (the close-ups).
inline const std::vector<float>& half_threshold_candidates() {
  static const std::vector<float> candidates = {0.0f, 2.0f, 3.0f, 4.0f, 6.0f, 8.0f, 12.0f, 16.0f, 24.0f, 32.0f, 48.0f, 64.0f};
  return candidates;
}

// The smaller reach (mm) of the one-term kernel `settings` builds, the horizontal or the vertical
// pass's: on a sweep plane at footprint f its reach in pixels is this / f.
double half_threshold_reach_mm(const sss::math::FilterSettings& settings);

// The footprints the threshold is chosen on: the sweep's range (0.05 to 2 mm per pixel) at twice
// the benchmark's density, and for each candidate T the footprint where the kernel reaches just
// above T pixels (the narrowest kernel T hands to the upsample: where it misses most), where that
// lies in the range. Sorted.
std::vector<double> half_threshold_footprints(const sss::math::FilterSettings& settings);

struct HalfCaseScore {
  std::string scene;
  double footprint_mm = 0.0;
  double reach_px = 0.0;  // the kernel's smaller reach on the plane, full-size pixels
  Miss full;              // the full-size passes (cpu_pass_kernel_filter)
  std::vector<Miss> half;                // per candidate: cpu_half_resolution_filter at that threshold
  std::vector<double> upsampled_share;   // per candidate: upsampled / translucent pixels
};

// `thresholds`: the candidates to score (half_threshold_candidates() or a subset). On all cores.
std::vector<HalfCaseScore> score_half_resolution(const sss::math::FilterSettings& settings,
                                                 const std::vector<CalibrationCase>& cases,
                                                 const std::vector<float>& thresholds);

// The criterion: the half path's pooled interior miss within kHalfResolutionMissMargin of the
// full-size passes', and no channel worse than doing nothing (miss above 1) where the full-size
// passes' is not already (the eq. (1) kernel's blue is, at some coarse footprints: the half path
// leaves those frames to the full-size passes, so at every threshold its miss there is theirs).
bool half_keeps_margin(const Miss& full, const Miss& half);

// The index of the smallest threshold at which every case keeps the margin; -1 where none does.
int smallest_passing_threshold(const std::vector<HalfCaseScore>& scores, std::size_t threshold_count);

}  // namespace sss_bench
