// The passes' walk over surfaces turned away from the camera (module/src/math/pass_surface.hpp) and
// the CPU model of the passes on turned planes against the exact 2D reference.
//
// On a plane the walk is exact: the horizontal pass steps |T_x| mm per pixel, the vertical one,
// sheared by -(T_x·T_y)/(T_x·T_x) columns per row, |T_t| = area / |T_x| mm per row, and every point
// of the plane lies on the tangent line of either pass (off-line distance 0). The expected values
// below come from the plane's own geometry in double (its metric G = J^T J of the map from window
// pixels to surface millimetres), not from the code under test.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "math/cpu_separable_filter.hpp"
#include "math/exact_reference.hpp"
#include "math/pass_kernel.hpp"
#include "math/pass_surface.hpp"
#include "metrics.hpp"
#include "regions.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

using sss::math::Float3;
using sss::math::Neighbour;
using sss::math::PassConstants;
using sss::math::PassGeometry;

constexpr double kPi = 3.14159265358979323846;
constexpr float kMetresPerMm = 0.001f;

// An orthographic camera whose facing pixel measures `pixel_mm` on a width x height frame.
sss::math::Matrix4 orthographic_for(int width, int height, double pixel_mm) {
  const float half_w = static_cast<float>(0.5 * width * pixel_mm * 1e-3);
  const float half_h = static_cast<float>(0.5 * height * pixel_mm * 1e-3);
  return orthographic_matrix(half_w, half_h, 0.01f, 10.0f);
}

PassConstants constants_for(const SyntheticScene& s, const sss::math::FilterSettings& settings,
                            const sss::math::PassKernel& kernel) {
  sss::math::FrameGeometry g;
  g.texture_width = s.width;
  g.texture_height = s.height;
  g.viewport = {0, 0, s.width, s.height};
  return sss::math::compute_pass_constants(settings, s.projection, g, kernel.reach_mm);
}

// The walk of the pass along `axis` at pixel (x, y) of `s`, from its distances, as the CPU model
// takes it.
PassGeometry walk_at(const SyntheticScene& s, const PassConstants& k, int axis, int x, int y) {
  const auto d = [&](int px, int py) { return s.distance[static_cast<std::size_t>(py) * s.width + px]; };
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  const std::array<float, 2> g = sss::math::ray_slope(k, cx, cy);
  const float d0 = d(x, y);
  const Float3 tx = sss::math::surface_tangent(k, g, 0, d0, Neighbour{d(x - 1, y), true}, Neighbour{d(x + 1, y), true});
  if (axis == 0) return sss::math::horizontal_geometry(k, g, d0, tx);
  const Float3 ty = sss::math::surface_tangent(k, g, 1, d0, Neighbour{d(x, y - 1), true}, Neighbour{d(x, y + 1), true});
  return sss::math::vertical_geometry(k, g, d0, tx, ty);
}

// The plane's metric in window pixels, from its turn about the axis at `axis_degrees` (orthographic,
// square facing pixels of side 1): along the axis a pixel is 1 facing pixel of surface, across it
// 1 / cos(turn).
struct Metric {
  double xx, xy, yy;
};
Metric plane_metric(double turn_degrees, double axis_degrees) {
  const double c = std::cos(turn_degrees * kPi / 180.0), a = axis_degrees * kPi / 180.0;
  const double along = 1.0, across = 1.0 / (c * c);  // squared lengths
  const double ca = std::cos(a), sa = std::sin(a);
  return {along * ca * ca + across * sa * sa, (along - across) * ca * sa, along * sa * sa + across * ca * ca};
}

TEST(PassSurface, OnAPlaneEachPassStepsItsOwnFootprintSheared) {
  const int w = 64, h = 64;
  const sss::math::FilterSettings settings;
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  for (const double turn : {0.0, 30.0, 60.0, 75.0}) {
    for (const double axis : {0.0, 30.0, 45.0, 90.0}) {
      SCOPED_TRACE("turn " + std::to_string(turn) + ", axis " + std::to_string(axis));
      const SyntheticScene s = make_turned_plane_scene(w, h, turn, axis, 0.5, orthographic_for(w, h, 0.2), 1);
      const PassConstants k = constants_for(s, settings, kernel);
      const Metric m = plane_metric(turn, axis);
      const PassGeometry across = walk_at(s, k, 0, 30, 33), up = walk_at(s, k, 1, 30, 33);
      // Horizontal: |T_x| = sqrt(G_xx) facing pixels; vertical: sheared by -G_xy / G_xx columns per
      // row, its step sqrt(det G / G_xx).
      EXPECT_NEAR(across.ratio, 1.0 / std::sqrt(m.xx), 2e-4);
      EXPECT_NEAR(up.shear, -m.xy / m.xx, 2e-4);
      EXPECT_NEAR(up.ratio, 1.0 / std::sqrt((m.xx * m.yy - m.xy * m.xy) / m.xx), 2e-4);
      EXPECT_EQ(across.shear, 0.0f);
    }
  }
}

