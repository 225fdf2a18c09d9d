// The cross-bilateral mode's math: tap placement by the inverse CDF, per-channel weights, the
// spike blend, the footprint cosine, the transmittance terms, and the CPU model's invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/cbf_constants.hpp"
#include "math/cbf_kernel.hpp"
#include "math/cpu_cbf_filter.hpp"
#include "math/spike_gaussian_profile.hpp"
#include "sss/sss_tools.h"
#include "synthetic_scene.hpp"

namespace {

using namespace sss::math;

TEST(SpikeGaussianProfile, EachChannelSumsToOne) {
  for (const SpikeGaussianProfile& p : {mikkelsen_profile(), skin_spike_gaussian_profile()}) {
    for (int c = 0; c < 3; ++c) {
      double sum = p.spike[static_cast<std::size_t>(c)];
      for (const GaussianTerm& t : p.terms) sum += t.weight[static_cast<std::size_t>(c)];
      EXPECT_NEAR(sum, 1.0, 1e-12) << p.name << " channel " << c;
    }
  }
  EXPECT_DOUBLE_EQ(broad_variance_mm2(mikkelsen_profile(), 0), 2.3);
  EXPECT_DOUBLE_EQ(broad_variance_mm2(mikkelsen_profile(), 2), 1.1);
}

TEST(CbfKernel, TapsSplitRedProbabilityEvenly) {
  const SpikeGaussianProfile p = mikkelsen_profile();
  std::vector<double> bounds;
  const std::vector<double> offsets = cbf_tap_offsets(p, 13, 4.5, &bounds);
  ASSERT_EQ(offsets.size(), 13u);
  ASSERT_EQ(bounds.size(), 14u);
  EXPECT_EQ(bounds.front(), -4.5);
  EXPECT_EQ(bounds.back(), 4.5);
  EXPECT_EQ(offsets[6], 0.0);
  const double total = broad_marginal_integral(p, 0, -4.5, 4.5);
  for (int i = 0; i < 13; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_LT(bounds[k], offsets[k]);
    EXPECT_LT(offsets[k], bounds[k + 1]);
    EXPECT_NEAR(broad_marginal_integral(p, 0, bounds[k], bounds[k + 1]) / total, 1.0 / 13.0, 1e-9);
    // The tap is the interval's probability midpoint.
    EXPECT_NEAR(broad_marginal_integral(p, 0, bounds[k], offsets[k]) / total, 0.5 / 13.0, 1e-9);
    EXPECT_NEAR(offsets[k], -offsets[12 - k], 1e-12);
  }
  // The red Gaussian (sigma 1.52 mm): the outermost tap's probability midpoint 1/26 lies near
  // -1.77 sigma of the truncated distribution.
  EXPECT_NEAR(offsets[0], -2.6, 0.1);
}

TEST(CbfKernel, WeightsSpikeAndVariances) {
  const CbfKernel k = cbf_kernel(mikkelsen_profile(), 13, 4.5);
  ASSERT_EQ(k.taps.size(), 13u);
  EXPECT_EQ(k.taps[0].offset_mm, 0.0f);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const KernelTap& t : k.taps) sum += t.weight[static_cast<std::size_t>(c)];
    EXPECT_NEAR(sum, 1.0, 1e-6);
  }
  for (std::size_t i = 2; i < k.taps.size(); ++i) EXPECT_LT(k.taps[i - 1].offset_mm, k.taps[i].offset_mm);
  // Red: 1/13 each. Narrower green and blue: more weight at the centre, less at the ends.
  for (const KernelTap& t : k.taps) EXPECT_NEAR(t.weight[0], 1.0 / 13.0, 1e-6);
  EXPECT_GT(k.taps[0].weight[2], k.taps[0].weight[1]);
  EXPECT_GT(k.taps[0].weight[1], k.taps[0].weight[0]);
  EXPECT_LT(k.taps[1].weight[2], k.taps[1].weight[0]);
  // Two passes of (b, 1-b) leave exactly 1 - spike fully 2D-filtered.
  const double spikes[3] = {0.15, 0.18, 0.20};
  const double variances[3] = {2.3, 1.4, 1.1};
  for (int c = 0; c < 3; ++c) {
    const double b = k.spike_blend[static_cast<std::size_t>(c)];
    EXPECT_NEAR((1.0 - b) * (1.0 - b), 1.0 - spikes[c], 1e-6);
    EXPECT_NEAR(k.inv_two_variance[static_cast<std::size_t>(c)], 1.0 / (2.0 * variances[c]), 1e-6);
  }
}

TEST(CbfKernel, AnyProfilePlugsIn) {
  // The six-Gaussian skin profile and a wide r_max, many taps: still a valid kernel.
  const CbfKernel k = cbf_kernel(skin_spike_gaussian_profile(), 65, 8.0);
  ASSERT_EQ(k.taps.size(), 65u);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const KernelTap& t : k.taps) {
      EXPECT_GE(t.weight[static_cast<std::size_t>(c)], 0.0f);
      sum += t.weight[static_cast<std::size_t>(c)];
    }
    EXPECT_NEAR(sum, 1.0, 1e-5);
  }
  EXPECT_GT(k.taps.back().offset_mm, 2.0f);
  EXPECT_LT(k.taps.back().offset_mm, 8.0f);
}

TEST(CbfConstants, FootprintCosine) {
  EXPECT_FLOAT_EQ(footprint_cosine(1.0f, 0.0f, 0.0f, 1.0f), 1.0f);  // facing the eye
  EXPECT_NEAR(footprint_cosine(std::cos(1.0472f), std::sin(1.0472f), 0.0f, 1.0f), 0.5f, 1e-4f);  // 60° tilt
  EXPECT_NEAR(footprint_cosine(0.0f, 1.0f, 0.0f, 1.0f), 0.0f, 1e-7f);  // seen edge-on
  EXPECT_FLOAT_EQ(footprint_cosine(0.0f, 0.0f, 0.0f, 1.0f), 1.0f);    // degenerate tangent: no correction
}

