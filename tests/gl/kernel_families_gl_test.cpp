// Every kernel family of sss_kernels.h run by the GL passes through sss_settings.kernel (one
// horizontal and one vertical pass per term, later terms summed in the module's accumulators),
// against the CPU model of the same passes; the pre-integrated kernel against the 2D (non-separable)
// profile-matrix convolution it is exact for; jittered taps; the settings' checks.
//
// Tolerance against the CPU model: 3e-3 relative, as for eq. (1) (matches_cpu_model_test.cpp: one
// RGBA16F intermediate rounding flip, 2^-10, carried with weight <= 1, plus one on an RGBA16F
// output). With several terms each term's intermediate may flip once; the terms' weights sum to 1
// for the families here, so the flips add up to the same 2^-10 bound. The accumulators are RGBA32F on
// desktop GL (float sums) and RGBA16F on OpenGL ES, where the CPU model rounds the same way; there
// each of the terms - 1 stored sums can flip once more, 2^-11 each (measured 2.7e-3 with 6 terms on
// llvmpipe's ES, against at most 3e-3 + 5 · 2^-11). A wrong tap, weight, term, sum or depth rule
// moves values by 1e-2 or more on the relief scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/kernel_of.hpp"
#include "filter_case.hpp"
#include "math/kernel_request.hpp"
#include "math/plane_reference.hpp"
#include "math/skin_profile.hpp"

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;

sss_settings family_settings(int32_t family, int32_t rank = 1) {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.045f;  // about 2 pixels per profile millimetre on the 64x48 relief scene
  sss_test::kernel_of(s).family = family;
  sss_test::kernel_of(s).rank = rank;
  s.taps = 17;
  return s;
}

SyntheticScene relief() { return make_relief_scene(64, 48, 3, perspective_matrix(40.0f, 64.0f / 48.0f, 0.1f, 10.0f)); }

using KernelFamilies = FilterCaseTest;

void expect_blurred_and_matching(const FilterOutcome& o, const char* what, bool gles = false, int terms = 1) {
  ASSERT_EQ(o.result, SSS_OK) << what;
  const float tolerance = kTolerance + (gles ? static_cast<float>(terms - 1) * 0x1p-11f : 0.0f);
  const float difference = largest_relative_difference(o.gpu, o.cpu);
  std::printf("%s: GPU vs CPU model largest relative difference %.3g (tolerance %.3g)\n", what, difference,
              tolerance);
  EXPECT_LE(difference, tolerance) << what;
  EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f) << what << ": the case must change the image";
}

struct FamilyCase {
  const char* name;
  int32_t family, rank;
};

constexpr FamilyCase kFamilies[] = {
    {"sum of Gaussians, 3 terms", SSS_KERNEL_SUM_OF_GAUSSIANS, 3},
    {"sum of Gaussians, 6 terms", SSS_KERNEL_SUM_OF_GAUSSIANS, 6},
    {"SVD rank 1", SSS_KERNEL_SVD, 1},
    {"SVD rank 3 (negative weights)", SSS_KERNEL_SVD, 3},
    {"pre-integrated", SSS_KERNEL_PREINTEGRATED, 1},
    {"guided rank-1 fit", SSS_KERNEL_GUIDED, 1},
    {"artist two-Gaussian, exact depth correction", SSS_KERNEL_ARTIST, 1},
};

TEST_F(KernelFamilies, EveryFamilyMatchesTheCpuModel) {
  for (const FamilyCase& f : kFamilies) {
    SCOPED_TRACE(f.name);
    FilterCase c;
    c.settings = family_settings(f.family, f.rank);
    expect_blurred_and_matching(run_case(relief(), c), f.name, is_gles(), f.rank);
    TearDown();
    SetUp();
  }
}

