// The benchmark's image metrics and PNG writers (tests/bench/metrics.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "metrics.hpp"

namespace {

using sss_bench::RgbImage;

// A smooth, non-trivial linear image (values 0.05..1.5) so SSIM has structure to compare.
RgbImage gradient_image(int w, int h) {
  RgbImage img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      img.at(x, y, 0) = 0.05 + 1.45 * x / (w - 1.0);
      img.at(x, y, 1) = 0.05 + 0.7 * (1.0 + std::sin(0.3 * x + 0.2 * y)) / 2.0;
      img.at(x, y, 2) = 0.05 + 0.5 * y / (h - 1.0);
    }
  }
  return img;
}

TEST(Metrics, IdenticalImagesHaveZeroErrorAndUnitSsim) {
  const RgbImage a = gradient_image(40, 30);
  const auto m = sss_bench::compare_images(a, a, nullptr);
  EXPECT_EQ(m.relative_rmse, 0.0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.p99_abs, 0.0);
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);  // exactly 1 up to the rounding of the filtered moments
  EXPECT_EQ(m.pixels, 40u * 30u);
}

TEST(Metrics, KnownPerturbationGivesHandComputedValues) {
  // 10 x 10 image, every component 1. Perturb 4 components: +0.5, -0.2, +0.1, +0.1 (distinct
  // pixels). n = 300 components, Σ r² = 300, Σ (a - r)² = 0.25 + 0.04 + 0.01 + 0.01 = 0.31:
  // relative RMSE = sqrt(0.31 / 300); max = 0.5; p99 by nearest rank = the ceil(0.99·300) = 297th
  // smallest of 296 zeros and {0.1, 0.1, 0.2, 0.5} sorted: 0.1.
  const RgbImage r(10, 10, 1.0);
  RgbImage a = r;
  a.at(1, 1, 0) += 0.5;
  a.at(2, 5, 1) -= 0.2;
  a.at(7, 3, 2) += 0.1;
  a.at(9, 9, 0) += 0.1;
  EXPECT_NEAR(sss_bench::relative_rmse(a, r, nullptr), std::sqrt(0.31 / 300.0), 1e-15);
  EXPECT_NEAR(sss_bench::max_abs_error(a, r, nullptr), 0.5, 1e-15);
  EXPECT_NEAR(sss_bench::percentile_abs_error(a, r, nullptr, 0.99), 0.1, 1e-15);
  // The 298th smallest is 0.1 again, the 299th 0.2, the 300th 0.5 (fraction 1: the maximum).
  EXPECT_NEAR(sss_bench::percentile_abs_error(a, r, nullptr, 299.0 / 300.0), 0.2, 1e-15);
  EXPECT_NEAR(sss_bench::percentile_abs_error(a, r, nullptr, 1.0), 0.5, 1e-15);
  EXPECT_LT(sss_bench::ssim_tonemapped(a, r, nullptr), 1.0);
}

TEST(Metrics, SsimDecreasesMonotonicallyWithNoise) {
  const RgbImage r = gradient_image(48, 48);
  std::mt19937 rng(12345u);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> noise(r.rgb.size());
  for (double& n : noise) n = normal(rng);
  double previous = 1.0;
  for (double amplitude : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4}) {
    RgbImage a = r;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) a.rgb[i] = std::max(0.0, a.rgb[i] + amplitude * noise[i]);
    const double s = sss_bench::ssim_tonemapped(a, r, nullptr);
    EXPECT_LT(s, previous) << "amplitude " << amplitude;
    EXPECT_GT(s, 0.0);
    previous = s;
  }
  EXPECT_LT(previous, 0.5);
}

