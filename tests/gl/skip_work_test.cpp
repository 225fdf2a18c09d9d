// Skipping what a frame does not need (issue: footprint-adaptive taps and the host's region of
// translucent pixels), on the GL against the CPU model and against the full-frame result.
//
// Adaptive taps choose a tap list per pixel by comparing the pixel's step (pixels per profile mm)
// with each level's limit. The GPU and the CPU model compute that step in float but not bit for
// bit alike, so a pixel whose step lies within an ulp of a limit could take different levels on
// the two: the scenes here are built of flat bands whose steps sit well between the limits, so
// every pixel's choice is the same on both and the comparison keeps matches_cpu_model_test's 3e-3
// tolerance (one fp16 half-ulp flip of the intermediate and one of the output, explained there).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "../support/kernel_of.hpp"
#include "filter_case.hpp"
#include "math/filter_constants.hpp"
#include "math/pass_kernel.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;
constexpr int kWidth = 100, kHeight = 30;

sss_settings settings_for(uint32_t flags, float world_units_per_mm) { return visible_settings(17, flags, world_units_per_mm); }

// Five vertical bands of a plane facing the camera, each at its own distance, chosen so that a
// pixel's step (pixels_per_mm / distance at alpha 1) is `steps[band]`; colour is seeded noise so
// that any blur shows. The last 10 columns are not translucent (alpha 0).
SyntheticScene banded_scene(const sss_settings& s, const std::array<float, 5>& steps) {
  SyntheticScene scene;
  scene.width = kWidth;
  scene.height = kHeight;
  scene.projection = perspective_matrix(40.0f, static_cast<float>(kWidth) / kHeight, 0.1f, 100.0f);
  sss::math::FilterSettings fs;
  fs.world_units_per_mm = s.world_units_per_mm;
  sss::math::FrameGeometry g;
  g.texture_width = kWidth;
  g.texture_height = kHeight;
  g.viewport = {0, 0, kWidth, kHeight};
  const auto k = sss::math::compute_pass_constants(fs, scene.projection, g, 2.0f);
  EXPECT_NEAR(k.pixels_per_mm[0], k.pixels_per_mm[1], 1e-3f * k.pixels_per_mm[0]);  // square pixels
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> noise(0.1f, 1.0f);
  const std::size_t n = static_cast<std::size_t>(kWidth) * kHeight;
  scene.color.resize(n * 4);
  scene.distance.resize(n);
  scene.stencil.assign(n, 1);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      const int band = std::min(x / 18, 4);
      scene.distance[i] = k.pixels_per_mm[0] / steps[static_cast<std::size_t>(band)];
      for (int c = 0; c < 3; ++c) scene.color[i * 4 + static_cast<std::size_t>(c)] = noise(rng);
      scene.color[i * 4 + 3] = x >= kWidth - 10 ? 0.0f : 1.0f;
    }
  }
  compute_window_depth(&scene);
  return scene;
}

// Steps of the region tests' bands (pixels per profile mm): from a sub-pixel kernel to a wide one.
constexpr std::array<float, 5> kRegionSteps = {0.05f, 0.3f, 1.0f, 3.0f, 10.0f};

