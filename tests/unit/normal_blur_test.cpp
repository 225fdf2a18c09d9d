// The normal-map pre-blur of the pre-integrated path (math/normal_blur.*, used by tools/blur_normals
// and the benchmark's pre-integrated head): a constant map is a fixed point, every output is a unit
// normal, and a step between two normals spreads exactly as the profile's 1D step response says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "math/normal_blur.hpp"
#include "math/radial_profile.hpp"

namespace {

using sss::math::blur_normal_map;

std::uint8_t encode(double v) { return static_cast<std::uint8_t>(std::lround((v * 0.5 + 0.5) * 255.0)); }
double decode(std::uint8_t b) { return b / 255.0 * 2.0 - 1.0; }

TEST(NormalBlur, AConstantMapStaysConstant) {
  const int w = 40, h = 30;
  const double n[3] = {0.3, -0.2, std::sqrt(1.0 - 0.09 - 0.04)};
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = encode(n[i % 3]);
  const auto out = blur_normal_map(rgb, w, h, 0.1, sss::math::deon_skin_profile(), 0);
  ASSERT_EQ(out.size(), rgb.size());
  // Renormalising a normal that was only quantised moves a byte by at most one step.
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_LE(std::abs(int(out[i]) - int(rgb[i])), 1) << i;
}

TEST(NormalBlur, OutputsAreUnitNormalsAndAStepSpreadsAsTheProfileSays) {
  // Two normals tilted ±a about y meet at column x0. Linear filtering of vectors (what the paper
  // adopts) gives x = a·(2F − 1), z = c, with F the profile's 1D step response Σ w_i Φ(d / σ_i)
  // for the red channel's Gaussians; then the vector is renormalised.
  const int w = 1400, h = 3, x0 = 700;
  const double texel_mm = 0.02;  // the narrowest red Gaussian (σ = 0.08 mm) spans 4 texels
  const double a = 0.6, c = 0.8;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &rgb[3 * static_cast<std::size_t>(y * w + x)];
      p[0] = encode(x < x0 ? -a : a);
      p[1] = encode(0.0);
      p[2] = encode(c);
    }
  }
  const auto& profile = sss::math::deon_skin_profile();
  const auto out = blur_normal_map(rgb, w, h, texel_mm, profile, 0);
  ASSERT_EQ(out.size(), rgb.size());
  const auto* terms = profile.gaussian_terms();
  ASSERT_NE(terms, nullptr);
  double weight_total = 0.0;
  for (const auto& t : *terms) weight_total += t.weight[0];
  const double quantum = 2.0 / 255.0;
  // The encoded input is not exactly (±a, 0, c): use what the bytes hold.
  const double a_in = decode(encode(a)), c_in = decode(encode(c));
  double largest_error = 0.0;
  for (int x = x0 - 150; x < x0 + 150; ++x) {
    const std::uint8_t* p = &out[3 * static_cast<std::size_t>(w + x)];  // the middle row
    const double n[3] = {decode(p[0]), decode(p[1]), decode(p[2])};
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 2.0 * quantum) << x;
    const double d = (x + 0.5 - x0) * texel_mm;
    double f = 0.0;
    for (const auto& t : *terms) f += t.weight[0] / weight_total * 0.5 * std::erfc(-d / std::sqrt(2.0 * t.variance_mm2));
    const double vx = a_in * (2.0 * f - 1.0), length = std::sqrt(vx * vx + c_in * c_in);
    largest_error = std::max(largest_error, std::abs(n[0] - vx / length));
    EXPECT_NEAR(n[0], vx / length, 1.5 * quantum) << "x = " << x << ", d = " << d << " mm";
  }
  RecordProperty("largest_error", std::to_string(largest_error));
}

TEST(NormalBlur, BlendFactorsFollowTheScatteringRadius) {
  // Red scatters furthest: its factor is 1, green's and blue's are smaller (1, 0.22, 0.13 for skin).
  const auto f = sss::math::normal_blend_factors(sss::math::deon_skin_profile(), 0);
  EXPECT_DOUBLE_EQ(f[0], 1.0);
  EXPECT_GT(f[0], f[1]);
  EXPECT_GT(f[1], f[2]);
  EXPECT_GT(f[2], 0.0);
}

}  // namespace
