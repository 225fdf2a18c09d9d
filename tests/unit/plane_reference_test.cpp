// The fronto-parallel plane reference (module/src/math/plane_reference.hpp): its 1D weights, and the
// whole convolution against the brute-force 2D surface convolution (exact_reference.hpp) on a
// small plane, where both must give the same numbers. The same for the turned plane under an
// orthographic camera (convolve_turned_plane): against the facing plane's where it does not turn,
// against the 2D reference where it does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
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

// Light with every frequency the filter meets, on a width x height frame: a step, a bright spot and
// a per-pixel pattern, different per channel.
std::vector<float> irregular_light(int width, int height) {
  std::vector<float> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const float step = x + y < (width + height) / 2 ? 1.0f : 0.02f;
      const float spot = (x - width / 3) * (x - width / 3) + (y - height / 2) * (y - height / 2) <= 2 ? 4.0f : 0.0f;
      const float pattern = 0.1f * static_cast<float>((x * 7 + y * 13) % 5);
      rgba[i * 4 + 0] = step + spot + pattern;
      rgba[i * 4 + 1] = 0.5f * step + spot;
      rgba[i * 4 + 2] = 0.25f * step + pattern;
      rgba[i * 4 + 3] = 1.0f;
    }
  }
  return rgba;
}

// The largest |x - y| / |y| over two images of the same size.
double largest_relative_difference(const std::vector<double>& x, const std::vector<double>& y) {
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::fabs(x[i] - y[i]) / std::fabs(y[i]));
  return worst;
}

// Not turned (c = 0), the turned plane's 2D sum is the facing plane's two 1D passes: the same pixel
// integrals, skipped by the same rule, summed in another order. Pixels wider than tall, so that a
// swap of a and b would show.
TEST(TurnedPlaneReference, WithoutShiftEqualsTheFrontoParallelPlane) {
  const int width = 40, height = 30;
  const std::vector<float> rgba = irregular_light(width, height);
  const GaussianProfile profile = sss::math::skin_profile_terms();
  const sss::math::PlaneInput facing{width, height, rgba.data(), 0.4, 0.25};
  std::vector<double> expected(static_cast<std::size_t>(width) * height * 3);
  sss::math::convolve_fronto_parallel_plane(facing, profile, expected.data());
  sss::math::TurnedPlaneInput turned;
  turned.width = width;
  turned.height = height;
  turned.irradiance = rgba.data();
  turned.footprint = {0.4, 0.25, 0.0};
  std::vector<double> result(expected.size());
  sss::math::convolve_turned_plane(turned, profile, {0, 0, width, height}, result.data());
  EXPECT_LT(largest_relative_difference(result, expected), 1e-12);
}

// Only the receivers of the region are written, and they do not depend on the thread count.
TEST(TurnedPlaneReference, WritesTheRegionOnlyWithAnyThreadCount) {
  const int width = 30, height = 24;
  const std::vector<float> rgba = irregular_light(width, height);
  sss::math::TurnedPlaneInput turned;
  turned.width = width;
  turned.height = height;
  turned.irradiance = rgba.data();
  turned.footprint = {0.5, 0.9, -0.35};
  const sss::math::PixelRegion region{5, 7, 13, 9};
  std::vector<double> one(static_cast<std::size_t>(width) * height * 3, -1.0), three(one);
  sss::math::convolve_turned_plane(turned, sss::math::skin_profile_terms(), region, one.data(), 1);
  sss::math::convolve_turned_plane(turned, sss::math::skin_profile_terms(), region, three.data(), 3);
  EXPECT_EQ(one, three);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool inside = x >= region.x && x < region.x + region.width && y >= region.y && y < region.y + region.height;
      const double v = one[(static_cast<std::size_t>(y) * width + x) * 3];
      EXPECT_EQ(v == -1.0, !inside) << x << ", " << y;
    }
  }
}

// The footprint from the projection and the plane: under an orthographic camera with p mm pixels, a
// plane turned by t about the screen's x axis has a = p, b = p / cos t, c = 0; about y, a = p / cos t,
// b = p, c = 0; about the diagonal the rows shift (c != 0) and the area is still p² / cos t.
TEST(TurnedPlaneReference, FootprintFromTheProjectionAndThePlane) {
  const double pixel = 0.3, t = 60.0 * kPi / 180.0;
  const int width = 24, height = 20;
  const sss::math::Matrix4 m = sss_test::orthographic_matrix(static_cast<float>(0.5 * pixel * width),
                                                             static_cast<float>(0.5 * pixel * height), 1.0f, 200.0f);
  // The float matrix's pixel sides.
  const double px = 2.0 / (static_cast<double>(m[0]) * width), py = 2.0 / (static_cast<double>(m[5]) * height);
  const sss::math::Vec3 point{0.0, 0.0, -100.0};
  const auto footprint = [&](sss::math::Vec3 n) {
    return sss::math::turned_plane_footprint(m, width, height, point, n, 1.0, 3, 4);
  };
  const auto about_x = footprint({0.0, -std::sin(t), std::cos(t)});
  EXPECT_NEAR(about_x.a_mm, px, 1e-12);
  EXPECT_NEAR(about_x.b_mm, py / std::cos(t), 1e-12);
  EXPECT_NEAR(about_x.c_mm, 0.0, 1e-12);
  const auto about_y = footprint({std::sin(t), 0.0, std::cos(t)});
  EXPECT_NEAR(about_y.a_mm, px / std::cos(t), 1e-12);
  EXPECT_NEAR(about_y.b_mm, py, 1e-12);
  EXPECT_NEAR(about_y.c_mm, 0.0, 1e-12);
  const double r = std::sqrt(0.5);
  const auto diagonal = footprint({std::sin(t) * r, -std::sin(t) * r, std::cos(t)});
  EXPECT_GT(std::fabs(diagonal.c_mm), 0.1 * px);
  EXPECT_NEAR(diagonal.a_mm * diagonal.b_mm, px * py / std::cos(t), 1e-12);
  EXPECT_THROW(footprint({1.0, 0.0, 0.0}), std::invalid_argument);  // edge-on: the rays miss it
}

