// Invariants that need no reference (DESIGN.md §6, reference 3), on the GL.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "filter_case.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

using Invariants = FilterCaseTest;

sss_settings wide_settings() {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.06f;
  s.strength[0] = s.strength[1] = s.strength[2] = 1.0f;
  s.falloff[0] = 1.0f;
  s.falloff[1] = 0.5f;
  s.falloff[2] = 0.3f;
  return s;
}

const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
// One RGBA16F ulp relative to the value, at most: 2^-10.
constexpr float kHalfUlp = 1.0f / 1024.0f;

TEST_F(Invariants, AFlatImageStaysFlat) {
  FilterCase c;
  c.settings = wide_settings();
  const FilterOutcome o = run_case(make_flat_scene(48, 48, {0.8f, 0.4f, 0.2f, 1.0f}, 1.5f, kCamera), c);
  ASSERT_EQ(o.result, SSS_OK);
  for (std::size_t i = 0; i < o.gpu.size(); ++i) {
    // Kernel weights sum to 1 within 1e-6; the RGBA16F intermediate rounds each value to one
    // half-float ulp at most (2^-10 of it: 10 stored mantissa bits).
    EXPECT_NEAR(o.gpu[i], o.input[i], kHalfUlp * o.input[i] + 1e-6f) << "component " << i;
  }
}

TEST_F(Invariants, StrengthZeroSettingsAreTheIdentityBitForBit) {
  FilterCase c;
  c.settings = wide_settings();
  c.settings.strength[0] = c.settings.strength[1] = c.settings.strength[2] = 0.0f;
  const FilterOutcome o = run_case(make_relief_scene(40, 30, 1, kCamera), c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_EQ(0, std::memcmp(o.gpu.data(), o.input.data(), o.gpu.size() * sizeof(float)));
}

TEST_F(Invariants, WidthZeroIntoASeparateOutputCopiesBitForBit) {
  FilterCase c;
  c.settings = wide_settings();
  c.settings.world_units_per_mm = 0.0f;
  c.separate_output = true;
  const FilterOutcome o = run_case(make_relief_scene(40, 30, 1, kCamera), c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_EQ(0, std::memcmp(o.gpu.data(), o.input.data(), o.gpu.size() * sizeof(float)));
}

// Alpha-0 pixels and stencil-rejected pixels keep their exact input value, written back or copied.
void expect_untouched_pixels_identical(const SyntheticScene& scene, const FilterOutcome& o, bool stencil) {
  int checked = 0;
  for (std::size_t i = 0; i < scene.stencil.size(); ++i) {
    const bool untouched = scene.color[i * 4 + 3] == 0.0f || (stencil && scene.stencil[i] == 0);
    if (!untouched) continue;
    ++checked;
    ASSERT_EQ(0, std::memcmp(&o.gpu[i * 4], &o.input[i * 4], 4 * sizeof(float))) << "pixel " << i;
  }
  EXPECT_GT(checked, 50);
}

TEST_F(Invariants, StrengthZeroAndStencilRejectedPixelsAreBitIdentical) {
  const SyntheticScene scene = make_relief_scene(64, 48, 9, kCamera);
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "separate output" : "write back");
    FilterCase c;
    c.settings = wide_settings();
    c.depth = DepthKind::depth24_stencil8;
    c.use_stencil = true;
    c.separate_output = separate;
    expect_untouched_pixels_identical(scene, run_case(scene, c), true);
    c.use_stencil = false;
    TearDown();
    SetUp();
    expect_untouched_pixels_identical(scene, run_case(scene, c), false);
    TearDown();
    SetUp();
  }
}

