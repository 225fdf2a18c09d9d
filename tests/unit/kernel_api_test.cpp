// The GL-free kernel and profile C API (sss_kernels.h): results match the math layer, and every bad
// argument is refused with a message naming it, leaving the outputs untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "math/kernel_request.hpp"
#include "sss/sss_tools.h"

namespace {

std::string last() { return sss_last_error(nullptr); }

TEST(KernelApi, DefaultsAreValidAndBuildTheTable1Kernel) {
  sss_kernel_desc d;
  sss_default_kernel_desc(&d);
  EXPECT_EQ(d.struct_size, sizeof d);
  EXPECT_EQ(d.family, SSS_KERNEL_SEPARABLE);
  std::vector<float> taps(SSS_KERNEL_MAX_TERMS * 2 * 65 * 4, -7.0f);
  int32_t terms = 0;
  float reach = 0.0f, depth[SSS_KERNEL_MAX_TERMS] = {};
  ASSERT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, taps.data(), depth, &terms, &reach), SSS_OK) << last();
  EXPECT_EQ(terms, 1);
  EXPECT_FLOAT_EQ(reach, 2.0f);
  EXPECT_EQ(depth[0], 0.0f);
  // Same as sss_kernel_separable with the same parameters, on both passes.
  std::vector<float> ref(65 * 4);
  ASSERT_EQ(sss_kernel_separable(d.taps, d.strength, d.falloff, ref.data()), SSS_OK);
  for (int i = 0; i < d.taps * 4; ++i) {
    EXPECT_EQ(taps[static_cast<std::size_t>(i)], ref[static_cast<std::size_t>(i)]);
    EXPECT_EQ(taps[static_cast<std::size_t>(d.taps * 4 + i)], ref[static_cast<std::size_t>(i)]);
  }
}

TEST(KernelApi, EveryFamilyAndMaterialBuildsAnEnergyConservingPlan) {
  for (int32_t family = 0; family < SSS_KERNEL_FAMILY_COUNT; ++family) {
    for (int32_t material : {SSS_PROFILE_SKIN_DEON, SSS_PROFILE_MARBLE, SSS_PROFILE_KETCHUP, SSS_PROFILE_BURLEY}) {
      sss_kernel_desc d;
      sss_default_kernel_desc(&d);
      d.family = family;
      d.taps = 13;
      d.rank = 2;
      d.profile.profile = material;
      std::vector<float> taps(SSS_KERNEL_MAX_TERMS * 2 * 13 * 4);
      int32_t terms = 0;
      ASSERT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, taps.data(), nullptr, &terms, nullptr), SSS_OK) << last();
      for (int c = 0; c < 3; ++c) {
        double gain = 0.0;
        for (int t = 0; t < terms; ++t) {
          double h = 0.0, v = 0.0;
          for (int i = 0; i < 13; ++i) {
            h += taps[static_cast<std::size_t>(((t * 2 + 0) * 13 + i) * 4 + c)];
            v += taps[static_cast<std::size_t>(((t * 2 + 1) * 13 + i) * 4 + c)];
          }
          gain += h * v;
        }
        EXPECT_NEAR(gain, 1.0, 1e-5) << "family " << family << " material " << material;
      }
    }
  }
}

TEST(KernelApi, ProfileEvaluateMatchesTheMathLayer) {
  sss_profile_desc p;
  sss_default_profile_desc(&p);
  p.profile = SSS_PROFILE_SKIN1;
  const float r[3] = {0.0f, 0.5f, 4.0f};
  float out[9] = {};
  ASSERT_EQ(sss_profile_evaluate(&p, 3, r, out), SSS_OK);
  const sss::math::DipoleProfile dipole(sss::math::measured_materials()[8]);
  for (int i = 0; i < 3; ++i) {
    const auto v = dipole.evaluate(r[i]);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(out[i * 3 + c], static_cast<float>(v[static_cast<std::size_t>(c)]));
  }
  float total[3] = {};
  ASSERT_EQ(sss_profile_integral(&p, total), SSS_OK);
  EXPECT_FLOAT_EQ(total[0], static_cast<float>(dipole.integral()[0]));
  EXPECT_STREQ(sss_profile_name(SSS_PROFILE_SKIN1), "skin1");
  EXPECT_STREQ(sss_profile_name(SSS_PROFILE_WHOLEMILK), "wholemilk");
  EXPECT_EQ(sss_profile_name(SSS_PROFILE_COUNT), nullptr);
  EXPECT_EQ(sss_profile_name(-1), nullptr);
}

