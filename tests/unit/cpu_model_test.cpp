// The CPU model of the two-pass filter: invariants, and the follow-surface behaviour it must show.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "math/cpu_separable_filter.hpp"
#include "math/pass_kernel.hpp"
#include "math/half_float.hpp"
#include "synthetic_scene.hpp"

namespace {

using sss_test::SyntheticScene;

struct Run {
  std::vector<float> out;
};

std::vector<float> filter(const SyntheticScene& scene, sss::math::FilterSettings s, bool mask = false) {
  sss::math::FrameGeometry g;
  g.texture_width = scene.width;
  g.texture_height = scene.height;
  g.viewport = {0, 0, scene.width, scene.height};
  // The kernel the settings describe, as the library builds it (footprint-aware taps).
  const auto kernel = sss::math::build_pass_kernel(s);
  const auto constants = sss::math::compute_pass_constants(s, scene.projection, g, kernel.reach_mm);
  sss::math::CpuFilterImage image;
  image.width = scene.width;
  image.height = scene.height;
  image.color = scene.color.data();
  image.depth = scene.window_depth.data();
  image.mask = mask ? scene.stencil.data() : nullptr;
  std::vector<float> out(scene.color.size());
  sss::math::cpu_pass_kernel_filter(kernel, constants, image, out.data());
  return out;
}

sss::math::FilterSettings wide() {
  sss::math::FilterSettings s;
  s.world_units_per_mm = 0.06f;
  s.strength = {1.0f, 1.0f, 1.0f};
  s.falloff = {1.0f, 0.5f, 0.3f};
  return s;
}

const sss::math::Matrix4 kCamera = sss_test::perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);

TEST(CpuModel, FlatStaysFlatWithinHalfPrecision) {
  const auto scene = sss_test::make_flat_scene(32, 32, {0.7f, 0.3f, 0.1f, 1.0f}, 2.0f, kCamera);
  const auto out = filter(scene, wide());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], scene.color[i], 5e-4f * scene.color[i]);
}

TEST(CpuModel, UntouchedPixelsKeepTheirValueAndMaskedOnesToo) {
  const auto scene = sss_test::make_relief_scene(40, 30, 2, kCamera);
  const auto out = filter(scene, wide(), true);
  for (std::size_t i = 0; i < scene.stencil.size(); ++i) {
    if (scene.stencil[i] == 0 || scene.color[i * 4 + 3] == 0.0f) {
      EXPECT_EQ(0, std::memcmp(&out[i * 4], &scene.color[i * 4], 16)) << i;
    }
  }
}

TEST(CpuModel, DotEnergyIsConserved) {
  auto scene = sss_test::make_flat_scene(64, 64, {0, 0, 0, 1}, 1.0f, kCamera);
  scene.color[(32 * 64 + 32) * 4 + 0] = 50.0f;
  const auto out = filter(scene, wide());
  double sum = 0.0;
  for (std::size_t i = 0; i < out.size(); i += 4) sum += out[i];
  EXPECT_NEAR(sum, 50.0, 0.005 * 50.0);
  EXPECT_LT(out[(32 * 64 + 32) * 4], 40.0f);
}

TEST(CpuModel, FollowSurfaceStopsLightCrossingADepthStep) {
  // Left half near and dark, right half 0.3 units further and bright.
  auto scene = sss_test::make_flat_scene(48, 16, {0, 0, 0, 1}, 1.0f, kCamera);
  for (int y = 0; y < 16; ++y) {
    for (int x = 24; x < 48; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 48 + x;
      scene.distance[i] = 1.3f;
      scene.color[i * 4] = 1.0f;
    }
  }
  sss_test::compute_window_depth(&scene);
  auto on = wide();
  auto off = wide();
  off.follow_surface = false;
  const auto with = filter(scene, on);
  const auto without = filter(scene, off);
  const std::size_t edge = (8 * 48 + 23) * 4;  // the last dark pixel
  EXPECT_GT(without[edge], 0.05f);
  // Whole-pixel taps read the far side's colour with its own depth, so the ramp stops them; what
  // may remain is the ramp's partial blend of taps whose depth difference is under the reach.
  EXPECT_LT(with[edge], 0.1f * without[edge]);
  EXPECT_LT(with[edge], 0.01f);
}

}  // namespace
