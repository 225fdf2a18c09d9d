// The fronto-parallel plane reference (module/src/math/plane_reference.hpp): its 1D weights, and the
// whole convolution against the brute-force 2D surface convolution (exact_reference.hpp) on a
// small plane, where both must give the same numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "math/exact_reference.hpp"
#include "math/plane_reference.hpp"
#include "math/surface.hpp"
#include "synthetic_scene.hpp"

namespace {

using sss::math::GaussianProfile;

constexpr double kPi = 3.14159265358979323846;

TEST(PixelIntegratedGaussian, SumsToOneAndIsSymmetric) {
  for (double variance : {0.0064, 0.187, 7.41}) {
    for (double pixel : {0.05, 0.3, 2.0}) {
      const auto k = sss::math::pixel_integrated_gaussian(variance, pixel, 4000);
      const double sum = std::accumulate(k.begin(), k.end(), 0.0);
      EXPECT_NEAR(sum, 1.0, 1e-14) << variance << " mm², " << pixel << " mm";
      for (std::size_t i = 0; i < k.size(); ++i) EXPECT_EQ(k[i], k[k.size() - 1 - i]);
    }
  }
}

// The weight of a pixel equals the integral of the 1D Gaussian over it, taken independently by
// the midpoint rule on 20000 panels per pixel: its error is h²/24 · (f'(b) - f'(a)) with h = 2e-5 mm
// and |f'| <= 1 / (v √(2π e)) = 0.48, so at most 1.6e-11.
TEST(PixelIntegratedGaussian, EqualsTheIntegralOverEachPixel) {
  const double variance = 0.5, pixel = 0.4;
  const auto k = sss::math::pixel_integrated_gaussian(variance, pixel, 6);
  for (int d = -6; d <= 6; ++d) {
    const int panels = 20000;
    double sum = 0.0;
    for (int i = 0; i < panels; ++i) {
      const double x = (d - 0.5 + (i + 0.5) / panels) * pixel;
      sum += std::exp(-x * x / (2.0 * variance)) / std::sqrt(2.0 * kPi * variance);
    }
    EXPECT_NEAR(k[static_cast<std::size_t>(d + 6)], sum * pixel / panels, 2e-11) << d;
  }
}

// Far tails keep relative precision (erfc on the far side, not 1 - 1).
TEST(PixelIntegratedGaussian, FarTailsAreNotRoundedToZero) {
  const auto k = sss::math::pixel_integrated_gaussian(1.0, 1.0, 10);
  // d = 10: ½ erfc(9.5/√2) - ½ erfc(10.5/√2), both ~1e-21.
  const double expected = 0.5 * (std::erfc(9.5 / std::sqrt(2.0)) - std::erfc(10.5 / std::sqrt(2.0)));
  EXPECT_GT(k[20], 0.0);
  EXPECT_NEAR(k[20] / expected, 1.0, 1e-12);
}

TEST(PixelIntegratedGaussian, RefusesBadArguments) {
  EXPECT_THROW(sss::math::pixel_integrated_gaussian(0.0, 1.0, 3), std::invalid_argument);
  EXPECT_THROW(sss::math::pixel_integrated_gaussian(1.0, -1.0, 3), std::invalid_argument);
  EXPECT_THROW(sss::math::pixel_integrated_gaussian(1.0, 1.0, -1), std::invalid_argument);
}

// The check: on a small fronto-parallel plane (a perspective camera, 0.3 mm pixels at
// 250 mm, irregular light) the separable reference equals the brute-force 2D surface convolution to
// 1e-9 at every pixel and channel, frame border included (both take the plane to end there). The 2D
// reference truncates each term where 1e-15 of its mass is left and sums positions computed from
// the projection, so the two differ by rounding alone.
TEST(PlaneReference, EqualsTheBruteForce2dReference) {
  const int width = 23, height = 17;
  const double pixel_mm = 0.3, distance_mm = 250.0;
  const double fovy = 2.0 * std::atan(0.5 * pixel_mm * height / distance_mm) * 180.0 / kPi;
  const sss::math::Matrix4 m = sss_test::perspective_matrix(static_cast<float>(fovy),
                                                             static_cast<float>(width) / static_cast<float>(height), 1.0f, 1e4f);
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<float> rgba(n * 4);
  std::vector<double> distance(n, distance_mm);
  for (std::size_t i = 0; i < n; ++i) {
    // A bright spot, a step and a per-pixel pattern: every frequency the filter meets.
    const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
    const float step = x < 9 ? 1.0f : 0.02f;
    const float spot = (x - 15) * (x - 15) + (y - 8) * (y - 8) <= 2 ? 4.0f : 0.0f;
    const float pattern = 0.1f * static_cast<float>((x * 7 + y * 13) % 5);
    rgba[i * 4 + 0] = step + spot + pattern;
    rgba[i * 4 + 1] = 0.5f * step + spot;
    rgba[i * 4 + 2] = 0.25f * step + pattern;
    rgba[i * 4 + 3] = 1.0f;
  }
  sss::math::ExactInput in;
  in.width = width;
  in.height = height;
  in.irradiance = rgba.data();
  in.distance_f64 = distance.data();
  in.projection = m;
  in.world_units_per_mm = 1.0;
  const GaussianProfile profile = sss::math::skin_profile_terms();
  sss::math::PlaneInput plane;
  plane.width = width;
  plane.height = height;
  plane.irradiance = rgba.data();
  plane.pixel_x_mm = sss::math::plane_pixel_mm_x(m, width, distance_mm, 1.0);
  plane.pixel_y_mm = sss::math::plane_pixel_mm_y(m, height, distance_mm, 1.0);
  EXPECT_NEAR(plane.pixel_x_mm, pixel_mm, 1e-5);  // the float projection rounds the field of view
  std::vector<double> separable(n * 3);
  sss::math::convolve_fronto_parallel_plane(plane, profile, separable.data());
  for (bool series : {true, false}) {
    sss::math::ExactOptions options;
    options.tail_mass = 1e-15;
    options.series = series;
    std::vector<double> brute(n * 3);
    sss::math::exact_surface_convolution(in, profile, {0, 0, width, height}, brute.data(), options);
    double worst = 0.0;
    for (std::size_t i = 0; i < n * 3; ++i) worst = std::max(worst, std::fabs(brute[i] - separable[i]));
    EXPECT_LT(worst, 1e-9) << (series ? "Hermite series" : "closed form");
    std::printf("largest difference to the 2D reference (%s): %.3g\n", series ? "series" : "closed form", worst);
  }
}

// Energy: a uniformly lit plane keeps its value where the profile stays inside the frame, and loses
// what crosses the frame edge at its corners.
TEST(PlaneReference, UniformLightStaysUniformInsideAndIsLostPastTheFrame) {
  // 0.5 mm pixels: the centre is 50 mm from every edge, where the widest term (σ = 2.7 mm) has no
  // mass left in double precision.
  const int width = 200, height = 200;
  std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4, 1.0f);
  sss::math::PlaneInput plane{width, height, rgba.data(), 0.5, 0.5};
  std::vector<double> out(static_cast<std::size_t>(width) * height * 3);
  sss::math::convolve_fronto_parallel_plane(plane, sss::math::skin_profile_terms(), out.data());
  const std::size_t centre = (static_cast<std::size_t>(100) * width + 100) * 3;
  for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(out[centre + c], 1.0, 1e-12);
  // The corner pixel keeps the terms narrower than its pixel almost whole and about a quarter of
  // the wide ones (half of each 1D marginal per axis).
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_LT(out[c], 0.95) << c;
    EXPECT_GT(out[c], 0.25) << c;
  }
}

}  // namespace