TEST(Metrics, OnlySelectedPixelsCount) {
  // Errors only outside the mask: every metric sees identical images.
  const RgbImage r = gradient_image(32, 32);
  RgbImage a = r;
  std::vector<uint8_t> mask(32 * 32, 0);
  for (int y = 8; y < 24; ++y) {
    for (int x = 8; x < 24; ++x) mask[a.index(x, y)] = 1;
  }
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      if (!mask[a.index(x, y)]) a.at(x, y, 1) += 3.0;
    }
  }
  // SSIM windows reach 5 pixels beyond the mask, so the SSIM sees the outside only through them;
  // test it on a mask whose windows stay inside the unperturbed area.
  std::vector<uint8_t> inner(32 * 32, 0);
  for (int y = 13; y < 19; ++y) {
    for (int x = 13; x < 19; ++x) inner[a.index(x, y)] = 1;
  }
  const auto m = sss_bench::compare_images(a, r, mask.data());
  EXPECT_EQ(m.relative_rmse, 0.0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.p99_abs, 0.0);
  EXPECT_EQ(m.pixels, 16u * 16u);
  EXPECT_NEAR(sss_bench::ssim_tonemapped(a, r, inner.data()), 1.0, 1e-12);
  // And an error inside the mask is seen, normalised by the selected reference only.
  a.at(10, 10, 0) += 0.25;
  double sum_r2 = 0.0;
  for (int y = 8; y < 24; ++y) {
    for (int x = 8; x < 24; ++x) {
      for (int c = 0; c < 3; ++c) sum_r2 += r.at(x, y, c) * r.at(x, y, c);
    }
  }
  EXPECT_NEAR(sss_bench::relative_rmse(a, r, mask.data()), 0.25 / std::sqrt(sum_r2), 1e-15);
  EXPECT_NEAR(sss_bench::max_abs_error(a, r, mask.data()), 0.25, 1e-15);
  // Empty selection: no error, SSIM 1.
  const std::vector<uint8_t> none(32 * 32, 0);
  const auto e = sss_bench::compare_images(a, r, none.data());
  EXPECT_EQ(e.pixels, 0u);
  EXPECT_EQ(e.relative_rmse, 0.0);
  EXPECT_EQ(e.ssim, 1.0);
}

// miss (metrics.hpp): 1 for the input itself, 0 for the reference, in every channel and pooled;
// the halfway image misses half; per channel it sees what the pooled value averages away.
TEST(Metrics, MissIsOneForTheInputAndZeroForTheReference) {
  const RgbImage reference = gradient_image(32, 24);
  RgbImage input = reference;
  for (std::size_t i = 0; i < input.rgb.size(); ++i) input.rgb[i] += 0.1 * std::sin(0.7 * static_cast<double>(i));
  const auto nothing = sss_bench::miss_share(input, reference, input, nullptr);
  const auto exact = sss_bench::miss_share(reference, reference, input, nullptr);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(nothing.channel[c], 1.0) << c;
    EXPECT_EQ(exact.channel[c], 0.0) << c;
  }
  EXPECT_EQ(nothing.pooled, 1.0);
  EXPECT_EQ(exact.pooled, 0.0);
  EXPECT_EQ(nothing.pixels, 32u * 24u);

  RgbImage halfway = reference;
  for (std::size_t i = 0; i < halfway.rgb.size(); ++i) halfway.rgb[i] = 0.5 * (input.rgb[i] + reference.rgb[i]);
  EXPECT_NEAR(sss_bench::miss_share(halfway, reference, input, nullptr).pooled, 0.5, 1e-12);

  // Only blue made worse, three times as far as the input: pooled ~1, blue 3, the others 0.
  RgbImage blue_worse = reference;
  for (std::size_t i = 2; i < blue_worse.rgb.size(); i += 3) blue_worse.rgb[i] = reference.rgb[i] + 3.0 * (input.rgb[i] - reference.rgb[i]);
  const auto m = sss_bench::miss_share(blue_worse, reference, input, nullptr);
  EXPECT_EQ(m.channel[0], 0.0);
  EXPECT_NEAR(m.channel[2], 3.0, 1e-12);
  EXPECT_NEAR(m.worst_channel(), 3.0, 1e-12);
  EXPECT_LT(m.pooled, 3.0);
}