TEST(Transmittance, TermsComeFromTheProfile) {
  float terms[4 * SSS_PROFILE_MAX_TERMS];
  int32_t count = 0;
  ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_SKIN_DEON, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK);
  ASSERT_EQ(count, 6);  // the spike has a width (0.0064 mm²): it transmits too
  const auto& g = skin_gaussians();
  for (int i = 0; i < 6; ++i) {
    EXPECT_FLOAT_EQ(terms[i * 4], static_cast<float>(g[static_cast<std::size_t>(i)].variance_mm2));
    EXPECT_FLOAT_EQ(terms[i * 4 + 1], static_cast<float>(g[static_cast<std::size_t>(i)].weight[0]));
  }
  ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_MIKKELSEN_2010, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK);
  EXPECT_EQ(count, 3);  // a true delta transmits nothing
  EXPECT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_SKIN_DEON, terms, 5, &count), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(count, 6);
  EXPECT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_TABULATED, terms, 8, &count), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_profile_transmittance_terms(0, nullptr, 8, &count), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_profile_transmittance_terms(0, terms, 8, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  // At zero thickness the skin profile transmits all of each channel (weights sum to 1).
  const auto t = transmittance_terms(skin_spike_gaussian_profile());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(transmittance(t, c, 0.0), 1.0, 1e-12);
  EXPECT_LT(transmittance(t, 2, 1.0), transmittance(t, 0, 1.0));  // red travels furthest
}

// The CPU model's invariants: a flat, facing, uniform image stays the same (normalised weights);
// on a plane tilted about the y axis the cosine correction keeps the blur a function of the
// distance along the surface (no over-attenuation from the range Gaussian).
TEST(CpuCbfFilter, FlatStaysFlatAndTiltedPlaneIsBlurred) {
  const auto projection = sss_test::perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
  sss_test::SyntheticScene s = sss_test::make_flat_scene(32, 32, {0.3f, 0.5f, 0.7f, 1.0f}, 1.0f, projection);
  FilterSettings fs;
  fs.world_units_per_mm = 0.03f;
  FrameGeometry g;
  g.texture_width = g.texture_height = 32;
  g.viewport = {0, 0, 32, 32};
  const PassConstants k = compute_pass_constants(fs, projection, g);
  const CbfConstants c = compute_cbf_constants(fs, projection, g);
  const CbfKernel kernel = cbf_kernel(mikkelsen_profile(), 13, 4.5);
  CpuFilterImage image;
  image.width = image.height = 32;
  image.color = s.color.data();
  image.depth = s.window_depth.data();
  std::vector<float> out(s.color.size());
  cpu_cbf_filter(kernel, k, c, image, out.data());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], s.color[i], 2e-3f * s.color[i]);  // fp16 intermediate

  // A vertical stripe pattern on a plane tilted 60° about y: blurred (stripes lose contrast).
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 32 + x;
      s.distance[i] = 1.0f + 0.02f * static_cast<float>(x) * std::tan(1.0472f) / 1.0f * 0.5f;
      s.color[i * 4] = (x % 2 == 0) ? 1.0f : 0.0f;
    }
  }
  sss_test::compute_window_depth(&s);
  cpu_cbf_filter(kernel, k, c, image, out.data());
  const std::size_t mid = (16 * 32 + 16) * 4;
  EXPECT_GT(out[mid + 4], 0.2f);   // an odd (dark) column picks up light from its neighbours
  EXPECT_LT(out[mid], 0.8f);       // an even (bright) column loses some
}

}  // namespace

// The measured materials reach the cross-bilateral mode through 4a's sum-of-Gaussians fit of their
// dipole: every id of sss_material but TABULATED is a profile, with each channel summing to 1.
TEST(SpikeGaussianProfile, MeasuredMaterialsAreFittedGaussianSums) {
  EXPECT_TRUE(is_spike_gaussian_profile_id(SSS_PROFILE_MIKKELSEN_2010));
  EXPECT_TRUE(is_spike_gaussian_profile_id(SSS_PROFILE_WHOLEMILK));
  EXPECT_FALSE(is_spike_gaussian_profile_id(SSS_PROFILE_TABULATED));
  const SpikeGaussianProfile p = spike_gaussian_profile(SSS_PROFILE_MARBLE);
  EXPECT_EQ(p.name, "marble");
  ASSERT_EQ(p.terms.size(), static_cast<std::size_t>(SSS_PROFILE_FIT_GAUSSIANS));
  for (int c = 0; c < 3; ++c) {
    double sum = p.spike[static_cast<std::size_t>(c)];
    for (const GaussianTerm& t : p.terms) sum += t.weight[static_cast<std::size_t>(c)];
    EXPECT_NEAR(sum, 1.0, 1e-9);  // the fit's L1 constraint, up to the optimiser's tolerance on a sum
  }
  // Red scatters furthest in marble (smallest σa, Jensen et al. 2001): its broad variance is the largest.
  EXPECT_GT(broad_variance_mm2(p, 0), broad_variance_mm2(p, 2));
  const CbfKernel k = cbf_kernel(p, 13, 8.0);
  EXPECT_EQ(k.taps.size(), 13u);
  float terms[4 * SSS_PROFILE_MAX_TERMS];
  int32_t count = 0;
  ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_MARBLE, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK);
  EXPECT_EQ(count, SSS_PROFILE_FIT_GAUSSIANS);  // no spike: every fitted term transmits
  for (int i = 0; i < count; ++i) EXPECT_GT(terms[i * 4], 0.0f);
}
