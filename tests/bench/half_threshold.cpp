#include "half_threshold.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "math/cpu_half_resolution.hpp"
#include "math/cpu_separable_filter.hpp"
#include "math/half_resolution.hpp"
#include "math/pass_kernel.hpp"

namespace sss_bench {

double half_threshold_reach_mm(const sss::math::FilterSettings& settings) {
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  const auto& term = kernel.terms.front();
  return std::min(term.horizontal.footprint.reach_mm, term.vertical.footprint.reach_mm);
}

std::vector<double> half_threshold_footprints(const sss::math::FilterSettings& settings) {
  std::vector<double> footprints;
  for (int k = 0; k <= 12; ++k) footprints.push_back(0.05 * std::pow(40.0, k / 12.0));
  const double reach_mm = half_threshold_reach_mm(settings);
  for (float t : half_threshold_candidates()) {
    // 0.2 % above T: the model's reach (pixels per mm from the projection, in float) stays >= T.
    const double f = t > 0.0f ? reach_mm / (1.002 * t) : 0.0;
    if (f >= footprints.front() && f <= footprints[12]) footprints.push_back(f);
  }
  std::sort(footprints.begin(), footprints.end());
  return footprints;
}

namespace {

void score_case(const sss::math::FilterSettings& settings, const sss::math::PassKernel& kernel,
                const CalibrationCase& c, const std::vector<float>& thresholds, HalfCaseScore* out) {
  const sss::math::PassConstants constants = case_constants(settings, kernel, c);
  const sss::math::CpuFilterImage image = case_image(c);
  std::vector<float> result(c.input_rgba.size());
  auto score = [&] { return miss_share(RgbImage::from_rgba(result.data(), c.width, c.height), c.reference, c.input, c.interior.data()); };
  out->scene = c.scene;
  out->footprint_mm = c.footprint_mm;
  const auto& term = kernel.terms.front();
  // As the path computes it (cpu_half_resolution.cpp), at the frame's centre (a sweep plane's
  // reach is the same everywhere).
  const std::size_t centre = static_cast<std::size_t>(c.height / 2) * static_cast<std::size_t>(c.width) + static_cast<std::size_t>(c.width / 2);
  const double step = std::min(c.input_rgba[centre * 4 + 3], 1.0f) /
                      static_cast<double>(sss::math::clip_w(constants, sss::math::linearise_depth(constants, c.window_depth[centre])));
  out->reach_px = std::min(term.horizontal.footprint.reach_mm * constants.pixels_per_mm[0],
                           term.vertical.footprint.reach_mm * constants.pixels_per_mm[1]) * step;
  sss::math::cpu_pass_kernel_filter(kernel, constants, image, result.data());
  out->full = score();
  for (float t : thresholds) {
    sss::math::CpuHalfResolutionStats stats;
    sss::math::cpu_half_resolution_filter({&kernel}, {constants}, nullptr, image, t, result.data(), &stats);
    out->half.push_back(score());
    const long long translucent = stats.upsampled + stats.full_size;
    out->upsampled_share.push_back(translucent > 0 ? static_cast<double>(stats.upsampled) / static_cast<double>(translucent) : 0.0);
  }
}

}  // namespace

std::vector<HalfCaseScore> score_half_resolution(const sss::math::FilterSettings& settings,
                                                 const std::vector<CalibrationCase>& cases,
                                                 const std::vector<float>& thresholds) {
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  std::vector<HalfCaseScore> scores(cases.size());
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      for (std::size_t i = t; i < cases.size(); i += threads) score_case(settings, kernel, cases[i], thresholds, &scores[i]);
    });
  }
  for (auto& th : pool) th.join();
  return scores;
}

bool half_keeps_margin(const Miss& full, const Miss& half) {
  if (!(half.pooled <= full.pooled + sss::math::kHalfResolutionMissMargin)) return false;
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(half.channel[c] <= std::max(1.0, full.channel[c]))) return false;
  }
  return true;
}

int smallest_passing_threshold(const std::vector<HalfCaseScore>& scores, std::size_t threshold_count) {
  for (std::size_t k = 0; k < threshold_count; ++k) {
    if (std::all_of(scores.begin(), scores.end(), [&](const HalfCaseScore& s) { return half_keeps_margin(s.full, s.half[k]); })) {
      return static_cast<int>(k);
    }
  }
  return -1;
}

}  // namespace sss_bench
