// The cross-bilateral mode's math: each channel's broad marginal tabulated for the footprint-aware
// taps, the spike blend, the transmittance terms, and the CPU model's invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

TEST(CbfKernel, EachChannelsBroadMarginalIsTabulatedOnRMax) {
  // Mikkelsen's profile: one broad Gaussian per channel (2.3, 1.4, 1.1 mm²) truncated to ±4.5 mm,
  // each channel's table normalised to half its mass on [0, 4.5].
  const SpikeGaussianProfile p = mikkelsen_profile();
  const CbfKernel k = cbf_kernel(p, 13, 4.5);
  EXPECT_FLOAT_EQ(k.table.reach_mm, 4.5f);
  ASSERT_EQ(k.table.half_cdf.size(), static_cast<std::size_t>(kFootprintEntries));
  EXPECT_EQ(k.spacing, footprint_spacing(6, sss::math::FootprintLayout::cubic));  // 13 taps: 6 on either side
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(k.table.half_cdf.back()[c], 0.5f);
    EXPECT_EQ(k.table.delta[c], 0.0f);  // the spike is the blend, not a delta in the table
    // C(x) at 1 mm: the Gaussian's mass on [0, 1] over its mass on [0, 4.5].
    const double expected = 0.5 * broad_marginal_integral(p, static_cast<int>(c), 0.0, 1.0) /
                            broad_marginal_integral(p, static_cast<int>(c), 0.0, 4.5);
    EXPECT_NEAR(footprint_half_cdf(k.table, 1.0f)[c], expected, 2e-4);
  }
  // Narrower green and blue hold more of their mass near the centre.
  const auto near = footprint_half_cdf(k.table, 0.5f);
  EXPECT_GT(near[2], near[1]);
  EXPECT_GT(near[1], near[0]);
}

TEST(CbfKernel, SpikeBlendAndVariances) {
  const CbfKernel k = cbf_kernel(mikkelsen_profile(), 13, 4.5);
  // Each pass keeps the spike's share at the centre: the whole profile's 1D marginal per pass.
  const double spikes[3] = {0.15, 0.18, 0.20};
  const double variances[3] = {2.3, 1.4, 1.1};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(k.spike_blend[static_cast<std::size_t>(c)], spikes[c], 1e-6);
    EXPECT_NEAR(k.inv_two_variance[static_cast<std::size_t>(c)], 1.0 / (2.0 * variances[c]), 1e-6);
  }
}

TEST(CbfKernel, TheTapsWeighTheMarginalOverTheirPixels) {
  // d'Eon's skin, the spike its narrowest term: blue's broad part is almost all the 0.0484 mm²
  // Gaussian (sigma 0.22 mm). At 1 mm per pixel the pixel beside the centre holds the blue marginal's
  // mass between 0.5 and 1.5 mm (about 1.2 % on either side); Mikkelsen's importance-placed taps
  // read there with their interval's mass, 4.1 % (docs/surface-turns.md).
  const SpikeGaussianProfile p = skin_spike_gaussian_profile();
  const CbfKernel k = cbf_kernel(p, 13, 8.0);
  const FootprintTaps taps = footprint_taps(k.table, k.spacing, 1.0f);  // 1 pixel per mm
  ASSERT_GE(taps.count, 1);
  ASSERT_EQ(taps.position[0], 1);
  const double total = broad_marginal_integral(p, 2, -8.0, 8.0);
  const double beside = broad_marginal_integral(p, 2, 0.5, 1.5) / total;
  EXPECT_NEAR(taps.weight[1][2], beside, 2e-3);
  EXPECT_LT(taps.weight[1][2], 0.02f);
  for (int c = 0; c < 3; ++c) {
    double sum = taps.weight[0][static_cast<std::size_t>(c)];
    for (int i = 1; i <= taps.count; ++i) sum += 2.0 * taps.weight[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
    EXPECT_NEAR(sum, 1.0, 1e-5) << "channel " << c;
  }
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

// The CPU model's invariants: a flat, facing, uniform image stays the same (normalised weights); a
// stripe pattern on a plane turned 60 degrees about y is blurred, by the walk's footprint along
// the surface (the range Gaussian takes nothing from a plane).
TEST(CpuCbfFilter, FlatStaysFlatAndATurnedPlaneIsBlurred) {
  const auto projection = sss_test::perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
  sss_test::SyntheticScene s = sss_test::make_flat_scene(32, 32, {0.3f, 0.5f, 0.7f, 1.0f}, 1.0f, projection);
  FilterSettings fs;
  fs.world_units_per_mm = 0.03f;
  FrameGeometry g;
  g.texture_width = g.texture_height = 32;
  g.viewport = {0, 0, 32, 32};
  const PassConstants k = compute_pass_constants(fs, projection, g);
  const CbfKernel kernel = cbf_kernel(mikkelsen_profile(), 13, 4.5);
  CpuFilterImage image;
  image.width = image.height = 32;
  image.color = s.color.data();
  image.depth = s.window_depth.data();
  std::vector<float> out(s.color.size());
  cpu_cbf_filter(kernel, k, image, out.data());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], s.color[i], 2e-3f * s.color[i]);  // fp16 intermediate

  s = sss_test::make_turned_plane_scene(32, 32, 60.0, 90.0, 1.0, projection, 5);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) s.color[(static_cast<std::size_t>(y) * 32 + x) * 4] = (x % 2 == 0) ? 1.0f : 0.0f;
  }
  image.color = s.color.data();
  image.depth = s.window_depth.data();
  cpu_cbf_filter(kernel, k, image, out.data());
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
  for (std::size_t c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(k.table.half_cdf.back()[c], 0.5f);
  float terms[4 * SSS_PROFILE_MAX_TERMS];
  int32_t count = 0;
  ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_MARBLE, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK);
  EXPECT_EQ(count, SSS_PROFILE_FIT_GAUSSIANS);  // no spike: every fitted term transmits
  for (int i = 0; i < count; ++i) EXPECT_GT(terms[i * 4], 0.0f);
}