TEST(PassSurface, EveryTapOfAPlaneLiesOnItsSurface) {
  // Perspective and orthographic, a plane turned 70 degrees: taps up to 20 steps away along either
  // pass's line (the vertical one's at the pixel nearest its sheared line) lie off the surface by
  // float rounding only (the raw depth difference there is 2.7 times the lateral distance).
  const int w = 96, h = 96;
  const sss::math::FilterSettings settings;
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  for (const bool perspective : {false, true}) {
    SCOPED_TRACE(perspective ? "perspective" : "orthographic");
    const sss::math::Matrix4 projection = perspective ? perspective_matrix(20.0f, 1.0f, 0.05f, 10.0f)
                                                      : orthographic_for(w, h, 0.2);
    const SyntheticScene s = make_turned_plane_scene(w, h, 70.0, 25.0, 0.5, projection, 2);
    const PassConstants k = constants_for(s, settings, kernel);
    const int x = 48, y = 48;
    const float d0 = s.distance[static_cast<std::size_t>(y) * w + x];
    for (int axis = 0; axis < 2; ++axis) {
      const PassGeometry walk = walk_at(s, k, axis, x, y);
      float worst = 0.0f, raw = 0.0f;
      for (int offset = -20; offset <= 20; ++offset) {
        const float o = static_cast<float>(offset);
        const int tx = static_cast<int>(static_cast<float>(x) + 0.5f + (axis == 0 ? o : walk.shear * o));
        const int ty = axis == 0 ? y : y + offset;
        const float d = s.distance[static_cast<std::size_t>(ty) * w + tx];
        // Factor 1 / (world units per mm): the distance off the line in millimetres.
        const float ox = static_cast<float>(tx - x), oy = static_cast<float>(ty - y);
        worst = std::max(worst, sss::math::off_surface_distance(k, walk, 1.0f / kMetresPerMm, o, ox, oy, d, d0, false));
        raw = std::max(raw, std::fabs(d - d0) / kMetresPerMm);
      }
      EXPECT_GT(raw, 1.0f) << "the plane's depth changes by millimetres along the line";
      EXPECT_LT(worst, 2e-3f) << "pass " << axis;
    }
  }
}

TEST(PassSurface, AStepIsAStepAndItsSideKeepsItsOwnSlope) {
  // A facing plane at 0.5 m with the neighbour on the + side 10 mm nearer: the tangent is the
  // - side's (the plane's), and the + neighbour lies 10 mm off the line.
  const int w = 8, h = 8;
  SyntheticScene s = make_turned_plane_scene(w, h, 0.0, 0.0, 0.5, orthographic_for(w, h, 0.2), 3);
  const sss::math::FilterSettings settings;
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  const PassConstants k = constants_for(s, settings, kernel);
  const std::array<float, 2> g = sss::math::ray_slope(k, 4.5f, 4.5f);
  const Float3 t = sss::math::surface_tangent(k, g, 0, 0.5f, Neighbour{0.5f, true}, Neighbour{0.49f, true});
  EXPECT_FLOAT_EQ(t.z, 0.0f) << "the step's side takes no share";
  const PassGeometry walk = sss::math::horizontal_geometry(k, g, 0.5f, t);
  EXPECT_NEAR(walk.ratio, 1.0f, 1e-5f);
  EXPECT_NEAR(sss::math::off_surface_distance(k, walk, 1.0f / kMetresPerMm, 1.0f, 1.0f, 0.0f, 0.49f, 0.5f, false), 10.0f,
              1e-3f);
  // With the slack of the follow-surface ramp: a quarter of the tap's distance along the line less.
  const float slack = sss::math::kFollowSurfaceSlack * 0.2f;
  EXPECT_NEAR(sss::math::off_surface_distance(k, walk, 1.0f / kMetresPerMm, 1.0f, 1.0f, 0.0f, 0.49f, 0.5f, true),
              10.0f - slack, 1e-3f);
  // Unequal but smooth sides (a bend of less than a facing pixel per pixel) keep the central difference.
  const Float3 central = sss::math::surface_tangent(k, g, 0, 0.5f, Neighbour{0.5f - 0.00005f, true},
                                                    Neighbour{0.5f + 0.00015f, true});
  EXPECT_NEAR(central.z, -0.0001f, 1e-7f);
}

