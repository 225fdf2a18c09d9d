#include "calibration.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "math/cpu_separable_filter.hpp"
#include "math/exact_reference.hpp"
#include "math/half_float.hpp"
#include "math/pass_kernel.hpp"
#include "math/plane_reference.hpp"
#include "regions.hpp"
#include "scenes.hpp"
#include "sweep_geometry.hpp"

namespace sss_bench {

std::vector<double> exact_plane_rgb(const Scene& scene, const float* irradiance_half) {
  sss::math::PlaneInput plane;
  plane.width = scene.width;
  plane.height = scene.height;
  plane.irradiance = irradiance_half;
  plane.pixel_x_mm = sss::math::plane_pixel_mm_x(scene.projection, scene.width, scene.distance[0], scene.world_units_per_mm);
  plane.pixel_y_mm = sss::math::plane_pixel_mm_y(scene.projection, scene.height, scene.distance[0], scene.world_units_per_mm);
  std::vector<double> rgb(static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height) * 3);
  sss::math::convolve_fronto_parallel_plane(plane, sss::math::skin_profile_terms(), rgb.data());
  return rgb;
}

RegionInput region_input_of(const Scene& scene, double reach_mm) {
  RegionInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.mask = scene.mask.data();
  in.distance = scene.distance.data();
  in.projection = scene.projection;
  in.world_units_per_mm = scene.world_units_per_mm;
  in.reach_mm = reach_mm;
  return in;
}

std::vector<CalibrationCase> make_calibration_cases(const std::vector<double>& footprints, int interior_px,
                                                    const std::vector<std::string>& scenes) {
  const double reach_mm = profile_reach_mm(sss::math::skin_profile_terms());
  std::vector<CalibrationCase> cases;
  for (const std::string& name : scenes.empty() ? footprint_scene_names() : scenes) {
    for (double f : footprints) {
      const int side = sweep_frame_side(f, interior_px, reach_mm);
      const Scene scene = make_footprint_scene(name, f, side, side);
      CalibrationCase c;
      c.scene = name;
      c.footprint_mm = f;
      c.width = scene.width;
      c.height = scene.height;
      c.input_rgba.resize(scene.irradiance.size());
      for (std::size_t i = 0; i < scene.irradiance.size(); ++i) c.input_rgba[i] = sss::math::round_to_half(scene.irradiance[i]);
      c.window_depth = scene.window_depth;
      c.projection = scene.projection;
      c.world_units_per_mm = scene.world_units_per_mm;
      c.input = RgbImage::from_rgba(c.input_rgba.data(), c.width, c.height);
      // The exact result, as the benchmark's plane reference computes it.
      const std::vector<double> rgb = exact_plane_rgb(scene, c.input_rgba.data());
      c.reference = RgbImage::from_rgb(rgb.data(), c.width, c.height);
      c.interior = region_mask(classify_regions(region_input_of(scene, reach_mm)), Region::interior);
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

sss::math::PassConstants case_constants(const sss::math::FilterSettings& settings, const sss::math::PassKernel& kernel,
                                        const CalibrationCase& c) {
  sss::math::FrameGeometry g;
  g.texture_width = c.width;
  g.texture_height = c.height;
  g.viewport = {0, 0, c.width, c.height};
  sss::math::FilterSettings s = settings;
  s.world_units_per_mm = c.world_units_per_mm;
  return sss::math::compute_pass_constants(s, c.projection, g, kernel.reach_mm);
}

sss::math::CpuFilterImage case_image(const CalibrationCase& c) {
  return sss::math::cpu_filter_image(c.width, c.height, c.input_rgba.data(), c.window_depth.data());
}

std::vector<CaseScore> score_settings(const sss::math::FilterSettings& settings,
                                      const std::vector<CalibrationCase>& cases) {
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  std::vector<CaseScore> scores(cases.size());
  auto score = [&](std::size_t i) {
    const CalibrationCase& c = cases[i];
    std::vector<float> out(c.input_rgba.size());
    sss::math::cpu_pass_kernel_filter(kernel, case_constants(settings, kernel, c), case_image(c), out.data());
    scores[i] = {c.scene, c.footprint_mm, miss_share(RgbImage::from_rgba(out.data(), c.width, c.height), c.reference,
                                                     c.input, c.interior.data())};
  };
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      for (std::size_t i = t; i < cases.size(); i += threads) score(i);
    });
  }
  for (auto& th : pool) th.join();
  return scores;
}

double calibration_objective(const std::vector<CaseScore>& scores) {
  double sum = 0.0, eighth = 0.0, excess = 0.0;
  for (const CaseScore& s : scores) {
    sum += s.miss.pooled;
    eighth += std::pow(s.miss.pooled, 8.0);
    for (double m : s.miss.channel) excess += std::max(0.0, m - kChannelLimit);
  }
  const double n = static_cast<double>(scores.size());
  return sum / n + std::pow(eighth / n, 1.0 / 8.0) + kChannelPenalty * excess;
}

}  // namespace sss_bench