// The check for turned planes: small orthographic planes turned 30, 60 and 75 degrees about
// the screen's x axis, its y axis and a diagonal, their depth exact (distance_f64), irregular light:
// the closed form equals the 2D surface convolution with central differences (which on such a
// plane are exact, surface.hpp) at every pixel, frame border included (both take the plane to end
// there). The 2D reference truncates each term where 1e-15 of its mass is left.
TEST(TurnedPlaneReference, EqualsTheBruteForce2dReference) {
  const int width = 24, height = 20;
  const double pixel = 0.3, distance = 100.0;
  const sss::math::Matrix4 m = sss_test::orthographic_matrix(static_cast<float>(0.5 * pixel * width),
                                                             static_cast<float>(0.5 * pixel * height), 1.0f, 400.0f);
  const std::size_t n = static_cast<std::size_t>(width) * height;
  const std::vector<float> rgba = irregular_light(width, height);
  const GaussianProfile profile = sss::math::skin_profile_terms();
  sss::math::ExactOptions options;
  options.tail_mass = 1e-15;
  double worst = 0.0;
  for (double axis_degrees : {0.0, 90.0, 45.0}) {
    for (double turn_degrees : {30.0, 60.0, 75.0}) {
      SCOPED_TRACE("turned " + std::to_string(turn_degrees) + " about " + std::to_string(axis_degrees));
      // The normal (0, 0, 1) turned about the screen axis at axis_degrees from x.
      const double t = turn_degrees * kPi / 180.0, a = axis_degrees * kPi / 180.0;
      const sss::math::Vec3 normal{std::sin(t) * std::sin(a), -std::sin(t) * std::cos(a), std::cos(t)};
      const sss::math::Vec3 point{0.0, 0.0, -distance};
      std::vector<double> depth(n);
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          // An orthographic ray keeps its x and y: the plane's depth there.
          const sss::math::Vec3 at = sss::math::pixel_position(m, width, height, x, y, distance);
          depth[static_cast<std::size_t>(y) * width + x] = distance + (normal.x * at.x + normal.y * at.y) / normal.z;
        }
      }
      sss::math::ExactInput in;
      in.width = width;
      in.height = height;
      in.irradiance = rgba.data();
      in.distance_f64 = depth.data();
      in.projection = m;
      in.world_units_per_mm = 1.0;
      std::vector<double> brute(n * 3);
      sss::math::exact_surface_convolution(in, profile, {0, 0, width, height}, brute.data(), options);
      sss::math::TurnedPlaneInput turned;
      turned.width = width;
      turned.height = height;
      turned.irradiance = rgba.data();
      turned.footprint = sss::math::turned_plane_footprint(m, width, height, point, normal, 1.0, width / 2, height / 2);
      std::vector<double> closed(n * 3);
      sss::math::convolve_turned_plane(turned, profile, {0, 0, width, height}, closed.data());
      const double difference = largest_relative_difference(closed, brute);
      EXPECT_LT(difference, 1e-9);
      worst = std::max(worst, difference);
    }
  }
  std::printf("largest relative difference to the 2D reference on the turned planes: %.3g\n", worst);
}

TEST(TurnedPlaneReference, RefusesBadArguments) {
  const std::vector<float> rgba(16 * 4, 1.0f);
  std::vector<double> out(16 * 3);
  sss::math::TurnedPlaneInput in;
  in.width = in.height = 4;
  in.irradiance = rgba.data();
  in.footprint = {0.5, 0.5, 0.1};
  const GaussianProfile profile = sss::math::skin_profile_terms();
  EXPECT_NO_THROW(sss::math::convolve_turned_plane(in, profile, {0, 0, 4, 4}, out.data()));
  EXPECT_THROW(sss::math::convolve_turned_plane(in, profile, {1, 0, 4, 4}, out.data()), std::invalid_argument);
  in.footprint.b_mm = 0.0;
  EXPECT_THROW(sss::math::convolve_turned_plane(in, profile, {0, 0, 4, 4}, out.data()), std::invalid_argument);
  in.footprint = {0.5, 0.5, std::nan("")};
  EXPECT_THROW(sss::math::convolve_turned_plane(in, profile, {0, 0, 4, 4}, out.data()), std::invalid_argument);
  EXPECT_THROW(sss::math::turned_plane_footprint({1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}), std::invalid_argument);
}

}  // namespace
