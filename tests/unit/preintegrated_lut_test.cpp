// The pre-integrated diffuse and shadow LUTs (module/src/math/preintegrated_lut.*): limits of eq.
// (1.1), monotonicity, agreement with an independent integration, the shadow LUT's limits, no NaN
// at any texel, thread-count independence, the cache, and the GL-free C API.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "math/lut_cache.hpp"
#include "math/materials.hpp"
#include "math/preintegrated_lut.hpp"
#include "sss/sss_lut.h"
#include "sss/sss_tools.h"

namespace {

using sss::math::DiffuseLutDesc;
using sss::math::ShadowFilter;
using sss::math::ShadowLutDesc;

constexpr double kPi = 3.14159265358979323846;

const sss::math::RadialProfile& skin() { return sss::math::deon_skin_profile(); }

// Adaptive Simpson (absolute tolerance per interval), the independent integrator of the tests.
double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
               double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  if (depth <= 0 || std::fabs(left + right - whole) <= 15.0 * tol) return left + right + (left + right - whole) / 15.0;
  return simpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) + simpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

// ∫_a^b f over `pieces` equal intervals, each refined adaptively.
double integrate(const std::function<double(double)>& f, double a, double b, int pieces, double tol) {
  double sum = 0.0;
  for (int i = 0; i < pieces; ++i) {
    const double lo = a + (b - a) * i / pieces, hi = a + (b - a) * (i + 1) / pieces, mid = 0.5 * (lo + hi);
    const double flo = f(lo), fmid = f(mid), fhi = f(hi);
    sum += simpson(f, lo, hi, flo, fmid, fhi, (hi - lo) / 6.0 * (flo + 4.0 * fmid + fhi), tol / pieces, 40);
  }
  return sum;
}

// Eq. (1.1) directly: x over the whole ring [-π, π] (no folding, no cut-off, no breakpoints but the
// profile's peak at 0), weights R(|2r sin(x/2)|), one channel.
double reference_diffuse(double ndotl, double curvature, int channel,
                         const sss::math::RadialProfile& profile = skin()) {
  const double r = 1.0 / curvature, theta = std::acos(ndotl);
  const auto w = [&](double x) { return profile.evaluate(std::fabs(2.0 * r * std::sin(0.5 * x)))[static_cast<std::size_t>(channel)]; };
  const auto lit = [&](double x) { return std::max(0.0, std::cos(theta + x)) * w(x); };
  const double num = integrate(lit, -kPi, 0.0, 64, 1e-9) + integrate(lit, 0.0, kPi, 64, 1e-9);
  const double den = integrate(w, -kPi, 0.0, 64, 1e-9) + integrate(w, 0.0, kPi, 64, 1e-9);
  return num / den;
}

TEST(PreintegratedDiffuse, FlatSurfaceIsLambert) {
  // r → ∞: the profile (σ <= 2.7 mm) sees no change of N·L across it; at r = 100 m the blur of the
  // kink at N·L = 0 is ~σ/r = 3e-5 rad, far below 1e-4.
  for (double ndotl = -1.0; ndotl <= 1.0; ndotl += 0.05) {
    const auto d0 = sss::math::preintegrated_diffuse(skin(), ndotl, 0.0);
    const auto d = sss::math::preintegrated_diffuse(skin(), ndotl, 1e-5);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(d0[c], std::max(0.0, ndotl));
      EXPECT_NEAR(d[c], std::max(0.0, ndotl), 1e-4) << "ndotl " << ndotl << " channel " << c;
    }
  }
}

TEST(PreintegratedDiffuse, TinySphereIsRingMean) {
  // r → 0: the weights are constant over the ring (at r = 1 µm, R varies by < 1e-3 relative across
  // it), so D is the ring mean of saturate(cos): (1/2π)·∫ max(0, cos) = 1/π, whatever N·L.
  for (double ndotl = -1.0; ndotl <= 1.0; ndotl += 0.1) {
    const auto d = sss::math::preintegrated_diffuse(skin(), ndotl, 1000.0);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(d[c], 1.0 / kPi, 1e-3) << "ndotl " << ndotl;
  }
}

