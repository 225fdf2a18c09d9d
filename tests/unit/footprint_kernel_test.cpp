// Footprint-aware taps (module/src/math/footprint_kernel.hpp): energy, the sub-pixel pass-through,
// the exact discrete sum of Gaussians, and the tables' interpolation error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../../module/src/math/filter_constants.hpp"
#include "../../module/src/math/footprint_kernel.hpp"
#include "../../module/src/math/pass_kernel.hpp"
#include "../../module/src/math/plane_reference.hpp"
#include "../../module/src/math/skin_profile.hpp"

namespace {

using sss::math::FootprintTable;
using sss::math::FootprintTaps;

std::size_t idx(int i) { return static_cast<std::size_t>(i); }

// Every family's kernel at 17 taps (and the sum of Gaussians at 65).
std::vector<sss::math::PassKernel> every_family() {
  std::vector<sss::math::PassKernel> out;
  sss::math::FilterSettings s;
  out.push_back(sss::math::build_pass_kernel(s));
  s.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  s.kernel.rank = 6;
  out.push_back(sss::math::build_pass_kernel(s));
  s.samples = 65;
  out.push_back(sss::math::build_pass_kernel(s));
  s.samples = 17;
  for (auto family : {sss::math::KernelFamily::svd, sss::math::KernelFamily::preintegrated,
                      sss::math::KernelFamily::guided, sss::math::KernelFamily::artist}) {
    s.kernel.family = family;
    s.kernel.rank = 2;
    out.push_back(sss::math::build_pass_kernel(s));
  }
  return out;
}

// Steps (pixels per profile mm) from far crowds to extreme close-ups, log-spaced.
std::vector<float> steps() {
  std::vector<float> out;
  for (int i = 0; i <= 40; ++i) out.push_back(0.01f * std::pow(10.0f, static_cast<float>(i) / 10.0f));
  return out;
}

std::array<double, 3> mass(const FootprintTable& t) {
  return {2.0 * t.half_cdf.back()[0] + t.delta[0], 2.0 * t.half_cdf.back()[1] + t.delta[1],
          2.0 * t.half_cdf.back()[2] + t.delta[2]};
}

TEST(FootprintKernel, WeightsConserveEachChannelsEnergyAtEveryFootprint) {
  for (const auto& kernel : every_family()) {
    for (const auto& term : kernel.terms) {
      for (const auto* pass : {&term.horizontal, &term.vertical}) {
        const std::array<double, 3> expected = mass(pass->footprint);
        for (float step : steps()) {
          const FootprintTaps taps = sss::math::footprint_taps(pass->footprint, kernel.spacing, step);
          for (std::size_t c = 0; c < 3; ++c) {
            double sum = taps.weight[0][c];
            for (int i = 1; i <= taps.count; ++i) sum += 2.0 * taps.weight[static_cast<std::size_t>(i)][c];
            EXPECT_NEAR(sum, expected[c], 1e-6) << "step " << step << " channel " << c;
          }
        }
      }
    }
    // A normalised kernel's two passes of all terms together sum to 1 (the first pass of each
    // sum-of-Gaussians term carries the term's weight).
    for (std::size_t c = 0; c < 3; ++c) {
      double total = 0.0;
      for (const auto& term : kernel.terms) total += mass(term.horizontal.footprint)[c] * mass(term.vertical.footprint)[c];
      EXPECT_NEAR(total, 1.0, 1e-6) << "channel " << c;
    }
  }
}

TEST(FootprintKernel, TapsSitOnWholeDistinctPixelsWithinTheBudget) {
  for (const auto& kernel : every_family()) {
    const int half = static_cast<int>(kernel.spacing.size());
    for (float step : steps()) {
      const auto& table = kernel.terms[0].horizontal.footprint;
      const FootprintTaps taps = sss::math::footprint_taps(table, kernel.spacing, step);
      ASSERT_LE(taps.count, half);
      const float reach_px = table.reach_mm * step;
      if (reach_px <= static_cast<float>(half) + 0.5f) {
        // Every pixel out to the reach, no more.
        EXPECT_EQ(taps.count, std::max(0, static_cast<int>(std::ceil(reach_px - 0.5f))));
        for (int i = 0; i < taps.count; ++i) EXPECT_EQ(taps.position[static_cast<std::size_t>(i)], i + 1);
      } else {
        for (int i = 1; i < taps.count; ++i) {
          EXPECT_GT(taps.position[static_cast<std::size_t>(i)], taps.position[static_cast<std::size_t>(i - 1)]);
        }
        EXPECT_NEAR(taps.position[static_cast<std::size_t>(taps.count - 1)], reach_px, 0.5f + 1e-3f * reach_px);
      }
    }
  }
}

// Jitter moves a spread-out tap to a pixel of its own cell (between the midpoints to its neighbours;
// the outermost one's cell mirrored) and changes no weight; where every pixel has its tap, and for
// taps inside the jittered share's complement, nothing moves.
TEST(FootprintKernel, JitterReadsAPixelOfTheTapsOwnCellAndKeepsTheWeights) {
  sss::math::FilterSettings s;
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(s);
  const int half = static_cast<int>(kernel.spacing.size());
  const int from = sss::math::first_jittered_tap(0.33f, half);
  ASSERT_EQ(from, half - static_cast<int>(std::lround(0.33 * half)) + 1);
  EXPECT_EQ(sss::math::first_jittered_tap(0.0f, half), sss::math::kNoJitter);
  EXPECT_EQ(sss::math::first_jittered_tap(1.0f, half), 1);
  const auto& table = kernel.terms[0].horizontal.footprint;
  int moved = 0;
  for (float step : steps()) {
    const FootprintTaps plain = sss::math::footprint_taps(table, kernel.spacing, step);
    const bool sparse = table.reach_mm * step > static_cast<float>(half) + 0.5f;
    for (int jitter_from : {from, 1}) {
      for (float noise : {0.0f, 0.3f, 0.5f, 0.999f}) {
        const FootprintTaps jittered = sss::math::footprint_taps(table, kernel.spacing, step, jitter_from, noise);
        ASSERT_EQ(jittered.count, plain.count);
        for (int i = 0; i <= plain.count; ++i) EXPECT_EQ(jittered.weight[idx(i)], plain.weight[idx(i)]);
        for (int i = 1; i <= plain.count; ++i) {
          const int p = plain.position[idx(i - 1)], q = jittered.position[idx(i - 1)];
          if (!sparse || i < jitter_from) {
            EXPECT_EQ(q, p) << "step " << step << " tap " << i;
            continue;
          }
          const int inner = i > 1 ? plain.position[idx(i - 2)] : 0;
          const int lo = (inner + p) / 2 + 1;
          const int hi = i < plain.count ? (p + plain.position[idx(i)]) / 2 : 2 * p - lo;
          EXPECT_GE(q, lo) << "step " << step << " tap " << i << " noise " << noise;
          EXPECT_LE(q, hi) << "step " << step << " tap " << i << " noise " << noise;
          moved += q != p;
        }
      }
    }
  }
  EXPECT_GT(moved, 0);  // the noise moves taps somewhere on the sweep, or this proves nothing
}

TEST(FootprintKernel, AKernelInsideItsPixelLeavesThePixelAlone) {
  for (const auto& kernel : every_family()) {
    for (const auto& term : kernel.terms) {
      const auto& table = term.vertical.footprint;
      const float step = 0.49f / table.reach_mm;  // the whole pass within half a pixel of the centre
      const FootprintTaps taps = sss::math::footprint_taps(table, kernel.spacing, step);
      EXPECT_EQ(taps.count, 0);
      for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(taps.weight[0][c], mass(table)[c], 1e-7);
    }
  }
}

TEST(FootprintKernel, TheSumOfGaussiansIsTheExactPixelIntegralWhereEveryPixelHasATap) {
  sss::math::FilterSettings s;
  s.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  s.kernel.rank = 6;
  s.samples = 65;
  const auto kernel = sss::math::build_pass_kernel(s);
  const auto& gaussians = sss::math::skin_gaussians();
  ASSERT_EQ(kernel.terms.size(), gaussians.size());
  double worst = 0.0;
  for (std::size_t t = 0; t < gaussians.size(); ++t) {
    // The horizontal pass: normalised to 1 in every channel (the term's weight is on the vertical).
    const auto& table = kernel.terms[t].horizontal.footprint;
    for (float step : steps()) {
      const FootprintTaps taps = sss::math::footprint_taps(table, kernel.spacing, step);
      if (table.reach_mm * step > static_cast<float>(kernel.spacing.size()) + 0.5f) continue;  // sparse
      const int radius = taps.count + 1;
      const auto exact = sss::math::pixel_integrated_gaussian(gaussians[t].variance_mm2, 1.0 / step, radius);
      const auto at = [&](int d) { return exact[static_cast<std::size_t>(radius + d)]; };
      for (int i = 0; i <= taps.count; ++i) {
        // The outermost tap also takes the tail beyond it (the exact sum of what lies past).
        double reference = at(i);
        if (i == taps.count && i > 0) {
          double below = at(0);
          for (int j = 1; j < i; ++j) below += 2.0 * at(j);
          reference = 0.5 * (1.0 - below);
        }
        worst = std::max(worst, std::fabs(taps.weight[static_cast<std::size_t>(i)][0] - reference));
      }
    }
  }
  std::printf("largest weight error of the discrete sum of Gaussians: %.3g\n", worst);
  // The tables' interpolation (below) plus float rounding.
  EXPECT_LE(worst, 2e-4);
}

// Each family's sparse layout by the shape of its terms (footprint_kernel.hpp): the cube for a peaked
// kernel, the power 2.5 for the sum of Gaussians of two terms or more (one term may be a per-pixel
// profile, which shares the cube of the others).
TEST(FootprintKernel, EachFamilySpreadsItsSparseTapsByTheShapeOfItsTerms) {
  // Each share (i / half)^p to float precision.
  const auto power = [](const sss::math::PassKernel& k, double p) {
    const int half = static_cast<int>(k.spacing.size());
    for (int i = 1; i <= half; ++i) {
      const double t = static_cast<double>(i) / half;
      if (std::fabs(k.spacing[idx(i - 1)] - std::pow(t, p)) > 1e-6 * std::pow(t, p)) return false;
    }
    return half > 0;
  };
  const std::vector<sss::math::PassKernel> kernels = every_family();
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    const bool gaussians = i == 1 || i == 2;  // every_family's sums of Gaussians
    EXPECT_EQ(kernels[i].layout, gaussians ? sss::math::FootprintLayout::gaussian : sss::math::FootprintLayout::cubic)
        << "kernel " << i;
    EXPECT_TRUE(power(kernels[i], gaussians ? 2.5 : 3.0)) << "kernel " << i;
  }
  sss::math::FilterSettings one;
  one.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  one.kernel.rank = 1;
  EXPECT_EQ(sss::math::build_pass_kernel(one).layout, sss::math::FootprintLayout::cubic);
}

