// The pass constants at the extremes of their inputs (found by fuzzing the CPU model): a projection
// scale near FLT_MAX times the viewport overflowed float to Inf, and Inf times a zero width gave a
// NaN step, which the CPU model turned into an int (undefined behaviour) and a shader into NaN
// tap positions. They are computed in double and clamped to float's range now.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "math/filter_constants.hpp"

namespace {

sss::math::Matrix4 camera_with_scales(float sx, float sy) {
  sss::math::Matrix4 m{};
  m[0] = sx;
  m[5] = sy;
  m[10] = -1.02f;
  m[11] = -1.0f;
  m[14] = -0.202f;
  return m;
}

sss::math::FrameGeometry geometry(int width, int height) {
  sss::math::FrameGeometry g;
  g.texture_width = width;
  g.texture_height = height;
  g.viewport = {0, 0, width, height};
  return g;
}

TEST(PassConstants, HugeProjectionScalesNeverGiveNaNOrInfinity) {
  const float big = std::numeric_limits<float>::max();
  for (float width : {0.0f, std::numeric_limits<float>::denorm_min(), 0.0015f, 1e6f}) {
    for (float scale : {-2.3373e38f, big, -big, 1e30f}) {
      sss::math::FilterSettings s;
      s.world_units_per_mm = width;
      const auto k = sss::math::compute_pass_constants(s, camera_with_scales(scale, scale), geometry(16384, 4));
      for (float p : k.pixels_per_mm) {
        EXPECT_TRUE(std::isfinite(p)) << "width " << width << " scale " << scale << ": " << p;
        EXPECT_GE(p, 0.0f);
      }
      EXPECT_TRUE(std::isfinite(k.follow_surface_factor)) << "width " << width;
      if (width == 0.0f) {
        EXPECT_EQ(k.pixels_per_mm[0], 0.0f);
      }
    }
  }
}

TEST(PassConstants, ADenormalWidthGivesAFiniteFollowSurfaceFactor) {
  sss::math::FilterSettings s;
  s.world_units_per_mm = std::numeric_limits<float>::denorm_min();
  const auto k = sss::math::compute_pass_constants(s, camera_with_scales(1.0f, 1.0f), geometry(8, 8));
  EXPECT_EQ(k.follow_surface_factor, std::numeric_limits<float>::max());
}

}  // namespace