TEST(Metrics, MissWithNothingToChangeOrNothingSelected) {
  const RgbImage reference = gradient_image(8, 8);
  RgbImage off = reference;
  off.rgb[0] += 0.5;
  // The input is already the reference: a result equal to it misses nothing, any other infinitely much.
  EXPECT_EQ(sss_bench::miss_share(reference, reference, reference, nullptr).pooled, 0.0);
  EXPECT_TRUE(std::isinf(sss_bench::miss_share(off, reference, reference, nullptr).pooled));
  const std::vector<uint8_t> none(64, 0);
  const auto empty = sss_bench::miss_share(off, reference, off, none.data());
  EXPECT_TRUE(std::isnan(empty.pooled));
  EXPECT_EQ(empty.pixels, 0u);
  // Only the selected pixels count: the changed pixel left out, nothing is left to miss.
  std::vector<uint8_t> mask(64, 1);
  mask[0] = 0;
  EXPECT_EQ(sss_bench::miss_share(off, reference, off, mask.data()).pooled, 0.0);
}

TEST(Metrics, ToneMapAndRamp) {
  EXPECT_EQ(sss_bench::tone_map(0.0), 0.0);
  EXPECT_EQ(sss_bench::tone_map(-1.0), 0.0);
  EXPECT_NEAR(sss_bench::tone_map(1e6), 1.0, 1e-15);  // 1.055 · 1 - 0.055 in doubles
  // x = 1: ACES fit 2.54 / 3.16 = 0.80380..., sRGB-encoded 1.055 · 0.80380^(1/2.4) - 0.055.
  const double aces = 2.54 / 3.16;
  EXPECT_NEAR(sss_bench::tone_map(1.0), 1.055 * std::pow(aces, 1.0 / 2.4) - 0.055, 1e-12);
  EXPECT_NEAR(sss_bench::tone_map(0.5, 2.0), sss_bench::tone_map(1.0), 1e-15);
  double previous = -1.0;
  for (double x = 0.0; x <= 20.0; x += 0.01) {  // monotone
    const double t = sss_bench::tone_map(x);
    EXPECT_GE(t, previous);
    previous = t;
  }
  const auto lo = sss_bench::error_ramp(0.0), hi = sss_bench::error_ramp(1.0), over = sss_bench::error_ramp(7.0);
  EXPECT_EQ(lo, (std::array<uint8_t, 3>{68, 1, 84}));
  EXPECT_EQ(hi, (std::array<uint8_t, 3>{253, 231, 37}));
  EXPECT_EQ(over, hi);
  // Luma increases along the ramp (readable in grey).
  double luma_before = -1.0;
  for (int i = 0; i <= 64; ++i) {
    const auto c = sss_bench::error_ramp(i / 64.0);
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luma, luma_before) << i;
    luma_before = luma;
  }
}

TEST(Metrics, WritesPngs) {
  const RgbImage r = gradient_image(24, 16);
  RgbImage a = r;
  a.at(3, 4, 0) += 0.3;
  const std::string dir = ::testing::TempDir();
  const std::string heat = dir + "sss_metrics_heat.png", tone = dir + "sss_metrics_tone.png";
  ASSERT_TRUE(sss_bench::write_error_heatmap_png(heat, a, r, nullptr, 0.3));
  ASSERT_TRUE(sss_bench::write_tonemapped_png(tone, r));
  for (const std::string& path : {heat, tone}) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    ASSERT_NE(f, nullptr) << path;
    unsigned char signature[8] = {};
    EXPECT_EQ(std::fread(signature, 1, 8, f), 8u);
    std::fclose(f);
    EXPECT_EQ(signature[1], 'P');
    EXPECT_EQ(signature[2], 'N');
    EXPECT_EQ(signature[3], 'G');
    std::remove(path.c_str());
  }
  EXPECT_THROW(sss_bench::relative_rmse(a, RgbImage(3, 3), nullptr), std::invalid_argument);
}

}  // namespace