TEST(KernelApi, TabulatedProfileRoundTrips) {
  const float radii[3] = {0.0f, 1.0f, 2.0f};
  const float rgb[9] = {1, 2, 3, 0.5f, 1, 1.5f, 0, 0, 0};
  sss_profile_desc p;
  sss_default_profile_desc(&p);
  p.profile = SSS_PROFILE_TABULATED;
  p.table_size = 3;
  p.table_radius_mm = radii;
  p.table_rgb = rgb;
  const float r[2] = {0.5f, 5.0f};
  float out[6] = {};
  ASSERT_EQ(sss_profile_evaluate(&p, 2, r, out), SSS_OK) << last();
  EXPECT_FLOAT_EQ(out[0], 0.75f);
  EXPECT_FLOAT_EQ(out[5], 0.0f);
  sss_kernel_desc d;
  sss_default_kernel_desc(&d);
  d.family = SSS_KERNEL_PREINTEGRATED;
  d.profile = p;
  std::vector<float> taps(2 * 17 * 4);
  int32_t terms = 0;
  EXPECT_EQ(sss_kernel_plan(&d, 1, taps.data(), nullptr, &terms, nullptr), SSS_OK) << last();
}

struct BadCase {
  const char* what;
  void (*edit)(sss_kernel_desc&);
};

TEST(KernelApi, BadArgumentsAreNamedAndWriteNothing) {
  static const float bad_radii[2] = {1.0f, 1.0f};
  static const float rgb[6] = {1, 1, 1, 1, 1, 1};
  static const float zero_rgb[6] = {0, 0, 0, 0, 0, 0};
  // The first value past the families (a new family moves it).
  static const std::string first_unknown_family = "desc->family = " + std::to_string(SSS_KERNEL_FAMILY_COUNT);
  static const float radii[2] = {0.0f, 1.0f};
  const BadCase cases[] = {
      {"desc->struct_size", [](sss_kernel_desc& d) { d.struct_size = 4; }},
      {first_unknown_family.c_str(), [](sss_kernel_desc& d) { d.family = SSS_KERNEL_FAMILY_COUNT; }},
      {"desc->family = -1", [](sss_kernel_desc& d) { d.family = -1; }},
      {"desc->taps = 16", [](sss_kernel_desc& d) { d.taps = 16; }},
      {"desc->taps = 67", [](sss_kernel_desc& d) { d.taps = 67; }},
      {"desc->flags", [](sss_kernel_desc& d) { d.flags = 0x10; }},
      {"desc->strength[1] = nan", [](sss_kernel_desc& d) { d.strength[1] = NAN; }},
      {"desc->falloff[2] = 2", [](sss_kernel_desc& d) { d.falloff[2] = 2.0f; }},
      {"desc->rank = 7", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.rank = 7; }},
      {"desc->rank = 0", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SUM_OF_GAUSSIANS, d.rank = 0; }},
      {"desc->guide_k = 4.5", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_GUIDED, d.guide_k = 4.5f; }},
      {"desc->radius_mm = -1", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.radius_mm = -1.0f; }},
      {"desc->radius_mm = inf", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.radius_mm = INFINITY; }},
      {"desc->near_variance_mm2[0] = 0", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_ARTIST, d.near_variance_mm2[0] = 0; }},
      {"desc->far_variance_mm2[1] = -1", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_ARTIST, d.far_variance_mm2[1] = -1; }},
      {"desc->near_weight[2] = 1.5", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_ARTIST, d.near_weight[2] = 1.5f; }},
      {"desc->profile->profile = 13", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.profile = 13; }},
      {"desc->profile->struct_size", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.struct_size = 0; }},
      {"desc->profile->gaussian_count = 7", [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.gaussian_count = 7; }},
      {"desc->profile->table_size = 0",
       [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.profile = SSS_PROFILE_TABULATED; }},
      {"desc->profile->table_radius_mm is NULL",
       [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.profile = SSS_PROFILE_TABULATED, d.profile.table_size = 2, d.profile.table_rgb = rgb; }},
      {"desc->profile->table_radius_mm[1] = 1",
       [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.profile = SSS_PROFILE_TABULATED, d.profile.table_size = 2, d.profile.table_rgb = rgb, d.profile.table_radius_mm = bad_radii; }},
      {"integrates to 0",
       [](sss_kernel_desc& d) { d.family = SSS_KERNEL_SVD, d.profile.profile = SSS_PROFILE_TABULATED, d.profile.table_size = 2, d.profile.table_rgb = zero_rgb, d.profile.table_radius_mm = radii; }},
  };
  for (const BadCase& c : cases) {
    sss_kernel_desc d;
    sss_default_kernel_desc(&d);
    c.edit(d);
    std::vector<float> taps(SSS_KERNEL_MAX_TERMS * 2 * 65 * 4, -7.0f);
    int32_t terms = -3;
    float reach = -5.0f;
    EXPECT_EQ(sss_kernel_plan(&d, SSS_KERNEL_MAX_TERMS, taps.data(), nullptr, &terms, &reach), SSS_ERROR_INVALID_ARGUMENT)
        << c.what;
    EXPECT_NE(last().find(c.what), std::string::npos) << "message '" << last() << "' should name " << c.what;
    EXPECT_EQ(terms, -3);
    EXPECT_EQ(reach, -5.0f);
    EXPECT_EQ(taps[0], -7.0f);
  }
}