TEST(PreintegratedDiffuse, MonotoneInNdotLAndNoNaN) {
  DiffuseLutDesc desc;
  desc.width = 96;
  desc.height = 48;
  desc.curvature_min_per_mm = 0.0;
  desc.curvature_max_per_mm = 5.0;  // past the default range: up to r = 0.2 mm
  std::vector<float> lut(4u * 96 * 48);
  sss::math::generate_diffuse_lut(skin(), desc, 0, lut.data());
  for (int y = 0; y < desc.height; ++y) {
    for (int x = 0; x < desc.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        const float v = lut[static_cast<std::size_t>(4 * (y * desc.width + x) + c)];
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << x << "," << y << "," << c << ": " << v;
        // Non-decreasing in N·L: more of the ring's light falls inside the lit half. The 1e-6 slack
        // is float rounding of the stored values.
        if (x > 0 && c < 3) {
          EXPECT_GE(v, lut[static_cast<std::size_t>(4 * (y * desc.width + x - 1) + c)] - 1e-6f);
        }
      }
    }
  }
}

TEST(PreintegratedDiffuse, MatchesIndependentIntegration) {
  // The generator (folded ring, Gauss–Legendre panels, cut at the profile's support) against adaptive
  // Simpson on the raw eq. (1.1): 1e-3 is the bound.
  for (double curvature : {0.02, 0.1, 0.33, 1.0}) {
    for (double ndotl : {-0.9, -0.3, 0.0, 0.2, 0.6, 1.0}) {
      const auto d = sss::math::preintegrated_diffuse(skin(), ndotl, curvature);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(d[static_cast<std::size_t>(c)], reference_diffuse(ndotl, curvature, c), 1e-3)
            << "curvature " << curvature << " ndotl " << ndotl << " channel " << c;
      }
    }
  }
}

TEST(PreintegratedDiffuse, MatchesIndependentIntegrationForMeasuredMaterials) {
  // The dipoles of sss_kernels.h's measured materials (not sums of Gaussians; supports from the
  // closed-form encircled energy at 1e-9, up to hundreds of mm for skim milk): the same 1e-3 bound.
  // Marble scatters least, skim milk furthest; ketchup is strongly coloured.
  const auto& all = sss::math::measured_materials();
  for (const char* name : {"marble", "ketchup", "skimmilk"}) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& m) { return std::string(m.name) == name; });
    ASSERT_NE(it, all.end()) << name;
    const sss::math::DipoleProfile profile(*it);
    for (double curvature : {0.05, 0.5, 2.0}) {
      for (double ndotl : {-0.5, 0.0, 0.5}) {
        const auto d = sss::math::preintegrated_diffuse(profile, ndotl, curvature);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(d[static_cast<std::size_t>(c)], reference_diffuse(ndotl, curvature, c, profile), 1e-3)
              << name << " curvature " << curvature << " ndotl " << ndotl << " channel " << c;
        }
      }
    }
  }
}

TEST(PreintegratedDiffuse, RedScattersFurtherThanBlue) {
  // Past the terminator red (widest profile) wraps most: the paper's Figure 1.3.
  const auto d = sss::math::preintegrated_diffuse(skin(), -0.1, 0.2);
  EXPECT_GT(d[0], d[1]);
  EXPECT_GT(d[1], d[2]);
  EXPECT_GT(d[0], 0.005);  // 0.0068 by the generator: a visible red wrap
}

double reference_shadow_blur(const ShadowLutDesc& desc, double t0, double q, int channel) {
  const auto w = [&](double y) { return skin().evaluate(std::fabs(y))[static_cast<std::size_t>(channel)]; };
  const auto lit = [&](double y) { return sss::math::new_penumbra_value(desc.new_penumbra, t0 + y * q) * w(y); };
  const double l = 40.0;  // mm: beyond 17.5 the profile is < 1e-9 of its mass
  return (integrate(lit, -l, 0.0, 256, 1e-10) + integrate(lit, 0.0, l, 256, 1e-10)) /
         (integrate(w, -l, 0.0, 256, 1e-10) + integrate(w, 0.0, l, 256, 1e-10));
}

