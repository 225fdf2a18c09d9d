// SSS_PROFILE_BURLEY through the tools API (sss_tools.h): the desc's burley fields reach the math,
// the measured materials' parameters come from their dipoles, bad fields are refused by name with
// nothing written, every kernel family builds from the profile, and 0.1-0.3's smaller descs are
// still read (their missing burley fields at the defaults).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "math/burley_profile.hpp"
#include "math/spike_gaussian_profile.hpp"
#include "sss/sss_tools.h"

namespace {

std::string last() { return sss_last_error(nullptr); }

sss_profile_desc burley(float a0, float a1, float a2, float l0, float l1, float l2) {
  sss_profile_desc p;
  sss_default_profile_desc(&p);
  p.profile = SSS_PROFILE_BURLEY;
  p.burley_albedo[0] = a0, p.burley_albedo[1] = a1, p.burley_albedo[2] = a2;
  p.burley_dmfp_mm[0] = l0, p.burley_dmfp_mm[1] = l1, p.burley_dmfp_mm[2] = l2;
  return p;
}

TEST(BurleyApi, NameDefaultsAndMeasuredMaterials) {
  EXPECT_STREQ(sss_profile_name(SSS_PROFILE_BURLEY), "burley");
  EXPECT_EQ(SSS_PROFILE_COUNT, SSS_PROFILE_BURLEY + 1);
  sss_profile_desc d;
  sss_default_profile_desc(&d);
  const auto skin1 = sss::math::burley_default_parameters();
  for (int32_t m = SSS_PROFILE_APPLE; m <= SSS_PROFILE_WHOLEMILK; ++m) {
    sss_profile_desc p{};
    ASSERT_EQ(sss_profile_burley_from_measured(m, &p), SSS_OK) << last();
    EXPECT_EQ(p.struct_size, sizeof p);
    EXPECT_EQ(p.profile, SSS_PROFILE_BURLEY);
    const auto b = sss::math::burley_from_material(sss::math::measured_materials()[static_cast<std::size_t>(m - 1)]);
    float integral[3] = {};
    ASSERT_EQ(sss_profile_integral(&p, integral), SSS_OK) << last();
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(p.burley_albedo[c], static_cast<float>(b.albedo[c])) << sss_profile_name(m);
      EXPECT_EQ(p.burley_dmfp_mm[c], static_cast<float>(b.dmfp_mm[c])) << sss_profile_name(m);
      EXPECT_FLOAT_EQ(integral[c], p.burley_albedo[c]);  // ∫∫ R = A
      if (m == SSS_PROFILE_SKIN1) {  // the default desc's burley fields are skin1's
        EXPECT_EQ(d.burley_albedo[c], static_cast<float>(skin1.albedo[c]));
        EXPECT_EQ(p.burley_dmfp_mm[c], d.burley_dmfp_mm[c]);
      }
    }
  }
  sss_profile_desc untouched;
  untouched.profile = -9;
  for (int32_t bad : {0, 12, 15, -1}) {
    EXPECT_EQ(sss_profile_burley_from_measured(bad, &untouched), SSS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("material = " + std::to_string(bad)), std::string::npos) << last();
    EXPECT_EQ(untouched.profile, -9);
  }
  EXPECT_EQ(sss_profile_burley_from_measured(SSS_PROFILE_MARBLE, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("out is NULL"), std::string::npos);
}

TEST(BurleyApi, EvaluateIsTheMemosFormula) {
  const sss_profile_desc p = burley(0.8f, 0.5f, 0.2f, 2.0f, 1.0f, 0.5f);
  const float r[3] = {0.0f, 0.1f, 3.0f};
  float out[9] = {};
  ASSERT_EQ(sss_profile_evaluate(&p, 3, r, out), SSS_OK) << last();
  for (int c = 0; c < 3; ++c) {
    const double a = p.burley_albedo[c], s = 3.5 + 100.0 * std::pow(a - 0.33, 4.0);
    const double d = static_cast<double>(p.burley_dmfp_mm[c]) / s;
    EXPECT_TRUE(std::isinf(out[c]));  // the 1/r at the centre
    for (int i = 1; i < 3; ++i) {
      const double x = r[i];
      const double expected = a * (std::exp(-x / d) + std::exp(-x / (3.0 * d))) / (8.0 * M_PI * d * x);
      EXPECT_NEAR(out[i * 3 + c], expected, 1e-6 * expected) << x << " mm, channel " << c;
    }
  }
}

TEST(BurleyApi, BadFieldsAreNamedAndWriteNothing) {
  struct Bad {
    const char* what;
    sss_profile_desc p;
  };
  const Bad cases[] = {
      {"profile->burley_albedo[1] = 0", burley(0.5f, 0.0f, 0.5f, 1, 1, 1)},
      {"profile->burley_albedo[0] = 1.5", burley(1.5f, 0.5f, 0.5f, 1, 1, 1)},
      {"profile->burley_albedo[2] = nan", burley(0.5f, 0.5f, NAN, 1, 1, 1)},
      {"profile->burley_dmfp_mm[0] = 0", burley(0.5f, 0.5f, 0.5f, 0, 1, 1)},
      {"profile->burley_dmfp_mm[1] = 0.0001", burley(0.5f, 0.5f, 0.5f, 1, 1e-4f, 1)},
      {"profile->burley_dmfp_mm[2] = 2000", burley(0.5f, 0.5f, 0.5f, 1, 1, 2000)},
      {"profile->burley_dmfp_mm[2] = inf", burley(0.5f, 0.5f, 0.5f, 1, 1, INFINITY)},
  };
  for (const Bad& b : cases) {
    float out[3] = {7, 7, 7};
    EXPECT_EQ(sss_profile_integral(&b.p, out), SSS_ERROR_INVALID_ARGUMENT) << b.what;
    EXPECT_NE(last().find(b.what), std::string::npos) << "'" << last() << "' should name " << b.what;
    EXPECT_EQ(out[0], 7.0f);
    // The same through a kernel desc, named from the desc.
    sss_kernel_desc d;
    sss_default_kernel_desc(&d);
    d.family = SSS_KERNEL_PREINTEGRATED;
    d.profile = b.p;
    std::vector<float> taps(SSS_KERNEL_MAX_TERMS * 2 * 17 * 4, -7.0f);
    int32_t terms = -3;
    EXPECT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, taps.data(), nullptr, &terms, nullptr),
              SSS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find(std::string("desc->") + b.what), std::string::npos) << last();
    EXPECT_EQ(terms, -3);
    EXPECT_EQ(taps[0], -7.0f);
  }
  // The burley fields are read only for SSS_PROFILE_BURLEY.
  sss_profile_desc skin = cases[0].p;
  skin.profile = SSS_PROFILE_SKIN_DEON;
  float out[3];
  EXPECT_EQ(sss_profile_integral(&skin, out), SSS_OK) << last();
  // Neither is it an id without its parameters.
  int32_t count = 0;
  float terms[4 * SSS_PROFILE_MAX_TERMS];
  EXPECT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_BURLEY, terms, SSS_PROFILE_MAX_TERMS, &count),
            SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_FALSE(sss::math::is_cbf_profile_id(SSS_PROFILE_BURLEY));
}