TEST_F(KernelFamilies, SeveralTermsWithStencilSeparateOutputHalfColourAndLinearDepth) {
  FilterCase stencil_and_output;
  stencil_and_output.settings = family_settings(SSS_KERNEL_SUM_OF_GAUSSIANS, 4);
  stencil_and_output.depth = DepthKind::depth24_stencil8;
  stencil_and_output.use_stencil = true;
  stencil_and_output.separate_output = true;
  expect_blurred_and_matching(run_case(relief(), stencil_and_output), "4 Gaussians, stencil, separate output",
                              is_gles(), 4);
  TearDown();
  SetUp();
  FilterCase half;
  half.settings = family_settings(SSS_KERNEL_SVD, 2);
  half.half_color = true;
  half.depth = DepthKind::linear_r32f;
  expect_blurred_and_matching(run_case(relief(), half), "SVD rank 2, RGBA16F colour, linear depth", is_gles(), 2);
  TearDown();
  SetUp();
  FilterCase viewport;
  viewport.settings = family_settings(SSS_KERNEL_SUM_OF_GAUSSIANS, 2);
  viewport.viewport = {5, 7, 40, 30};
  viewport.separate_output = true;
  expect_blurred_and_matching(run_case(relief(), viewport), "2 Gaussians, viewport, separate output", is_gles(), 2);
}

TEST_F(KernelFamilies, MeasuredMaterialsAndWithoutFollowSurface) {
  FilterCase marble;
  marble.settings = family_settings(SSS_KERNEL_SUM_OF_GAUSSIANS, 2);
  sss_test::kernel_of(marble.settings).profile.profile = SSS_PROFILE_MARBLE;  // a fit of two Gaussians to its dipole
  marble.settings.world_units_per_mm = 0.01f;                                   // marble scatters far: fewer pixels per mm
  expect_blurred_and_matching(run_case(relief(), marble), "marble, 2 fitted Gaussians", is_gles(), 2);
  TearDown();
  SetUp();
  FilterCase plain;
  plain.settings = family_settings(SSS_KERNEL_ARTIST);
  plain.settings.flags = 0;  // no follow-surface test: the depth correction is off too
  expect_blurred_and_matching(run_case(relief(), plain), "artist model, no depth test");
}

TEST_F(KernelFamilies, JitteredTapsMatchTheCpuModelBitForBitNoise) {
  FilterCase eq1;
  eq1.settings = family_settings(SSS_KERNEL_SEPARABLE);
  eq1.settings.taps = 9;
  eq1.settings.jitter = 0.33f;
  const FilterOutcome jittered = run_case(relief(), eq1);
  expect_blurred_and_matching(jittered, "eq. (1), 9 taps, 33% jittered");
  TearDown();
  SetUp();
  eq1.settings.jitter = 0.0f;
  const FilterOutcome fixed = run_case(relief(), eq1);
  // The noise must move something: otherwise the CPU-model match above would prove nothing about it.
  EXPECT_GT(largest_relative_difference(jittered.gpu, fixed.gpu), 1e-3f);
  TearDown();
  SetUp();
  FilterCase gaussians;
  gaussians.settings = family_settings(SSS_KERNEL_SUM_OF_GAUSSIANS, 3);
  gaussians.settings.jitter = 1.0f;
  expect_blurred_and_matching(run_case(relief(), gaussians), "3 Gaussians, every tap jittered", is_gles(), 3);
}