std::size_t pixel(int x, int y) { return (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4; }

// ---- Footprint-aware taps (math/footprint_kernel.hpp): each band of the scene is a footprint.

using FootprintTaps = FilterCaseTest;

// The kernels of every family, as the settings select them.
std::vector<std::pair<const char*, sss_settings>> every_family(float world_units_per_mm) {
  std::vector<std::pair<const char*, sss_settings>> out;
  sss_settings s = settings_for(SSS_FOLLOW_SURFACE, world_units_per_mm);
  out.emplace_back("eq. (1)", s);
  sss_test::kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
  sss_test::kernel_of(s).rank = 6;
  out.emplace_back("sum of Gaussians", s);
  sss_test::kernel_of(s).family = SSS_KERNEL_SVD;
  sss_test::kernel_of(s).rank = 2;
  out.emplace_back("SVD rank 2", s);
  sss_test::kernel_of(s).family = SSS_KERNEL_PREINTEGRATED;
  out.emplace_back("pre-integrated", s);
  sss_test::kernel_of(s).family = SSS_KERNEL_ARTIST;
  out.emplace_back("artist", s);
  return out;
}

// The reach of the widest pass of the kernel, in profile millimetres.
float widest_reach(const sss_settings& s) {
  sss::math::FilterSettings fs;
  fs.samples = s.taps;
  fs.strength = {s.strength[0], s.strength[1], s.strength[2]};
  fs.falloff = {s.falloff[0], s.falloff[1], s.falloff[2]};
  fs.separable_scale = s.separable_scale;
  if (s.kernel != nullptr) {  // NULL: eq. (1), FilterSettings' default family
    fs.kernel.family = static_cast<sss::math::KernelFamily>(s.kernel->family);
    fs.kernel.rank = s.kernel->rank;
  }
  float reach = 0.0f;
  for (const auto& t : sss::math::build_pass_kernel(fs).terms) {
    reach = std::max({reach, t.horizontal.footprint.reach_mm, t.vertical.footprint.reach_mm});
  }
  return reach;
}

TEST_F(FootprintTaps, MatchesTheCpuModelAtEveryFootprintForEveryFamily) {
  // Bands whose widest pass reaches 0.3 px (inside the pixel), 3 px (every pixel a tap), 8 px (the
  // dense layout's last), 30 px and 120 px (the sparse layout) on a side.
  for (const auto& [name, settings] : every_family(0.05f)) {
    SCOPED_TRACE(name);
    const float reach = widest_reach(settings);
    std::array<float, 5> steps{};
    const float reach_px[5] = {0.3f, 3.0f, 8.0f, 30.0f, 120.0f};
    for (std::size_t b = 0; b < 5; ++b) steps[b] = reach_px[b] / reach;
    for (bool separate : {false, true}) {
      SCOPED_TRACE(separate ? "separate output" : "in place");
      FilterCase c;
      c.settings = settings;
      c.separate_output = separate;
      const SyntheticScene scene = banded_scene(c.settings, steps);
      const FilterOutcome o = run_case(scene, c);
      ASSERT_EQ(o.result, SSS_OK);
      const float difference = largest_relative_difference(o.gpu, o.cpu);
      std::printf("footprint taps, %s, GPU vs CPU model: %.3g (tolerance %.3g)\n", name, difference, kTolerance);
      EXPECT_LE(difference, kTolerance);
      // The band whose kernel fits inside its pixel keeps the input to fp16: one unit in the last
      // place of the passes' RGBA16F intermediate, 2^-10 relative (llvmpipe's conversion does not
      // round to nearest, so half a unit is not enough); every other band was blurred.
      for (int band = 0; band < 5; ++band) {
        float changed = 0.0f;
        for (int y = 0; y < kHeight; ++y) {
          for (int x = band * 18 + 2; x < band * 18 + 16; ++x) {
            for (int ch = 0; ch < 3; ++ch) {
              const float in = o.input[pixel(x, y) + ch];
              changed = std::max(changed, std::fabs(o.gpu[pixel(x, y) + ch] - in) / in);
            }
          }
        }
        if (band == 0) {
          EXPECT_LE(changed, 1.0f / 1024.0f) << "band 0 must keep its input";
        } else {
          EXPECT_GT(changed, 0.02f) << "band " << band;
        }
      }
      TearDown();
      SetUp();
    }
  }
}

// 0.1's SSS_ADAPTIVE_TAPS (0x2) was accepted and ignored in 0.2; 0.3 removed it from the header: a
// 0.3 sss_settings with the bit is refused, a 0.1 or 0.2 one has it dropped (versioned_structs_test).
TEST_F(FootprintTaps, TheRemovedAdaptiveBitIsRefused) {
  sss_context* ctx = create_sss();
  ASSERT_NE(ctx, nullptr);
  sss_settings s = settings_for(SSS_FOLLOW_SURFACE | 0x2u, 0.05f);
  EXPECT_EQ(sss_set_settings(ctx, &s), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(ctx)).find("settings->flags = 0x3"), std::string::npos) << sss_last_error(ctx);
  sss_destroy(ctx);
}

// ---- The host's region (SSS_FRAME_REGION).

// The banded scene with translucent pixels only inside `inner` (x, y, w, h).
SyntheticScene island_scene(const sss_settings& s, const std::array<int, 4>& inner) {
  SyntheticScene scene = banded_scene(s, {1.0f, 1.0f, 1.0f, 1.0f, 1.0f});  // 1 px per profile mm
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool in = x >= inner[0] && x < inner[0] + inner[2] && y >= inner[1] && y < inner[1] + inner[3];
      scene.color[pixel(x, y) + 3] = in ? 1.0f : 0.0f;
      scene.stencil[static_cast<std::size_t>(y) * kWidth + x] = in ? 1 : 0;
    }
  }
  return scene;
}

using Region = FilterCaseTest;

TEST_F(Region, APaddedRegionGivesTheFullFrameResultBitForBit) {
  // The kernel (17 taps: 2 kernel mm over separable_scale, under 5 mm of surface; the
  // cross-bilateral mode's r_max 4.5 mm) reaches under 5 px at 1 px/mm: a region 8 px larger than
  // the island on every side holds every tap, so restricting the passes to it changes nothing.
  const std::array<int, 4> island = {30, 10, 25, 10};
  const std::array<int32_t, 4> padded = {22, 2, 41, 26};
  for (uint32_t mode : {SSS_MODE_SEPARABLE, SSS_MODE_CROSS_BILATERAL}) {
    for (bool separate : {false, true}) {
      SCOPED_TRACE(std::string(mode == SSS_MODE_SEPARABLE ? "separable" : "cross-bilateral") +
                   (separate ? ", separate output" : ", in place"));
      std::vector<float> results[2];
      for (int with_region = 0; with_region < 2; ++with_region) {
        FilterCase c;
        c.settings = settings_for(SSS_FOLLOW_SURFACE, 0.05f);
        c.settings.mode = mode;
        c.separate_output = separate;
        c.use_region = with_region == 1;
        c.region = padded;
        const FilterOutcome o = run_case(island_scene(c.settings, island), c);
        ASSERT_EQ(o.result, SSS_OK);
        EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), kTolerance);
        EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // the island was blurred
        results[with_region] = o.gpu;
        TearDown();
        SetUp();
      }
      EXPECT_EQ(results[0], results[1]);
    }
  }
}