// Every family that reads a profile builds an energy-conserving plan from Burley's, and the
// transmittance terms fit it.
TEST(BurleyApi, EveryKernelFamilyBuildsFromIt) {
  sss_profile_desc marble;
  ASSERT_EQ(sss_profile_burley_from_measured(SSS_PROFILE_MARBLE, &marble), SSS_OK);
  for (int32_t family : {SSS_KERNEL_SUM_OF_GAUSSIANS, SSS_KERNEL_SVD, SSS_KERNEL_PREINTEGRATED, SSS_KERNEL_GUIDED}) {
    for (int32_t rank : {1, 3}) {
      sss_kernel_desc d;
      sss_default_kernel_desc(&d);
      d.family = family;
      d.rank = rank;
      d.taps = 21;
      d.profile = marble;
      std::vector<float> taps(SSS_KERNEL_MAX_TERMS * 2 * 21 * 4);
      int32_t terms = 0;
      float reach = 0.0f;
      ASSERT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, taps.data(), nullptr, &terms, &reach), SSS_OK) << last();
      EXPECT_GT(reach, 0.0f);
      for (int c = 0; c < 3; ++c) {
        double gain = 0.0;
        for (int t = 0; t < terms; ++t) {
          double h = 0.0, v = 0.0;
          for (int i = 0; i < 21; ++i) {
            h += taps[static_cast<std::size_t>(((t * 2 + 0) * 21 + i) * 4 + c)];
            v += taps[static_cast<std::size_t>(((t * 2 + 1) * 21 + i) * 4 + c)];
          }
          gain += h * v;
        }
        EXPECT_NEAR(gain, 1.0, 1e-5) << "family " << family << " rank " << rank << " channel " << c;
      }
    }
  }
  float terms[4 * SSS_PROFILE_MAX_TERMS];
  int32_t count = 0;
  ASSERT_EQ(sss_profile_desc_transmittance_terms(&marble, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK) << last();
  EXPECT_EQ(count, SSS_PROFILE_FIT_GAUSSIANS);
  for (int c = 0; c < 3; ++c) {
    double weight = 0.0;
    for (int i = 0; i < count; ++i) weight += terms[i * 4 + 1 + c];
    EXPECT_NEAR(weight, 1.0, 1e-3) << c;
  }
}

