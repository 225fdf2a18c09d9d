// Radial profiles (math/radial_profile.hpp): the skin Gaussians, the dipole, tabulated data.
#include <gtest/gtest.h>

#include <cmath>

#include "math/materials.hpp"
#include "math/radial_profile.hpp"

namespace {

using sss::math::DipoleProfile;
using sss::math::GaussianSumProfile;
using sss::math::Rgb;
using sss::math::TabulatedProfile;

TEST(Materials, ElevenInTheSupplementaryOrderWithLookup) {
  const auto& m = sss::math::measured_materials();
  ASSERT_EQ(m.size(), 11u);
  EXPECT_STREQ(m[0].name, "apple");
  EXPECT_STREQ(m[10].name, "wholemilk");
  EXPECT_EQ(sss::math::material_index("marble"), 5);
  EXPECT_DOUBLE_EQ(m[5].eta, 1.5);
  EXPECT_EQ(sss::math::material_index("glass"), -1);
}

TEST(GaussianSumProfile, FirstNTermsRenormalisedIntegrateToOne) {
  for (int n = 1; n <= 6; ++n) {
    const auto p = GaussianSumProfile::skin(n);
    ASSERT_EQ(p.terms().size(), static_cast<std::size_t>(n));
    const Rgb total = p.integral();
    // Numeric quadrature out to the extent (1e-4 left outside by construction) checks evaluate().
    const Rgb numeric = sss::math::encircled_numeric(p, p.extent_mm());
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(total[c], 1.0, 1e-12) << "n=" << n;
      EXPECT_NEAR(numeric[c], 1.0, 2e-4) << "n=" << n << " c=" << c;
    }
  }
}

TEST(DipoleProfile, TotalReflectanceMatchesJensensClosedForm) {
  // Jensen et al. 2001 eq. 6 (their total diffuse reflectance), an independent expression.
  for (const auto& m : sss::math::measured_materials()) {
    const DipoleProfile p(m);
    const double fdr = sss::math::fresnel_diffuse_reflectance(m.eta);
    const double a = (1.0 + fdr) / (1.0 - fdr);
    for (std::size_t c = 0; c < 3; ++c) {
      const double albedo = m.sigma_s_per_mm[c] / (m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c]);
      const double s = std::sqrt(3.0 * (1.0 - albedo));
      const double expected = 0.5 * albedo * (1.0 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
      EXPECT_NEAR(p.integral()[c], expected, 1e-12) << m.name << " c=" << c;
    }
  }
}

TEST(DipoleProfile, ClosedFormEncircledEnergyMatchesQuadratureOfTheProfile) {
  for (const auto& m : sss::math::measured_materials()) {
    const DipoleProfile p(m);
    for (double r : {0.1, 1.0, 10.0, p.extent_mm()}) {
      const Rgb exact = p.encircled(r);
      const Rgb numeric = sss::math::encircled_numeric(p, r);
      for (std::size_t c = 0; c < 3; ++c) {
        // Simpson with 4000 intervals on the r = s² axis: relative error well below 1e-6.
        EXPECT_NEAR(numeric[c], exact[c], 1e-6 * exact[c] + 1e-12) << m.name << " r=" << r << " c=" << c;
      }
    }
    const Rgb at_extent = p.encircled(p.extent_mm());
    for (std::size_t c = 0; c < 3; ++c) EXPECT_LE(1.0 - at_extent[c] / p.integral()[c], 1.0001e-4);
  }
}

TEST(DipoleProfile, PositiveAndDecreasing) {
  const DipoleProfile p(sss::math::measured_materials()[8]);  // skin1
  Rgb last = p.evaluate(0.0);
  for (double r = 0.01; r < 20.0; r *= 1.2) {
    const Rgb v = p.evaluate(r);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_GT(v[c], 0.0);
      EXPECT_LT(v[c], last[c]);
    }
    last = v;
  }
}

TEST(TabulatedProfile, InterpolatesLinearlyZeroBeyondAndIntegratesExactly) {
  const TabulatedProfile p({0.0, 1.0, 3.0}, {{2.0, 1.0, 0.0}, {1.0, 1.0, 1.0}, {0.0, 0.5, 1.0}});
  EXPECT_DOUBLE_EQ(p.evaluate(0.5)[0], 1.5);
  EXPECT_DOUBLE_EQ(p.evaluate(2.0)[1], 0.75);
  EXPECT_DOUBLE_EQ(p.evaluate(3.0)[2], 1.0);
  EXPECT_EQ(p.evaluate(3.0001)[2], 0.0);
  const Rgb exact = p.integral();
  const Rgb numeric = sss::math::encircled_numeric(p, 3.0);
  for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(numeric[c], exact[c], 1e-6 * exact[c]);
  EXPECT_THROW(TabulatedProfile({1.0, 1.0}, {{1, 1, 1}, {1, 1, 1}}), std::invalid_argument);
  EXPECT_THROW(TabulatedProfile({1.0}, {}), std::invalid_argument);
}

}  // namespace