TEST(PreintegratedShadow, MatchesIndependentIntegration) {
  for (ShadowFilter filter : {ShadowFilter::box, ShadowFilter::gaussian}) {
    ShadowLutDesc desc;
    desc.filter = filter;
    for (double w : {0.002, 0.008, 0.03}) {
      const double q = desc.world_units_per_mm / w;
      for (int c = 0; c < 3; ++c) {
        const double lo = reference_shadow_blur(desc, sss::math::shadow_penumbra_position(filter, 0.0), q, c);
        const double hi = reference_shadow_blur(desc, sss::math::shadow_penumbra_position(filter, 1.0), q, c);
        for (double s : {0.1, 0.4, 0.5, 0.8}) {
          const double t0 = sss::math::shadow_penumbra_position(filter, s);
          const double expected = (reference_shadow_blur(desc, t0, q, c) - lo) / (hi - lo);
          EXPECT_NEAR(sss::math::preintegrated_shadow(skin(), desc, s, w)[static_cast<std::size_t>(c)], expected, 1e-3)
              << "w " << w << " s " << s << " channel " << c;
        }
      }
    }
  }
}

TEST(PreintegratedShadow, WidePenumbraIsTheNewPenumbra) {
  // The profile's width against the penumbra's → 0 (the paper's w → 0: its w is the scattering width
  // in penumbra units, ours the penumbra's world width, so here the penumbra grows): P_S → P'(P^-1(s)).
  // At a 100 m penumbra the profile (σ <= 2.7 mm) spans < 1e-4 penumbra widths.
  for (ShadowFilter filter : {ShadowFilter::box, ShadowFilter::gaussian}) {
    ShadowLutDesc desc;
    desc.filter = filter;
    for (double s = 0.0; s <= 1.0; s += 0.05) {
      const double expected = sss::math::new_penumbra_value(desc.new_penumbra, sss::math::shadow_penumbra_position(filter, s));
      const auto p = sss::math::preintegrated_shadow(skin(), desc, s, 100.0);
      for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(p[c], expected, 1e-3) << "s " << s;
    }
  }
}

TEST(PreintegratedShadow, MonotoneEndsFixedAndNoNaN) {
  for (ShadowFilter filter : {ShadowFilter::box, ShadowFilter::gaussian}) {
    ShadowLutDesc desc;
    desc.filter = filter;
    desc.width = 64;
    desc.height = 32;
    desc.penumbra_min = 1e-6;  // a penumbra far narrower than the profile, at the LUT's edge
    desc.penumbra_max = 1.0;
    std::vector<float> lut(4u * 64 * 32);
    sss::math::generate_shadow_lut(skin(), desc, 2, lut.data());
    for (int y = 0; y < desc.height; ++y) {
      for (int x = 0; x < desc.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          const float v = lut[static_cast<std::size_t>(4 * (y * desc.width + x) + c)];
          ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << x << "," << y << ": " << v;
          if (x > 0) {
            EXPECT_GE(v, lut[static_cast<std::size_t>(4 * (y * desc.width + x - 1) + c)] - 1e-6f);
          }
        }
      }
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(lut[static_cast<std::size_t>(4 * (y * desc.width) + c)], 0.0f);  // umbra stays dark
        EXPECT_EQ(lut[static_cast<std::size_t>(4 * (y * desc.width + desc.width - 1) + c)], 1.0f);  // lit stays lit
      }
    }
  }
}

TEST(PreintegratedShadow, ScatteringWidensTheSharpPenumbra) {
  // Where the penumbra is a few mm wide, light scatters past the sharp penumbra's dark end: red most.
  ShadowLutDesc desc;
  const double s_dark = 0.3;  // P'(P^-1(0.3)) = 0 for new_penumbra 0.25
  ASSERT_EQ(sss::math::new_penumbra_value(desc.new_penumbra, s_dark), 0.0);
  const auto p = sss::math::preintegrated_shadow(skin(), desc, s_dark, 0.01);
  EXPECT_GT(p[0], 0.005);  // 0.009 by the generator
  EXPECT_GT(p[0], p[2]);
}

