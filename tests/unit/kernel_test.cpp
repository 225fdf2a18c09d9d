// The separable kernel (paper eq. 1) in the math layer and its GL-free C API.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "math/pass_kernel.hpp"
#include "math/separable_kernel.hpp"
#include "math/skin_profile.hpp"
#include "sss/sss_tools.h"

namespace {

using sss::math::KernelTap;

// Simpson's rule on the base profile's point values: an independent check of the erf integration.
double base_profile_point(double falloff, double x) {
  const auto& terms = sss::math::skin_gaussians();
  const double scale = 0.001 + falloff;
  double sum = 0.0;
  for (std::size_t i = 1; i < terms.size(); ++i) {
    sum += terms[i].weight[0] * sss::math::gaussian_2d(terms[i].variance_mm2, x / scale);
  }
  return sum;
}

double simpson(double falloff, double a, double b) {
  const int n = 20000;
  const double h = (b - a) / n;
  double sum = base_profile_point(falloff, a) + base_profile_point(falloff, b);
  for (int i = 1; i < n; ++i) sum += base_profile_point(falloff, a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

TEST(SkinProfile, EachChannelOfTheSixGaussiansSumsToOne) {
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const auto& term : sss::math::skin_gaussians()) sum += term.weight[static_cast<std::size_t>(c)];
    EXPECT_NEAR(sum, 1.0, 1e-12) << "channel " << c;
  }
}

TEST(SeparableKernel, EveryTapCountSumsToOnePerChannel) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int n = SSS_MIN_TAPS; n <= SSS_MAX_TAPS; n += 2) {
    for (int trial = 0; trial < 5; ++trial) {
      const std::array<float, 3> strength = {unit(rng), unit(rng), unit(rng)};
      const std::array<float, 3> falloff = {unit(rng), unit(rng), unit(rng)};
      const auto kernel = sss::math::separable_kernel(n, strength, falloff);
      ASSERT_EQ(kernel.size(), static_cast<std::size_t>(n));
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (const KernelTap& tap : kernel) {
          EXPECT_GE(tap.weight[static_cast<std::size_t>(c)], 0.0f);
          sum += tap.weight[static_cast<std::size_t>(c)];
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << "n=" << n << " channel " << c;
      }
    }
  }
}

TEST(SeparableKernel, LayoutIsCentreFirstThenAscendingAndSymmetric) {
  for (int n : {3, 9, 11, 17, 21, 25, 33, 65}) {
    const auto kernel = sss::math::separable_kernel(n, {0.78f, 0.70f, 0.75f}, {0.57f, 0.13f, 0.08f});
    const double range = 2.0;  // every tap count (separable_kernel.hpp)
    EXPECT_EQ(kernel[0].offset_mm, 0.0f);
    EXPECT_FLOAT_EQ(kernel[1].offset_mm, static_cast<float>(-range));
    EXPECT_FLOAT_EQ(kernel.back().offset_mm, static_cast<float>(range));
    for (std::size_t i = 2; i < kernel.size(); ++i) EXPECT_LT(kernel[i - 1].offset_mm, kernel[i].offset_mm);
    // Mirror pairs: taps 1 + i and n - 1 - i (skipping the centre at 0).
    for (std::size_t i = 0; i < kernel.size() / 2; ++i) {
      const KernelTap& a = kernel[1 + i];
      const KernelTap& b = kernel[kernel.size() - 1 - i];
      EXPECT_FLOAT_EQ(a.offset_mm, -b.offset_mm);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.weight[c], b.weight[c], 1e-7f);
    }
  }
}

TEST(SeparableKernel, OffsetsAreDenserAtTheCentre) {
  const std::vector<double> offsets = sss::math::separable_kernel_offsets(17);
  for (std::size_t i = 9; i + 1 < offsets.size(); ++i) {
    EXPECT_LT(offsets[i] - offsets[i - 1], offsets[i + 1] - offsets[i]) << i;
  }
}

TEST(SeparableKernel, WeightsAreTheProfileIntegratedOverEachInterval) {
  const std::array<float, 3> falloff = {0.57f, 0.13f, 0.08f};
  const int n = 11;
  const std::vector<double> offsets = sss::math::separable_kernel_offsets(n);
  const auto kernel = sss::math::separable_kernel(n, {1.0f, 1.0f, 1.0f}, falloff);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> reference(offsets.size());
    double total = 0.0;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      const double lo = i == 0 ? -2.0 : 0.5 * (offsets[i - 1] + offsets[i]);
      const double hi = i + 1 == offsets.size() ? 2.0 : 0.5 * (offsets[i] + offsets[i + 1]);
      reference[i] = simpson(falloff[static_cast<std::size_t>(c)], lo, hi);
      total += reference[i];
    }
    // Spatial index i sits at kernel position: centre (i = n/2) at 0, the others shifted by one.
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      const std::size_t k = i == offsets.size() / 2 ? 0 : (i < offsets.size() / 2 ? i + 1 : i);
      EXPECT_NEAR(kernel[k].weight[static_cast<std::size_t>(c)], reference[i] / total, 2e-6) << "tap " << i;
    }
  }
}