TEST_F(Invariants, AnIsolatedDotKeepsItsEnergy) {
  // A 2x2 bright dot on a dark plane facing the camera, far from the borders.
  SyntheticScene scene = make_flat_scene(96, 96, {0.0f, 0.0f, 0.0f, 1.0f}, 1.0f, kCamera);
  for (int y = 47; y <= 48; ++y) {
    for (int x = 47; x <= 48; ++x) {
      for (int ch = 0; ch < 3; ++ch) scene.color[(static_cast<std::size_t>(y) * 96 + x) * 4 + ch] = 100.0f;
    }
  }
  FilterCase c;
  c.settings = wide_settings();
  c.settings.taps = 25;
  // The kernel's reach (2 kernel mm over separable_scale, about 4.5 mm of surface) 0.03 world units
  // each: about 28 pixels at distance 1, so all of the dot's light stays inside the 96-pixel frame.
  c.settings.world_units_per_mm = 0.03f;
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);
  for (int ch = 0; ch < 3; ++ch) {
    double in = 0.0, out = 0.0, centre = 0.0;
    for (std::size_t i = 0; i < o.gpu.size() / 4; ++i) {
      in += o.input[i * 4 + ch];
      out += o.gpu[i * 4 + ch];
    }
    centre = o.gpu[(47 * 96 + 47) * 4 + ch];
    EXPECT_NEAR(out, in, 0.01 * in) << "channel " << ch;
    EXPECT_LT(centre, 0.9 * 100.0) << "the dot was not spread (channel " << ch << ")";
  }
}

TEST_F(Invariants, OutputIsFiniteOnExtremeButValidInput) {
  SyntheticScene scene = make_relief_scene(48, 32, 4, kCamera);
  for (std::size_t i = 0; i < scene.color.size(); i += 4) {
    scene.color[i] = (i / 4) % 3 == 0 ? 60000.0f : 0.0f;  // near fp16's largest value next to zeros
  }
  FilterCase c;
  c.settings = wide_settings();
  c.half_color = true;
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);
  for (float v : o.gpu) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(Invariants, NonFinitePixelsDoNotSpread) {
  // NaN and infinite pixels on a flat, uniformly lit plane: after the filter every finite pixel is
  // still finite and still the plane's colour (within half precision), and the bad pixels keep
  // their own value.
  SyntheticScene scene = make_flat_scene(48, 32, {0.5f, 0.3f, 0.2f, 1.0f}, 1.5f, kCamera);
  const float nan = std::nanf(""), inf = INFINITY;
  const std::size_t bad[] = {(10 * 48 + 10) * 4, (20 * 48 + 30) * 4 + 1, (5 * 48 + 40) * 4 + 3};
  scene.color[bad[0]] = nan;
  scene.color[bad[1]] = inf;
  scene.color[bad[2]] = nan;  // alpha
  // With and without follow-surface: the passes' inputs hold such a pixel as a tap that must count
  // as the centre either way (without follow-surface no depth test stands in for the colour's).
  // And through the half-resolution upsample, whose surface weights must treat a NaN distance as
  // off the surface (on NVIDIA, !(s < 1.0) alone let it through), and the compute path, whose cache
  // holds such a pixel as the inputs draw does (where there is no compute, the fragment passes).
  for (const uint32_t path :
       {uint32_t{SSS_PATH_AUTO}, uint32_t{SSS_PATH_HALF_RESOLUTION}, uint32_t{SSS_PATH_COMPUTE}}) {
    for (const uint32_t flags : {uint32_t{SSS_FOLLOW_SURFACE}, 0u}) {
      SCOPED_TRACE(flags != 0 ? "follow-surface" : "no follow-surface");
      SCOPED_TRACE(path == SSS_PATH_AUTO ? "automatic path" : path == SSS_PATH_COMPUTE ? "compute" : "half resolution");
      FilterCase c;
      c.settings = wide_settings();
      c.settings.flags = flags;
      c.settings.path = path;
      const FilterOutcome o = run_case(scene, c);
      ASSERT_EQ(o.result, SSS_OK);
      for (std::size_t i = 0; i < o.gpu.size(); i += 4) {
        const bool is_bad = i == bad[0] || i + 1 == bad[1] || i + 3 == bad[2];
        if (is_bad) {
          ASSERT_EQ(0, std::memcmp(&o.gpu[i], &o.input[i], 16)) << "pixel " << i / 4;
          continue;
        }
        for (std::size_t ch = 0; ch < 3; ++ch) {
          ASSERT_TRUE(std::isfinite(o.gpu[i + ch])) << "pixel " << i / 4;
          EXPECT_NEAR(o.gpu[i + ch], o.input[i + ch], kHalfUlp * o.input[i + ch] + 1e-6f) << "pixel " << i / 4;
        }
      }
      // (The half path is not the CPU model's image; on this flat plane the check above holds it.)
      if (path != SSS_PATH_HALF_RESOLUTION) {
        EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), 3e-3f);
      }
    }
  }
}

}  // namespace
}  // namespace sss_test