// Why the sum of Gaussians takes its own layout: a term's sparse taps on albedo detail of period 1 mm
// (the texturing benchmark's checker, here its fundamental, a cosine) from 2 to 20 pixels per mm
// (0.5 to 0.05 mm per pixel) at every phase. The exact answer is the cosine times the Gaussian's
// attenuation at that frequency, exp(-2π²σ²), at most 1.4e-5 for the three widest terms: what the
// taps return there is their aliasing of the detail. On the cube the widest terms read it almost in
// step; the power 2.5 spreads their taps over the σ-wide cells where the mass lies.
TEST(FootprintKernel, TheSumOfGaussiansWidestTermsDoNotReadFineDetailInStep) {
  sss::math::FilterSettings s;
  s.kernel.family = sss::math::KernelFamily::sum_of_gaussians;
  s.kernel.rank = 6;
  const sss::math::PassKernel kernel = sss::math::build_pass_kernel(s);
  const std::vector<float> cube = sss::math::footprint_spacing(static_cast<int>(kernel.spacing.size()),
                                                               sss::math::FootprintLayout::cubic);
  const auto& gaussians = sss::math::skin_gaussians();
  ASSERT_EQ(kernel.terms.size(), gaussians.size());
  const double kPi = 3.14159265358979323846;
  // The root mean square of (taps' sum - exact) over steps and phases, for a layout.
  const auto aliasing = [&](std::size_t t, const std::vector<float>& spacing) {
    const auto& table = kernel.terms[t].horizontal.footprint;  // normalised to 1 (weight on the vertical)
    const double attenuation = std::exp(-2.0 * kPi * kPi * gaussians[t].variance_mm2);
    double squares = 0.0;
    int count = 0;
    for (int k = 0; k <= 20; ++k) {
      const float step = 2.0f * std::pow(10.0f, static_cast<float>(k) / 20.0f);  // pixels per mm
      const FootprintTaps taps = sss::math::footprint_taps(table, spacing, step);
      for (int q = 0; q < 16; ++q) {
        const double phase = 2.0 * kPi * q / 16.0;
        const auto detail = [&](double x_px) { return std::cos(2.0 * kPi * x_px / step + phase); };
        double sum = taps.weight[0][0] * detail(0.0);
        for (int i = 1; i <= taps.count; ++i) {
          const double p = taps.position[idx(i - 1)];
          sum += taps.weight[idx(i)][0] * (detail(p) + detail(-p));
        }
        const double error = sum - attenuation * detail(0.0);
        squares += error * error;
        ++count;
      }
    }
    return std::sqrt(squares / count);
  };
  for (std::size_t t = 3; t < gaussians.size(); ++t) {
    const double ours = aliasing(t, kernel.spacing), cubic = aliasing(t, cube);
    std::printf("term %zu (variance %.3f mm2): aliasing (rms) %.4f on the Gaussian layout, %.4f on the cube\n", t,
                gaussians[t].variance_mm2, ours, cubic);
    EXPECT_LT(ours, 0.75 * cubic) << "term " << t;  // measured: 0.57, 0.39 and 0.68 of the cube
  }
}

TEST(FootprintKernel, TableInterpolatesTheExactCumulative) {
  // Each skin Gaussian's table against erf, and eq. (1)'s against its closed form.
  double worst = 0.0;
  for (const auto& g : sss::math::skin_gaussians()) {
    const FootprintTable t = sss::math::footprint_table_gaussians({{g.variance_mm2, {1.0, 1.0, 1.0}}});
    for (int i = 0; i <= 1000; ++i) {
      const double x = t.reach_mm * 1.2 * i / 1000.0;
      const double exact = 0.5 * std::erf(x / std::sqrt(2.0 * g.variance_mm2));
      worst = std::max(worst, std::fabs(sss::math::footprint_half_cdf(t, static_cast<float>(x))[0] - exact));
    }
  }
  std::printf("largest table error, skin Gaussians: %.3g of the half mass 0.5\n", worst);
  EXPECT_LE(worst, 1e-4);  // 2e-4 of the mass: kFootprintEntries' stated bound
}

}  // namespace