TEST(PreintegratedLut, SameResultOnAnyThreadCount) {
  DiffuseLutDesc desc;
  desc.width = 32;
  desc.height = 17;
  std::vector<float> one(4u * 32 * 17), many(4u * 32 * 17);
  sss::math::generate_diffuse_lut(skin(), desc, 1, one.data());
  sss::math::generate_diffuse_lut(skin(), desc, 5, many.data());
  EXPECT_EQ(one, many);
}

TEST(LutCache, HitDoesNotRegenerate) {
  sss::math::LutCache cache(2);
  int runs = 0;
  const auto make = [&runs] {
    ++runs;
    return std::vector<float>{1.0f, 2.0f};
  };
  DiffuseLutDesc a, b;
  b.curvature_max_per_mm = 0.5;
  const std::string ka = sss::math::diffuse_lut_key(skin(), a), kb = sss::math::diffuse_lut_key(skin(), b);
  ASSERT_NE(ka, kb);
  ASSERT_NE(sss::math::lut_hash(ka), sss::math::lut_hash(kb));
  const auto first = cache.get(ka, make);
  const auto again = cache.get(ka, make);
  EXPECT_EQ(first.get(), again.get());
  EXPECT_EQ(cache.generations(), 1u);
  cache.get(kb, make);
  EXPECT_EQ(cache.generations(), 2u);
  cache.get(ka, make);
  EXPECT_EQ(cache.generations(), 2u);
  EXPECT_EQ(runs, 2);
}

TEST(LutCApi, FillMatchesTheMathLayer) {
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 16;
  desc.height = 8;
  std::vector<float> out(4u * 16 * 8, -1.0f), expected(out.size());
  ASSERT_EQ(sss_lut_diffuse_fill(&desc, out.data(), out.size()), SSS_OK);
  DiffuseLutDesc d;
  d.width = 16;
  d.height = 8;
  sss::math::generate_diffuse_lut(skin(), d, 1, expected.data());
  EXPECT_EQ(out, expected);
  ASSERT_EQ(sss_lut_shadow_fill(&desc, out.data(), out.size()), SSS_OK);
  ShadowLutDesc s;
  s.width = 16;
  s.height = 8;
  sss::math::generate_shadow_lut(skin(), s, 1, expected.data());
  EXPECT_EQ(out, expected);
}

// The fill functions keep their LUTs by input (issue: nothing regenerated while the parameters stay
// the same): the same description again is a copy, the thread count is not an input of the values,
// and any field that changes a value makes a new LUT.
TEST(LutCApi, FillsWithTheSameInputsAreCached) {
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 12;
  desc.height = 5;
  desc.curvature_max = 0.77f;  // a description no other test fills
  std::vector<float> first(4u * 12 * 5, -1.0f), again(first.size(), -2.0f);
  const uint64_t before = sss_lut_fill_generation_count();
  ASSERT_EQ(sss_lut_diffuse_fill(&desc, first.data(), first.size()), SSS_OK);
  EXPECT_EQ(sss_lut_fill_generation_count(), before + 1);
  desc.threads = 3;
  ASSERT_EQ(sss_lut_diffuse_fill(&desc, again.data(), again.size()), SSS_OK);
  EXPECT_EQ(sss_lut_fill_generation_count(), before + 1);
  EXPECT_EQ(first, again);
  // The shadow LUT of the same description is another LUT, and so is another curvature range.
  ASSERT_EQ(sss_lut_shadow_fill(&desc, again.data(), again.size()), SSS_OK);
  EXPECT_EQ(sss_lut_fill_generation_count(), before + 2);
  desc.curvature_max = 0.78f;
  ASSERT_EQ(sss_lut_diffuse_fill(&desc, again.data(), again.size()), SSS_OK);
  EXPECT_EQ(sss_lut_fill_generation_count(), before + 3);
  EXPECT_NE(first, again);
}

