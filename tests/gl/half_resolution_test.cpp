// SSS_PATH_HALF_RESOLUTION (issue 24 item 5; module/src/math/half_resolution.hpp): the passes at
// half size where the kernel is wide, an upsample, the full-size passes elsewhere.
//
// Against the CPU model of the same steps (cpu_half_resolution_filter), within the tolerance of
// MatchesCpuModel (3e-3 relative: one RGBA16F rounding of the intermediate flipped by float
// reordering, carried into the output, and one more on output); the upsample adds a weighted mean
// of four half-size values, whose float reordering moves a value by a few ulps, well inside it.
// Invariants: where no kernel is wide, the path is the full-size passes bit for bit; a constant
// surface stays constant; frames it cannot run take the fragment passes and say so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "api/profiles.hpp"
#include "filter_case.hpp"
#include "host_gl_util.hpp"
#include "math/cpu_half_resolution.hpp"
#include "math/half_resolution.hpp"
#include "math/pass_kernel.hpp"

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;

// The scene scales below were chosen for an 8-pixel threshold: scaled with the generated one
// (kHalfResolutionMinReachPixels), the same share of the relief's kernels reaches it.
float at_threshold(float width_for_8_pixels) { return width_for_8_pixels * sss::math::kHalfResolutionMinReachPixels / 8.0f; }

SyntheticScene relief() { return make_relief_scene(64, 48, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f)); }

sss_settings half_settings(float width, uint32_t path = SSS_PATH_HALF_RESOLUTION) {
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, width);
  s.path = path;
  return s;
}

using HalfResolution = FilterCaseTest;

// Both kinds of pixel occur (0.12 world units per mm: kernels from a few to some twenty pixels on
// the relief), in place and into an output, RGBA16F and RGBA32F, whole frame and a region.
TEST_F(HalfResolution, MatchesTheCpuModel) {
  struct Variant {
    const char* name;
    bool half_color, separate, region, stencil;
  };
  for (const Variant& v : {Variant{"RGBA16F in place", true, false, false, false},
                           Variant{"RGBA32F in place", false, false, false, false},
                           Variant{"RGBA16F into an output", true, true, false, false},
                           Variant{"RGBA32F region into an output", false, true, true, false},
                           Variant{"RGBA16F region in place", true, false, true, false},
                           Variant{"RGBA16F behind a host stencil, in place", true, false, false, true},
                           Variant{"RGBA32F behind a host stencil, into an output", false, true, false, true}}) {
    SCOPED_TRACE(v.name);
    FilterCase c;
    c.settings = half_settings(at_threshold(0.03f));
    c.half_color = v.half_color;
    c.separate_output = v.separate;
    c.use_region = v.region;
    c.region = {5, 3, 41, 37};
    c.use_stencil = v.stencil;
    if (v.stencil) c.depth = DepthKind::depth24_stencil8;
    const FilterOutcome o = run_case(relief(), c);
    ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(last_path(), static_cast<uint32_t>(SSS_PATH_HALF_RESOLUTION));
    const float difference = largest_relative_difference(o.gpu, o.cpu);
    std::printf("%s: GPU vs CPU model: largest relative difference %.3g; %lld pixels upsampled, %lld at full size\n",
                v.name, static_cast<double>(difference), o.upsampled, o.full_size);
    EXPECT_LE(difference, kTolerance);
    EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // it blurred
    EXPECT_GT(o.upsampled, 200);  // both ways of filtering a pixel ran
    EXPECT_GT(o.full_size, 20);
    TearDown();
    SetUp();
  }
}

// Kernels of a few pixels everywhere: no pixel is upsampled, and the frame is the full-size
// passes' bit for bit (the half-size draws change nothing the output reads).
TEST_F(HalfResolution, WhereNoKernelIsWideItIsTheFullSizePassesBitForBit) {
  FilterCase c;
  c.half_color = true;
  c.settings = half_settings(0.005f);
  const FilterOutcome half = run_case(relief(), c);
  ASSERT_EQ(half.result, SSS_OK);
  EXPECT_EQ(half.upsampled, 0);
  EXPECT_GT(half.full_size, 1000);
  TearDown();
  SetUp();
  c.settings.path = SSS_PATH_FRAGMENT;
  const FilterOutcome full = run_case(relief(), c);
  ASSERT_EQ(full.result, SSS_OK);
  ASSERT_EQ(half.gpu.size(), full.gpu.size());
  EXPECT_EQ(std::memcmp(half.gpu.data(), full.gpu.data(), half.gpu.size() * sizeof(float)), 0);
  EXPECT_GT(largest_relative_difference(full.gpu, full.input), 0.02f);
}

// A surface of one colour facing the camera: every weight sums to one, so the upsample gives the
// colour back (B = X = the colour): within one half-float step of the RGBA16F target.
TEST_F(HalfResolution, AConstantSurfaceStaysConstant) {
  const SyntheticScene flat =
      make_flat_scene(64, 48, {0.8f, 0.4f, 0.2f, 1.0f}, 1.0f, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f));
  FilterCase c;
  c.half_color = true;
  c.settings = half_settings(at_threshold(0.12f));
  const FilterOutcome o = run_case(flat, c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_GT(o.upsampled, 1000);
  float worst = 0.0f;
  for (std::size_t i = 0; i < o.gpu.size(); ++i) {
    if (i % 4 != 3) worst = std::max(worst, std::fabs(o.gpu[i] - o.input[i]) / o.input[i]);
  }
  std::printf("constant surface: largest relative change %.3g\n", static_cast<double>(worst));
  EXPECT_LE(worst, 1.0f / 1024.0f);
}