// Supplementary S.5-S.6: for irradiance E1(x) + E2(y) the pre-integrated separable kernel gives the
// same result as the full 2D profile, which is not separable: convolving E1(x) with a radial
// profile is convolving it with the profile's 1D marginal, and the pre-integrated kernel is that
// marginal (for d'Eon's Gaussians in closed form). With footprint-aware taps on a plane facing the
// camera, where every pixel of the kernel's reach gets a tap, the passes compute the exact discrete
// convolution. What is left is the RGBA16F intermediate (2^-11 relative per pass, 3e-3 with the
// output's rounding included) and the footprint tables' interpolation (below 1e-4).
TEST_F(KernelFamilies, PreintegratedKernelIsExactForAdditivelySeparableIrradianceOnTheGpu) {
  const int w = 96, h = 72;
  SyntheticScene scene = make_flat_scene(w, h, {0.0f, 0.0f, 0.0f, 1.0f}, 2.0f,
                                         perspective_matrix(40.0f, static_cast<float>(w) / h, 0.1f, 10.0f));
  // Random sinusoids plus a hard shadow edge along each axis, positive everywhere.
  const std::array<float, 3> a1 = {0.3f, 0.5f, 0.2f}, a2 = {0.2f, 0.1f, 0.4f};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (std::size_t c = 0; c < 3; ++c) {
        const float e1 = a1[c] * (1.0f + std::sin(0.37f * static_cast<float>(x) + static_cast<float>(c))) +
                         (x > 41 ? 0.8f : 0.05f);
        const float e2 = a2[c] * (1.0f + std::cos(0.23f * static_cast<float>(y) * (1.0f + 0.2f * static_cast<float>(c)))) +
                         (y > 30 ? 0.6f : 0.1f);
        scene.color[(static_cast<std::size_t>(y) * w + x) * 4 + c] = e1 + e2;
      }
    }
  }
  FilterCase c;
  c.settings = family_settings(SSS_KERNEL_PREINTEGRATED);
  c.settings.taps = 65;
  // About 49 pixels per world unit per mm here: the widest skin Gaussian's reach (4σ of 7.41 mm²,
  // 11 mm) spans about 21 pixels, so every pixel of it gets a tap (the dense layout, at most 32).
  c.settings.world_units_per_mm = 0.04f;
  c.settings.flags = 0;
  c.depth = DepthKind::linear_r32f;
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);

  // The exact result for E1(x) + E2(y): each term convolved along its own axis with the profile's
  // 1D marginal integrated over each pixel (Σ_i w_i of d'Eon's Gaussians, sss::math::
  // pixel_integrated_gaussian), reading clamped to the frame as the passes do.
  sss::math::FilterSettings fs;
  fs.world_units_per_mm = c.settings.world_units_per_mm;
  sss::math::FrameGeometry g;
  g.texture_width = w;
  g.texture_height = h;
  g.viewport = {0, 0, w, h};
  g.depth = sss::math::DepthEncoding::linear_distance;
  const auto k = sss::math::compute_pass_constants(fs, scene.projection, g);
  const double clip_w = sss::math::clip_w(k, 2.0f);
  const double step_x = k.pixels_per_mm[0] / clip_w, step_y = k.pixels_per_mm[1] / clip_w;
  constexpr int kRadius = 40;
  auto marginal = [&](double step, int ch) {
    std::vector<double> weights(2 * kRadius + 1, 0.0);
    for (const auto& gaussian : sss::math::skin_gaussians()) {
      const auto part = sss::math::pixel_integrated_gaussian(gaussian.variance_mm2, 1.0 / step, kRadius);
      for (std::size_t d = 0; d < weights.size(); ++d) weights[d] += gaussian.weight[static_cast<std::size_t>(ch)] * part[d];
    }
    return weights;
  };
  ASSERT_GT(11.0 * step_x, 8.0) << "the kernel must span several pixels";
  ASSERT_LT(11.0 * step_y, 32.0) << "every pixel of the kernel must get a tap";
  double worst = 0.0;
  int compared = 0;
  for (int ch = 0; ch < 3; ++ch) {
    const std::vector<double> wx = marginal(step_x, ch), wy = marginal(step_y, ch);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        // The input is E1(x) + E2(y): convolve it along x with wx, then along y with wy (the
        // marginals sum to 1, so each term passes the other axis unchanged).
        double sum = 0.0;
        for (int dy = -kRadius; dy <= kRadius; ++dy) {
          const int yy = std::clamp(y + dy, 0, h - 1);
          double row = 0.0;
          for (int dx = -kRadius; dx <= kRadius; ++dx) {
            const int xx = std::clamp(x + dx, 0, w - 1);
            row += wx[static_cast<std::size_t>(dx + kRadius)] *
                   static_cast<double>(o.input[(static_cast<std::size_t>(yy) * w + xx) * 4 + static_cast<std::size_t>(ch)]);
          }
          sum += wy[static_cast<std::size_t>(dy + kRadius)] * row;
        }
        const double gpu = o.gpu[(static_cast<std::size_t>(y) * w + x) * 4 + static_cast<std::size_t>(ch)];
        worst = std::max(worst, std::fabs(gpu - sum) / std::max(1.0, std::fabs(sum)));
        ++compared;
      }
    }
  }
  std::printf("pre-integrated kernel on the GPU vs the exact convolution: %d values, largest relative "
              "difference %.3g\n",
              compared, worst);
  EXPECT_GT(compared, 1000);
  EXPECT_LE(worst, static_cast<double>(kTolerance));
  EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // it did blur
}