// The interior miss of `result` against the exact 2D reference on `scene` (a plane), and the
// input's: the pixels farther from the frame's edge than the profile's reach.
sss_bench::Miss plane_miss(const SyntheticScene& scene, const std::vector<double>& distance_f64,
                           const std::vector<float>& result) {
  const double reach_mm = sss_bench::profile_reach_mm(sss::math::skin_profile_terms());
  sss::math::ExactInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.irradiance = scene.color.data();
  in.distance_f64 = distance_f64.data();
  in.projection = scene.projection;
  in.world_units_per_mm = kMetresPerMm;
  const double facing_mm = 2.0e3 / (static_cast<double>(scene.projection[0]) * scene.width);  // orthographic only
  const int border = static_cast<int>(std::ceil(reach_mm / facing_mm)) + 1;
  const sss::math::PixelRegion interior{border, border, scene.width - 2 * border, scene.height - 2 * border};
  std::vector<double> reference(static_cast<std::size_t>(scene.width) * scene.height * 3, 0.0);
  sss::math::exact_surface_convolution(in, sss::math::skin_profile_terms(), interior, reference.data());
  std::vector<uint8_t> mask(static_cast<std::size_t>(scene.width) * scene.height, 0);
  for (int y = interior.y; y < interior.y + interior.height; ++y) {
    for (int x = interior.x; x < interior.x + interior.width; ++x) mask[static_cast<std::size_t>(y) * scene.width + x] = 1;
  }
  const sss_bench::RgbImage ref = sss_bench::RgbImage::from_rgb(reference.data(), scene.width, scene.height);
  return sss_bench::miss_share(sss_bench::RgbImage::from_rgba(result.data(), scene.width, scene.height), ref,
                               sss_bench::RgbImage::from_rgba(scene.color.data(), scene.width, scene.height),
                               mask.data());
}

// The CPU model on `scene` with `settings` (hardware depth, RGBA32F throughout).
std::vector<float> cpu_model(const SyntheticScene& scene, const sss::math::FilterSettings& settings) {
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(settings);
  const PassConstants k = constants_for(scene, settings, kernel);
  sss::math::CpuFilterImage image = sss::math::cpu_filter_image(scene.width, scene.height, scene.color.data(),
                                                                 scene.window_depth.data());
  image.intermediate_is_half = false;
  std::vector<float> out(scene.color.size());
  sss::math::cpu_pass_kernel_filter(kernel, k, image, out.data());
  return out;
}

sss::math::FilterSettings sum_of_gaussians() {
  sss::math::FilterSettings s;
  s.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  s.kernel.rank = 6;
  return s;
}

TEST(SurfaceTurns, TheCpuModelIsExactOnAPlaneTurned60DegreesAboutAnAxisOffTheScreensAxes) {
  // 0.25 mm per facing pixel, 108x108: an interior of 44x44 pixels beyond the profile's reach.
  // Before the passes walked the surface (one step from the centre's depth for both axes, the raw
  // depth difference for follow-surface) this plane read 0.33 (sum of Gaussians) and 0.24 (default).
  const int n = 108;
  std::vector<double> d64;
  const SyntheticScene s = make_turned_plane_scene(n, n, 60.0, 30.0, 0.5, orthographic_for(n, n, 0.25), 4, &d64);
  const sss_bench::Miss sog = plane_miss(s, d64, cpu_model(s, sum_of_gaussians()));
  const sss_bench::Miss standard = plane_miss(s, d64, cpu_model(s, sss::math::FilterSettings{}));
  std::printf("interior miss: sum of Gaussians %.3f (%.3f %.3f %.3f), default %.3f (%.3f %.3f %.3f)\n", sog.pooled,
              sog.channel[0], sog.channel[1], sog.channel[2], standard.pooled, standard.channel[0], standard.channel[1],
              standard.channel[2]);
  EXPECT_LE(sog.pooled, 0.08);
  EXPECT_LE(standard.pooled, 0.18);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(sog.channel[static_cast<std::size_t>(c)], 1.0) << "channel " << c;
    EXPECT_LT(standard.channel[static_cast<std::size_t>(c)], 1.0) << "channel " << c;
  }
}

}  // namespace
}  // namespace sss_test