// What the path cannot run (a kernel of two terms; the cross-bilateral mode) takes the fragment
// passes: the same image as SSS_PATH_FRAGMENT, and the stats say so.
TEST_F(HalfResolution, FramesItCannotRunTakeTheFragmentPasses) {
  for (int which = 0; which < 2; ++which) {
    SCOPED_TRACE(which == 0 ? "two kernel terms" : "cross-bilateral mode");
    FilterCase c;
    c.settings = path_case_settings(half_settings(0.12f), SSS_PATH_HALF_RESOLUTION,
                                    which == 0 ? SSS_MODE_SEPARABLE : SSS_MODE_CROSS_BILATERAL, which == 0);
    const FilterOutcome half = run_case(relief(), c);
    ASSERT_EQ(half.result, SSS_OK);
    EXPECT_EQ(last_path(), static_cast<uint32_t>(SSS_PATH_FRAGMENT));
    TearDown();
    SetUp();
    c.settings.path = SSS_PATH_FRAGMENT;
    const FilterOutcome full = run_case(relief(), c);
    ASSERT_EQ(half.gpu.size(), full.gpu.size());
    EXPECT_EQ(std::memcmp(half.gpu.data(), full.gpu.data(), half.gpu.size() * sizeof(float)), 0);
    TearDown();
    SetUp();
  }
}

// Per-pixel profiles (R8UI indices, two materials and an object of the first): the reduction and
// the upsample keep to each pixel's index, and the whole frame matches the CPU model.
TEST_F(HalfResolution, PerPixelProfilesMatchTheCpuModel) {
  constexpr int kW = 64, kH = 48;
  const SyntheticScene scene = relief();
  sss_settings first = half_settings(at_threshold(0.03f));
  sss_settings second = first;
  second.scale = 2.0f;
  second.strength[0] = 0.5f;
  second.falloff[2] = 0.2f;
  const sss_settings profiles[2] = {first, second};
  const auto id = [](int x, int y) { return x < 30 ? (y < kH / 2 ? 0u : 0x10u) : (y < 20 ? 1u : 7u); };
  std::vector<uint8_t> ids8(static_cast<std::size_t>(kW) * kH);
  std::vector<uint16_t> ids(ids8.size());
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      ids[static_cast<std::size_t>(y) * kW + x] = static_cast<uint16_t>(id(x, y));
      ids8[static_cast<std::size_t>(y) * kW + x] = static_cast<uint8_t>(id(x, y));
    }
  }
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK) << sss_last_error(sss_);
  const GLuint color = make_rgba16f(kW, kH, scene.color);
  const GLuint depth = make_depth32f(kW, kH, scene.window_depth);
  host_gl::glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLuint id_texture = make_texture(GL_R8UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_BYTE, ids8.data());
  host_gl::glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const std::vector<float> input = read_rgba(color, kW, kH);
  sss_frame f = frame_of(color, depth);
  f.texture_width = kW;
  f.texture_height = kH;
  f.color_format = GL_RGBA16F;
  f.depth_format = GL_DEPTH_COMPONENT32F;
  f.profile_texture = id_texture;
  f.profile_format = GL_R8UI;
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(last_path(), static_cast<uint32_t>(SSS_PATH_HALF_RESOLUTION));
  const std::vector<float> gpu = read_rgba(color, kW, kH);

  const ProfileModels models = profile_models(profiles, 2, scene.projection, kW, kH);
  sss::math::CpuFilterImage image;
  image.width = kW;
  image.height = kH;
  image.color = input.data();
  image.depth = scene.window_depth.data();
  image.output_is_half = true;
  std::vector<float> cpu(input.size());
  sss::math::CpuHalfResolutionStats stats;
  sss::math::cpu_half_resolution_filter(models.kernel_pointers(), models.constants, ids.data(), image,
                                        sss::math::kHalfResolutionMinReachPixels, cpu.data(), &stats);
  const float difference = largest_relative_difference(gpu, cpu);
  std::printf("per-pixel profiles: largest relative difference %.3g; %lld upsampled, %lld at full size\n",
              static_cast<double>(difference), stats.upsampled, stats.full_size);
  EXPECT_LE(difference, kTolerance);
  EXPECT_GT(stats.upsampled, 200);
  EXPECT_GT(stats.full_size, 20);
  EXPECT_GT(largest_relative_difference(gpu, input), 0.02f);
  // Index 7 has no profile: left alone.
  EXPECT_EQ(gpu[(static_cast<std::size_t>(30) * kW + 50) * 4], input[(static_cast<std::size_t>(30) * kW + 50) * 4]);
}

// SSS_PATH_AUTO takes it only with SSS_AUTO_HALF_RESOLUTION and a trustworthy timer: on a software
// rasteriser (these tests' GL) never, flag or not.
TEST_F(HalfResolution, AutoDoesNotPickItWithoutATimer) {
  FilterCase c;
  c.settings = half_settings(0.12f, SSS_PATH_AUTO);
  c.settings.flags |= SSS_AUTO_HALF_RESOLUTION;
  const FilterOutcome o = run_case(relief(), c);
  ASSERT_EQ(o.result, SSS_OK);
  EXPECT_NE(last_path(), static_cast<uint32_t>(SSS_PATH_HALF_RESOLUTION));
  sss_settings back;
  back.struct_size = sizeof back;
  ASSERT_EQ(sss_get_settings(sss_, &back), SSS_OK);
  EXPECT_EQ(back.flags, SSS_FOLLOW_SURFACE | SSS_AUTO_HALF_RESOLUTION);  // the flag round-trips
}

}  // namespace
}  // namespace sss_test