TEST_F(KernelFamilies, EveryTermIsAPairOfPasses) {
  const SyntheticScene scene = relief();
  FilterCase c;
  c.settings = family_settings(SSS_KERNEL_SUM_OF_GAUSSIANS, 5);
  // The plain fragment path: nothing but the terms' passes (the default, SSS_PATH_AUTO, takes the
  // masked path on llvmpipe, which adds its stencil mark).
  c.settings.path = SSS_PATH_FRAGMENT;
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK);
  sss_stats stats;
  stats.struct_size = sizeof stats;
  ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  EXPECT_EQ(stats.last_frame_path, SSS_PATH_FRAGMENT);
  EXPECT_EQ(stats.last_frame_passes, 11u);  // the inputs, then a horizontal and a vertical pass per term
}

// Burley's normalized diffusion (SSS_PROFILE_BURLEY, its 1/r centre integrated exactly into the
// kernel's cells) runs like any profile: the rank-1 pre-integrated kernel the per-pixel profiles take
// and a multi-term SVD against the CPU model; as one of several profiles; its fields checked by name.
TEST_F(KernelFamilies, BurleyProfilesRunLikeAnyOther) {
  sss_profile_desc marble;
  ASSERT_EQ(sss_profile_burley_from_measured(SSS_PROFILE_MARBLE, &marble), SSS_OK);
  for (int32_t rank : {1, 3}) {
    FilterCase c;
    c.settings = family_settings(rank == 1 ? SSS_KERNEL_PREINTEGRATED : SSS_KERNEL_SVD, rank);
    sss_test::kernel_of(c.settings).profile = marble;
    c.settings.world_units_per_mm = 0.01f;  // marble scatters far: fewer pixels per mm
    expect_blurred_and_matching(run_case(relief(), c), rank == 1 ? "Burley marble, pre-integrated" : "Burley marble, SVD 3",
                                is_gles(), rank);
    TearDown();
    SetUp();
  }
  sss_context* ctx = create_sss();
  ASSERT_NE(ctx, nullptr);
  sss_settings profiles[2];
  sss_default_settings(&profiles[0]);
  profiles[1] = family_settings(SSS_KERNEL_PREINTEGRATED);
  profiles[1].taps = profiles[0].taps;
  profiles[1].jitter = profiles[0].jitter;
  profiles[1].flags = profiles[0].flags;
  sss_test::kernel_of(profiles[1]).profile = marble;
  EXPECT_EQ(sss_set_profiles(ctx, profiles, 2), SSS_OK) << sss_last_error(ctx);
  sss_settings bad = profiles[1];
  sss_test::kernel_of(bad).profile.burley_dmfp_mm[2] = 0.0f;
  EXPECT_EQ(sss_set_settings(ctx, &bad), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(ctx)).find("settings->kernel->profile->burley_dmfp_mm[2] = 0"), std::string::npos)
      << sss_last_error(ctx);
  sss_destroy(ctx);
}

