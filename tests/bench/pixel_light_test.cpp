// bench.whole_surface (with whole_surface_test.cpp): the pixel-consistent light of pixel_light.hpp
// on a frame of a plane facing the camera, whose pixels hold a quadratic of their coordinates:
//   - between translucent pixels Catmull-Rom gives the quadratic back (bilinear is off by t(1 - t)
//     of the second difference, which would widen every term of the reference by a sixth of a pixel²);
//   - where one of the sixteen pixels is not translucent it falls back to bilinear over the four;
//   - a point behind the surface the frame shows is not visible.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "pixel_light.hpp"

namespace {

using sss_bench::Point3;

constexpr int kSize = 16;
constexpr double kDistance = 1.0;  // the plane z = -1 in view space; the camera is the identity view

// Channel c is the quadratic times this: three distinct channels.
double channel_scale(std::size_t c) { return 1.0 + 0.5 * static_cast<double>(c); }

// The light of pixel (x, y): a quadratic with a cross term, and a second difference of 0.04 along x.
double quadratic(double x, double y) { return 0.5 + 0.01 * x - 0.02 * y + 0.02 * x * x + 0.003 * x * y + 0.01 * y * y; }

sss_bench::Scene plane_frame() {
  sss_bench::Scene s;
  s.width = s.height = kSize;
  s.projection = {};
  s.projection[0] = s.projection[5] = 1.0f;  // 90 degrees; only [0] and [5] place a point on the screen
  s.world_units_per_mm = 0.001f;
  const std::size_t n = static_cast<std::size_t>(kSize * kSize);
  s.irradiance.assign(n * 4, 1.0f);
  s.distance.assign(n, static_cast<float>(kDistance));
  s.mask.assign(n, 1);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kSize + x);
      for (std::size_t c = 0; c < 3; ++c) s.irradiance[i * 4 + c] = static_cast<float>(quadratic(x, y) * channel_scale(c));
    }
  }
  return s;
}

// The world point of the plane that projects to pixel coordinates (fx, fy) (pixel centres whole).
Point3 at_pixel(double fx, double fy) {
  const double ndc_x = (fx + 0.5) / kSize * 2.0 - 1.0, ndc_y = (fy + 0.5) / kSize * 2.0 - 1.0;
  return {ndc_x * kDistance, ndc_y * kDistance, -kDistance};
}

double bilinear(double fx, double fy) {
  const double x0 = std::floor(fx), y0 = std::floor(fy), tx = fx - x0, ty = fy - y0;
  return (1 - tx) * (1 - ty) * quadratic(x0, y0) + tx * (1 - ty) * quadratic(x0 + 1, y0) +
         (1 - tx) * ty * quadratic(x0, y0 + 1) + tx * ty * quadratic(x0 + 1, y0 + 1);
}

const sss_bench::detail::Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

TEST(PixelLight, CatmullRomGivesAQuadraticBackBetweenPixelCentres) {
  const sss_bench::Scene s = plane_frame();
  double worst = 0.0, worst_bilinear = 0.0;
  for (double fy = 3.0; fy < 12.0; fy += 0.37) {
    for (double fx = 3.0; fx < 12.0; fx += 0.29) {
      const sss_bench::PixelLight p = sss_bench::light_from_pixels(s, kIdentity, at_pixel(fx, fy));
      ASSERT_TRUE(p.visible) << fx << ", " << fy;
      for (std::size_t c = 0; c < 3; ++c) {
        const double expected = quadratic(fx, fy) * channel_scale(c);
        worst = std::fmax(worst, std::fabs(p.light[c] - expected));
        worst_bilinear = std::fmax(worst_bilinear, std::fabs(bilinear(fx, fy) * channel_scale(c) - expected));
      }
    }
  }
  std::printf("quadratic light: Catmull-Rom worst error %.2e, bilinear's %.2e\n", worst, worst_bilinear);
  // Float storage of values near 1: a few 1e-7; bilinear is off by up to a quarter of 0.04 x 2.
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(worst_bilinear, 5e-3);
}

TEST(PixelLight, NextToAPixelOffTheSurfaceItIsBilinearOverTheFour) {
  sss_bench::Scene s = plane_frame();
  s.mask[static_cast<std::size_t>(5 * kSize + 5)] = 0;  // one of the sixteen round (6.4, 6.7), not of its four
  const double fx = 6.4, fy = 6.7;
  const sss_bench::PixelLight p = sss_bench::light_from_pixels(s, kIdentity, at_pixel(fx, fy));
  ASSERT_TRUE(p.visible);
  EXPECT_NEAR(p.light[0], bilinear(fx, fy), 1e-6);
  EXPECT_GT(std::fabs(bilinear(fx, fy) - quadratic(fx, fy)), 1e-3);  // so the two rules differ here
}

TEST(PixelLight, APointBehindTheSurfaceIsNotVisible) {
  const sss_bench::Scene s = plane_frame();
  Point3 p = at_pixel(7.2, 7.6);
  // A millimetre behind the plane along the ray: past the quarter millimetre the tolerance allows.
  const double scale = (kDistance + 0.001) / kDistance;
  p = {p[0] * scale, p[1] * scale, p[2] * scale};
  EXPECT_FALSE(sss_bench::light_from_pixels(s, kIdentity, p).visible);
  const double nearer = (kDistance + 0.0002) / kDistance;
  const Point3 q = at_pixel(7.2, 7.6);
  EXPECT_TRUE(sss_bench::light_from_pixels(s, kIdentity, {q[0] * nearer, q[1] * nearer, q[2] * nearer}).visible);
}

}  // namespace