TEST(LutCApi, EveryMaterialGivesItsOwnLut) {
  // sss_lut_desc.profile takes sss_kernels.h's materials: each LUT is in [0, 1], flat rows are
  // saturate(N·L) exactly, and the materials differ (a strongly scattering one is brighter at the
  // terminator than marble on a curved row).
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 9;  // N·L = -1, -0.75, ..., 1: column 4 is the terminator
  desc.height = 3; // curvature 0, 0.5, 1 per mm
  desc.threads = 2;
  std::vector<std::vector<float>> luts;
  for (int32_t m = SSS_PROFILE_SKIN_DEON; m <= SSS_PROFILE_WHOLEMILK; ++m) {
    desc.profile = m;
    std::vector<float> out(4u * 9 * 3, -1.0f);
    ASSERT_EQ(sss_lut_diffuse_fill(&desc, out.data(), out.size()), SSS_OK) << sss_last_error(nullptr);
    for (float v : out) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << sss_profile_name(m) << ": " << v;
    for (int x = 0; x < 9; ++x) {
      const double ndotl = -1.0 + 0.25 * x;
      EXPECT_NEAR(out[static_cast<std::size_t>(4 * x)], std::max(0.0, ndotl), 1e-6) << sss_profile_name(m);
    }
    std::vector<float> shadow(out.size(), -1.0f);
    ASSERT_EQ(sss_lut_shadow_fill(&desc, shadow.data(), shadow.size()), SSS_OK) << sss_profile_name(m);
    for (float v : shadow) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << sss_profile_name(m) << ": " << v;
    luts.push_back(out);
  }
  for (std::size_t a = 0; a < luts.size(); ++a) {
    for (std::size_t b = a + 1; b < luts.size(); ++b) EXPECT_NE(luts[a], luts[b]) << a << " vs " << b;
  }
  // Row 2 (curvature 1/mm), column 4 (N·L = 0), red: light wraps past the terminator further for skim
  // milk (mean free path ~ mm) than for marble.
  const std::size_t terminator = 4u * (2 * 9 + 4);
  EXPECT_GT(luts[SSS_PROFILE_SKIMMILK][terminator], luts[SSS_PROFILE_MARBLE][terminator]);
}

TEST(LutCApi, RejectsBadInputWithNamedMessage) {
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 4;
  desc.height = 4;
  std::vector<float> out(64, 7.0f);
  const auto expect_rejected = [&](const sss_lut_desc& d, size_t floats, const char* needle, bool shadow) {
    const sss_result r = shadow ? sss_lut_shadow_fill(&d, out.data(), floats) : sss_lut_diffuse_fill(&d, out.data(), floats);
    EXPECT_EQ(r, SSS_ERROR_INVALID_ARGUMENT) << needle;
    EXPECT_NE(std::string(sss_last_error(nullptr)).find(needle), std::string::npos) << sss_last_error(nullptr);
    for (float v : out) ASSERT_EQ(v, 7.0f);  // untouched
  };
  sss_lut_desc d = desc;
  d.struct_size = 3;
  expect_rejected(d, 64, "struct_size = 3", false);
  d = desc;
  d.width = 1;
  expect_rejected(d, 64, "desc->width = 1", false);
  d = desc;
  d.height = 5000;
  expect_rejected(d, 1u << 30, "desc->height = 5000", false);
  d = desc;
  d.curvature_max = NAN;
  expect_rejected(d, 64, "desc->curvature_max = nan", false);
  d = desc;
  d.curvature_min = 2.0f;
  expect_rejected(d, 64, "curvature_min = 2 is not below", false);
  d = desc;
  d.profile = SSS_PROFILE_TABULATED;  // no table in sss_lut_desc
  expect_rejected(d, 64, "desc->profile = 12", false);
  d = desc;
  d.profile = -1;
  expect_rejected(d, 64, "desc->profile = -1", false);
  d = desc;
  d.threads = -1;
  expect_rejected(d, 64, "desc->threads = -1", true);
  d = desc;
  d.penumbra_min = 0.0f;
  expect_rejected(d, 64, "desc->penumbra_min = 0", true);
  d = desc;
  d.world_units_per_mm = INFINITY;
  expect_rejected(d, 64, "desc->world_units_per_mm = inf", true);
  d = desc;
  d.new_penumbra = 1.5f;
  expect_rejected(d, 64, "desc->new_penumbra = 1.5", true);
  d = desc;
  d.shadow_filter = 2;
  expect_rejected(d, 64, "desc->shadow_filter = 2", true);
  d = desc;
  d.flags = 0x10;
  expect_rejected(d, 64, "desc->flags = 0x10", true);
  expect_rejected(desc, 63, "out_floats = 63", false);
  EXPECT_EQ(sss_lut_diffuse_fill(nullptr, out.data(), 64), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_lut_shadow_fill(&desc, nullptr, 64), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_lut_generation_count(nullptr), 0u);
}