// 0.1-0.3's descs (without the six burley floats) are read as the prefix they are.
TEST(BurleyApi, EarlierReleasesDescsAreStillRead) {
  const auto old_profile = static_cast<uint32_t>(offsetof(sss_profile_desc, burley_albedo));
  const auto old_kernel = static_cast<uint32_t>(offsetof(sss_kernel_desc, profile)) + old_profile;
  sss_profile_desc p;
  sss_default_profile_desc(&p);
  p.profile = SSS_PROFILE_MARBLE;
  float now[3] = {}, then[3] = {};
  ASSERT_EQ(sss_profile_integral(&p, now), SSS_OK);
  p.struct_size = old_profile;
  p.burley_albedo[0] = NAN;  // past the old struct's end: never read
  ASSERT_EQ(sss_profile_integral(&p, then), SSS_OK) << last();
  for (int c = 0; c < 3; ++c) EXPECT_EQ(now[c], then[c]);
  p.struct_size = old_profile + 4;
  EXPECT_EQ(sss_profile_integral(&p, then), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("profile->struct_size = " + std::to_string(old_profile + 4)), std::string::npos) << last();

  sss_kernel_desc d;
  sss_default_kernel_desc(&d);
  d.family = SSS_KERNEL_SVD;
  d.rank = 2;
  d.profile.profile = SSS_PROFILE_MARBLE;
  std::vector<float> a(SSS_KERNEL_MAX_TERMS * 2 * 17 * 4), b(a.size());
  int32_t terms = 0;
  ASSERT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, a.data(), nullptr, &terms, nullptr), SSS_OK) << last();
  d.struct_size = old_kernel;
  d.profile.struct_size = old_profile;
  ASSERT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, b.data(), nullptr, &terms, nullptr), SSS_OK) << last();
  EXPECT_EQ(a, b);
  d.profile.struct_size = sizeof(sss_profile_desc);  // does not fit in 0.3's kernel desc
  EXPECT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, b.data(), nullptr, &terms, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("desc->profile.struct_size"), std::string::npos) << last();
}

}  // namespace