TEST_F(KernelFamilies, BadKernelSettingsAreNamedAndTheOldOnesStay) {
  sss_context* ctx = create_sss();
  ASSERT_NE(ctx, nullptr);
  sss_settings good = family_settings(SSS_KERNEL_SVD, 2);
  ASSERT_EQ(sss_set_settings(ctx, &good), SSS_OK) << sss_last_error(ctx);
  struct Bad {
    const char* field;
    void (*spoil)(sss_settings*);
  };
  const Bad cases[] = {
      {"settings->jitter", [](sss_settings* s) { s->jitter = std::nanf(""); }},
      {"settings->jitter", [](sss_settings* s) { s->jitter = 1.5f; }},
      {"settings->kernel->family", [](sss_settings* s) { sss_test::kernel_of(*s).family = SSS_KERNEL_FAMILY_COUNT; }},
      {"settings->kernel->rank", [](sss_settings* s) { sss_test::kernel_of(*s).rank = 7; }},
      {"settings->kernel->guide_k", [](sss_settings* s) {
         sss_test::kernel_of(*s).family = SSS_KERNEL_GUIDED;
         sss_test::kernel_of(*s).guide_k = 4.5f;
       }},
      {"settings->kernel->near_variance_mm2", [](sss_settings* s) { sss_test::kernel_of(*s).near_variance_mm2[1] = -1.0f; }},
      {"settings->kernel->struct_size", [](sss_settings* s) { sss_test::kernel_of(*s).struct_size = 3; }},
      {"settings->kernel->profile", [](sss_settings* s) { sss_test::kernel_of(*s).profile.profile = 99; }},
      {"settings->kernel->profile", [](sss_settings* s) {
         sss_test::kernel_of(*s).profile.profile = SSS_PROFILE_TABULATED;
         sss_test::kernel_of(*s).profile.table_size = 2;
         sss_test::kernel_of(*s).profile.table_radius_mm = nullptr;
       }},
  };
  for (const Bad& b : cases) {
    sss_settings s = good;
    b.spoil(&s);
    EXPECT_EQ(sss_set_settings(ctx, &s), SSS_ERROR_INVALID_ARGUMENT) << b.field;
    EXPECT_NE(std::string(sss_last_error(ctx)).find(b.field), std::string::npos) << sss_last_error(ctx);
    sss_settings now;
    now.struct_size = sizeof now;
    ASSERT_EQ(sss_get_settings(ctx, &now), SSS_OK);
    EXPECT_EQ(sss_test::kernel_of(now).family, SSS_KERNEL_SVD) << b.field;
    EXPECT_EQ(sss_test::kernel_of(now).rank, 2) << b.field;
    EXPECT_EQ(now.jitter, 0.0f) << b.field;
  }
  // A profile with no energy in a channel has no kernel.
  const float radii[2] = {0.0f, 1.0f};
  const float zero_green[6] = {1.0f, 0.0f, 1.0f, 0.5f, 0.0f, 0.5f};
  sss_settings empty = good;
  sss_test::kernel_of(empty).profile.profile = SSS_PROFILE_TABULATED;
  sss_test::kernel_of(empty).profile.table_size = 2;
  sss_test::kernel_of(empty).profile.table_radius_mm = radii;
  sss_test::kernel_of(empty).profile.table_rgb = zero_green;
  EXPECT_EQ(sss_set_settings(ctx, &empty), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(ctx)).find("channel 1"), std::string::npos) << sss_last_error(ctx);
  sss_destroy(ctx);
}

TEST_F(KernelFamilies, ATabulatedProfileIsCopiedAndGivenBack) {
  sss_context* ctx = create_sss();
  ASSERT_NE(ctx, nullptr);
  std::vector<float> radii = {0.0f, 0.5f, 1.0f, 2.0f};
  std::vector<float> rgb = {2.0f, 1.5f, 1.0f, 1.0f, 0.8f, 0.5f, 0.3f, 0.2f, 0.1f, 0.0f, 0.0f, 0.0f};
  sss_settings s = family_settings(SSS_KERNEL_PREINTEGRATED);
  sss_test::kernel_of(s).profile.profile = SSS_PROFILE_TABULATED;
  sss_test::kernel_of(s).profile.table_size = 4;
  sss_test::kernel_of(s).profile.table_radius_mm = radii.data();
  sss_test::kernel_of(s).profile.table_rgb = rgb.data();
  ASSERT_EQ(sss_set_settings(ctx, &s), SSS_OK) << sss_last_error(ctx);
  std::fill(radii.begin(), radii.end(), -1.0f);  // the caller's arrays may go away
  std::fill(rgb.begin(), rgb.end(), -1.0f);
  sss_settings back;
  back.struct_size = sizeof back;
  ASSERT_EQ(sss_get_settings(ctx, &back), SSS_OK);
  ASSERT_EQ(sss_test::kernel_of(back).profile.table_size, 4);
  EXPECT_EQ(sss_test::kernel_of(back).profile.table_radius_mm[3], 2.0f);
  EXPECT_EQ(sss_test::kernel_of(back).profile.table_rgb[4], 0.8f);
  EXPECT_EQ(sss_set_settings(ctx, &back), SSS_OK) << "what sss_get_settings gives back is valid input";
  sss_destroy(ctx);
}

}  // namespace
}  // namespace sss_test