TEST(SeparableKernel, StrengthZeroIsADeltaAndStrengthScalesTheRest) {
  const auto delta = sss::math::separable_kernel(17, {0.0f, 0.0f, 0.0f}, {0.5f, 0.5f, 0.5f});
  EXPECT_EQ(delta[0].weight[0], 1.0f);
  for (std::size_t i = 1; i < delta.size(); ++i) EXPECT_EQ(delta[i].weight[1], 0.0f);
  const auto full = sss::math::separable_kernel(17, {1.0f, 1.0f, 1.0f}, {0.5f, 0.5f, 0.5f});
  const auto half = sss::math::separable_kernel(17, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f});
  for (std::size_t i = 1; i < full.size(); ++i) EXPECT_NEAR(half[i].weight[2], 0.5f * full[i].weight[2], 1e-7f);
}

TEST(SeparableKernel, SmallerFalloffConcentratesWeightAtTheCentre) {
  const auto wide = sss::math::separable_kernel(17, {1, 1, 1}, {1.0f, 1.0f, 1.0f});
  const auto narrow = sss::math::separable_kernel(17, {1, 1, 1}, {0.1f, 0.1f, 0.1f});
  EXPECT_GT(narrow[0].weight[0], wide[0].weight[0]);
}

TEST(KernelApi, FillsTheSameTapsAsTheMathLayer) {
  const float strength[3] = {0.48f, 0.41f, 0.28f};
  const float falloff[3] = {1.0f, 0.37f, 0.3f};
  std::vector<float> rgba(25 * 4);
  ASSERT_EQ(sss_kernel_separable(25, strength, falloff, rgba.data()), SSS_OK);
  const auto kernel = sss::math::separable_kernel(25, {0.48f, 0.41f, 0.28f}, {1.0f, 0.37f, 0.3f});
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    EXPECT_EQ(rgba[i * 4 + 0], kernel[i].weight[0]);
    EXPECT_EQ(rgba[i * 4 + 3], kernel[i].offset_mm);
  }
}

TEST(KernelApi, RejectsBadArgumentsWithAMessageNamingThem) {
  const float ok[3] = {0.5f, 0.5f, 0.5f};
  std::vector<float> out(65 * 4);
  struct Case {
    int samples;
    float bad;
    const char* expected;
  };
  for (const Case& c : {Case{16, 0.5f, "taps = 16"}, Case{1, 0.5f, "taps = 1"}, Case{67, 0.5f, "taps = 67"},
                        Case{17, -0.1f, "strength[1] = -0.1"}, Case{17, NAN, "strength[1] = nan"},
                        Case{17, 1.5f, "strength[1] = 1.5"}}) {
    const float strength[3] = {0.5f, c.bad, 0.5f};
    EXPECT_EQ(sss_kernel_separable(c.samples, strength, ok, out.data()), SSS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(sss_last_error(nullptr)).find(c.expected), std::string::npos) << sss_last_error(nullptr);
  }
  EXPECT_EQ(sss_kernel_separable(17, ok, ok, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("out_rgba"), std::string::npos);
  EXPECT_EQ(sss_kernel_separable(17, nullptr, ok, out.data()), SSS_ERROR_INVALID_ARGUMENT);
  const float bad_falloff[3] = {0.5f, 0.5f, INFINITY};
  EXPECT_EQ(sss_kernel_separable(17, ok, bad_falloff, out.data()), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(nullptr)).find("falloff[2]"), std::string::npos);
}

TEST(ResultString, EveryCodeHasItsName) {
  EXPECT_STREQ(sss_result_string(SSS_OK), "SSS_OK");
  EXPECT_STREQ(sss_result_string(SSS_ERROR_INVALID_TEXTURE), "SSS_ERROR_INVALID_TEXTURE");
  EXPECT_STREQ(sss_result_string(SSS_ERROR_NO_CONTEXT), "SSS_ERROR_NO_CONTEXT");
  EXPECT_STREQ(sss_result_string(static_cast<sss_result>(SSS_ERROR_INVALID_OPERATION + 1)), "SSS_ERROR_UNKNOWN");
}

TEST(DefaultSettings, AreTheCalibratedKernelInAMetricScene) {
  // The calibrated values themselves are checked against their fit by bench.default_kernel_fit.
  sss_settings s;
  sss_default_settings(&s);
  EXPECT_EQ(s.struct_size, sizeof s);
  EXPECT_FLOAT_EQ(s.world_units_per_mm, 0.001f);
  EXPECT_FLOAT_EQ(s.scale, 1.0f);
  EXPECT_EQ(s.strength[0], sss::math::kCalibratedStrength[0]);
  EXPECT_EQ(s.falloff[2], sss::math::kCalibratedFalloff[2]);
  EXPECT_EQ(s.separable_scale, sss::math::kCalibratedSeparableScale);
  EXPECT_EQ(s.kernel, nullptr);  // eq. (1) from the settings' own strength and falloff
  EXPECT_EQ(s.taps, SSS_TAPS_MEDIUM);
  EXPECT_EQ(s.flags, SSS_FOLLOW_SURFACE);
}

}  // namespace