TEST_F(Region, ATightRegionClampsTheTapsLikeTheViewportEdge) {
  // The region is the island itself: taps that would leave it read its edge, as the CPU model does
  // with the region as its clamp; pixels outside it hold their input (copied into a separate output).
  const std::array<int, 4> island = {30, 10, 25, 10};
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "separate output" : "in place");
    FilterCase c;
    c.settings = settings_for(SSS_FOLLOW_SURFACE, 0.05f);
    c.separate_output = separate;
    c.use_region = true;
    c.region = {island[0], island[1], island[2], island[3]};
    const FilterOutcome o = run_case(island_scene(c.settings, island), c);
    ASSERT_EQ(o.result, SSS_OK);
    EXPECT_LE(largest_relative_difference(o.gpu, o.cpu), kTolerance);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const bool in = x >= island[0] && x < island[0] + island[2] && y >= island[1] && y < island[1] + island[3];
        if (in) continue;
        for (int ch = 0; ch < 4; ++ch) ASSERT_EQ(o.gpu[pixel(x, y) + ch], o.input[pixel(x, y) + ch]) << x << "," << y;
      }
    }
    TearDown();
    SetUp();
  }
}

TEST_F(Region, AnEmptyRegionDrawsNothingInPlaceAndCopiesIntoAnOutput) {
  for (bool separate : {false, true}) {
    SCOPED_TRACE(separate ? "separate output" : "in place");
    FilterCase c;
    c.settings = settings_for(SSS_FOLLOW_SURFACE, 0.05f);
    c.separate_output = separate;
    c.use_region = true;
    c.region = {40, 12, 0, 5};
    const SyntheticScene scene = banded_scene(c.settings, kRegionSteps);  // translucent, but the host says not
    const FilterOutcome o = run_case(scene, c);
    ASSERT_EQ(o.result, SSS_OK);
    EXPECT_EQ(o.gpu, o.input);
    sss_stats stats;
    stats.struct_size = sizeof stats;
    ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
    EXPECT_EQ(stats.last_frame_passes, separate ? 1u : 0u);
    EXPECT_EQ(stats.frames, 1u);
    TearDown();
    SetUp();
  }
}

TEST_F(Region, BadRegionsAreRejectedNamingTheValueAndChangeNothing) {
  const SyntheticScene scene = banded_scene(settings_for(SSS_FOLLOW_SURFACE, 0.05f), kRegionSteps);
  const GLuint color = make_rgba32f(kWidth, kHeight, scene.color);
  const GLuint depth = make_depth32f(kWidth, kHeight, scene.window_depth);
  const std::vector<float> before = read_rgba(color, kWidth, kHeight);
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_settings s = settings_for(SSS_FOLLOW_SURFACE, 0.05f);
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  struct Bad {
    std::array<int32_t, 4> viewport, region;
    const char* message;
  };
  const Bad cases[] = {
      {{0, 0, 0, 0}, {-1, 0, 4, 4}, "frame->region = {-1, 0, 4, 4}: x, y, width and height must be >= 0"},
      {{0, 0, 0, 0}, {0, 0, 4, -2}, "frame->region = {0, 0, 4, -2}"},
      {{0, 0, 0, 0}, {90, 0, 11, 4}, "frame->region = {90, 0, 11, 4} reaches outside the viewport {0, 0, 100, 30}"},
      {{10, 5, 50, 20}, {5, 5, 10, 10}, "frame->region = {5, 5, 10, 10} reaches outside the viewport {10, 5, 50, 20}"},
      {{0, 0, 0, 0}, {2147483647, 0, 2147483647, 1}, "reaches outside the viewport"},
  };
  for (const Bad& b : cases) {
    sss_frame f = frame_of(color, depth);
    f.flags = SSS_FRAME_REGION;
    for (int i = 0; i < 4; ++i) {
      f.viewport[i] = b.viewport[static_cast<std::size_t>(i)];
      f.region[i] = b.region[static_cast<std::size_t>(i)];
    }
    if (is_gles()) {
      FilterCase c;
      describe_frame(c, kWidth, kHeight, &f);
    }
    EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_ERROR_INVALID_ARGUMENT) << b.message;
    EXPECT_NE(std::string(sss_last_error(sss_)).find(b.message), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  EXPECT_EQ(read_rgba(color, kWidth, kHeight), before);
  // Without the flag the same region is not read.
  sss_frame f = frame_of(color, depth);
  f.region[0] = -5;
  if (is_gles()) {
    FilterCase c;
    describe_frame(c, kWidth, kHeight, &f);
  }
  EXPECT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
}

}  // namespace
}  // namespace sss_test