TEST(LutCApi, RandomDescriptionsGiveValuesInRangeOrANamedRejection) {
  // Every field drawn from valid values, edge values and garbage (NaN, ±inf, negatives, huge), small
  // sizes: a call either succeeds with every value finite and in [0, 1], or fails with
  // SSS_ERROR_INVALID_ARGUMENT naming a desc field, leaving the output untouched.
  std::mt19937 rng(20261121);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> floats = {0.0f, 1e-30f, 1e-6f, 0.001f, 0.02f, 0.5f, 1.0f, 3.0f, 999.0f, 1000.0f, 1001.0f,
                                     1e6f, 2e6f, -0.001f, -1.0f, inf, -inf, nan};
  const std::vector<int32_t> ints = {-1, 0, 1, 2, 3, 5, 8, 4097, 257, std::numeric_limits<int32_t>::min()};
  auto pick_f = [&] { return floats[std::uniform_int_distribution<std::size_t>(0, floats.size() - 1)(rng)]; };
  auto pick_i = [&] { return ints[std::uniform_int_distribution<std::size_t>(0, ints.size() - 1)(rng)]; };
  int ok = 0, rejected = 0;
  for (int i = 0; i < 400; ++i) {
    sss_lut_desc d;
    sss_lut_default_desc(&d);
    d.width = std::uniform_int_distribution<int>(0, 9)(rng) == 0 ? pick_i() : std::uniform_int_distribution<int>(2, 6)(rng);
    d.height = std::uniform_int_distribution<int>(0, 9)(rng) == 0 ? pick_i() : std::uniform_int_distribution<int>(2, 6)(rng);
    if (rng() % 4 == 0) d.profile = pick_i();
    if (rng() % 2 == 0) d.curvature_min = pick_f();
    if (rng() % 2 == 0) d.curvature_max = pick_f();
    if (rng() % 2 == 0) d.penumbra_min = pick_f();
    if (rng() % 2 == 0) d.penumbra_max = pick_f();
    if (rng() % 3 == 0) d.world_units_per_mm = pick_f();
    if (rng() % 3 == 0) d.new_penumbra = pick_f();
    if (rng() % 4 == 0) d.shadow_filter = pick_i();
    if (rng() % 4 == 0) d.threads = pick_i();
    if (rng() % 8 == 0) d.flags = static_cast<uint32_t>(rng());
    const bool shadow = rng() % 2 == 0;
    std::vector<float> out(4u * 6 * 6, -7.0f);
    const sss_result r = shadow ? sss_lut_shadow_fill(&d, out.data(), out.size()) : sss_lut_diffuse_fill(&d, out.data(), out.size());
    if (r == SSS_OK) {
      ++ok;
      for (int t = 0; t < 4 * d.width * d.height; ++t) {
        ASSERT_TRUE(std::isfinite(out[static_cast<std::size_t>(t)]) && out[static_cast<std::size_t>(t)] >= 0.0f &&
                    out[static_cast<std::size_t>(t)] <= 1.0f)
            << "case " << i << " texel " << t << ": " << out[static_cast<std::size_t>(t)];
      }
    } else {
      ++rejected;
      ASSERT_EQ(r, SSS_ERROR_INVALID_ARGUMENT) << "case " << i;
      const std::string message = sss_last_error(nullptr);
      EXPECT_TRUE(message.find("desc->") != std::string::npos || message.find("out_floats") != std::string::npos)
          << message;
      for (float v : out) ASSERT_EQ(v, -7.0f) << "case " << i << ": rejected but written";
    }
  }
  EXPECT_GT(ok, 40);  // both outcomes exercised
  EXPECT_GT(rejected, 40);
}

}  // namespace
