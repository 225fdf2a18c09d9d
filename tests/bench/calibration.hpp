// The default eq. (1) kernel's calibration against the footprint sweep (issue "Physically right by
// default"): the sweep's scenes and footprints (sweep_geometry.hpp), each filtered by the CPU model
// of the passes (module/src/math/cpu_separable_filter.hpp) and scored by the instrument's interior
// miss (metrics.hpp) against the exact plane reference. sss_fit_default (fit_default_main.cpp) fits
// with it; the test bench.default_kernel_fit re-scores the committed fit with it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "math/cpu_separable_filter.hpp"
#include "math/filter_constants.hpp"
#include "math/pass_kernel.hpp"
#include "metrics.hpp"
#include "regions.hpp"
#include "scene.hpp"

namespace sss_bench {

struct CalibrationCase {
  std::string scene;
  double footprint_mm = 0.0;
  int width = 0, height = 0;
  std::vector<float> input_rgba;    // the irradiance as the passes read it (RGBA16F)
  std::vector<float> window_depth;
  std::array<float, 16> projection{};
  float world_units_per_mm = 0.001f;
  RgbImage input, reference;
  std::vector<uint8_t> interior;    // the instrument's interior region
};

// The exact result on a sweep plane (scene.footprint_mm > 0) for the irradiance the passes read
// (irradiance_half: RGBA, the scene's irradiance as RGBA16F holds it): RGB per pixel, double.
std::vector<double> exact_plane_rgb(const Scene& scene, const float* irradiance_half);

// What the regions of regions.hpp need of a scene, with the profile's reach.
RegionInput region_input_of(const Scene& scene, double reach_mm);

// The interior the calibration's frames hold at least (the benchmark's default --sweep-interior).
inline constexpr int kCalibrationInteriorPx = 64;

// Every sweep scene (or those named in `scenes`, when not empty) at every footprint (frames as the
// benchmark sizes them at `interior_px`).
std::vector<CalibrationCase> make_calibration_cases(const std::vector<double>& footprints, int interior_px,
                                                    const std::vector<std::string>& scenes = {});

struct CaseScore {
  std::string scene;
  double footprint_mm = 0.0;
  Miss miss;  // interior
};

// The CPU model of `settings` on every case (on all cores), scored.
// A case's per-frame constants for `settings` at the case's world units per mm, and its frame as
// the CPU models read it (the case's input colour and window depth).
sss::math::PassConstants case_constants(const sss::math::FilterSettings& settings, const sss::math::PassKernel& kernel,
                                        const CalibrationCase& c);
sss::math::CpuFilterImage case_image(const CalibrationCase& c);

std::vector<CaseScore> score_settings(const sss::math::FilterSettings& settings,
                                      const std::vector<CalibrationCase>& cases);

// What the fit minimises: the mean interior miss over the cases plus their 8-norm (a smooth stand-in
// for the largest, which a derivative-free optimiser handles better), plus kChannelPenalty times
// every channel's excess over kChannelLimit (a channel left worse than doing nothing is what the
// instrument calls inaccurate, whatever the pooled miss).
inline constexpr double kChannelLimit = 0.9;
inline constexpr double kChannelPenalty = 4.0;
double calibration_objective(const std::vector<CaseScore>& scores);

}  // namespace sss_bench