TEST(KernelApi, TooFewTermsSaysHowManyAreNeeded) {
  sss_kernel_desc d;
  sss_default_kernel_desc(&d);
  d.family = SSS_KERNEL_SUM_OF_GAUSSIANS;
  d.rank = 6;
  std::vector<float> taps(2 * 2 * 17 * 4, -7.0f);
  int32_t terms = 0;
  EXPECT_EQ(sss_kernel_plan(&d, 2, taps.data(), nullptr, &terms, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(terms, 6);
  EXPECT_NE(last().find("max_terms = 2"), std::string::npos);
  EXPECT_EQ(taps[0], -7.0f);
  EXPECT_EQ(sss_kernel_plan(nullptr, 6, taps.data(), nullptr, &terms, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("desc is NULL"), std::string::npos);
  sss_default_kernel_desc(&d);
  EXPECT_EQ(sss_kernel_plan(&d, 6, nullptr, nullptr, &terms, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("out_taps is NULL"), std::string::npos);
  EXPECT_EQ(sss_kernel_plan(&d, 6, taps.data(), nullptr, nullptr, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("out_terms is NULL"), std::string::npos);
  EXPECT_EQ(sss_kernel_plan(&d, 0, taps.data(), nullptr, &terms, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("max_terms = 0"), std::string::npos);
}

TEST(KernelApi, ProfileBadArguments) {
  sss_profile_desc p;
  sss_default_profile_desc(&p);
  const float r[2] = {0.0f, -1.0f};
  float out[6] = {9, 9, 9, 9, 9, 9};
  EXPECT_EQ(sss_profile_evaluate(&p, 2, r, out), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("radius_mm[1] = -1"), std::string::npos) << last();
  EXPECT_EQ(out[0], 9.0f);
  EXPECT_EQ(sss_profile_evaluate(&p, 0, r, out), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("count = 0"), std::string::npos);
  EXPECT_EQ(sss_profile_evaluate(nullptr, 1, r, out), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("profile is NULL"), std::string::npos);
  EXPECT_EQ(sss_profile_evaluate(&p, 1, nullptr, out), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_profile_evaluate(&p, 1, r, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_profile_integral(&p, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("out_rgb is NULL"), std::string::npos);
  p.profile = -1;
  EXPECT_EQ(sss_profile_integral(&p, out), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(last().find("profile->profile = -1"), std::string::npos);
  sss_default_profile_desc(nullptr);  // ignored, no crash
  sss_default_kernel_desc(nullptr);
}

}  // namespace
