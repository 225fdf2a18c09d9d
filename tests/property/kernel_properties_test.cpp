// Property-based tests of the kernel families (RapidCheck) over generated radial profiles: sums of
// one to three Gaussians with random variances and channel weights, random tap counts and radii.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "math/kernel_families.hpp"

namespace {

using namespace sss::math;

std::size_t idx(int i) { return static_cast<std::size_t>(i); }

// A random skin-like profile: 1-3 Gaussians, variances 0.005..5 mm², weights 0.05..1 per channel.
GaussianSumProfile random_profile() {
  const int n = *rc::gen::inRange(1, 4);
  std::vector<GaussianTerm> terms;
  for (int i = 0; i < n; ++i) {
    GaussianTerm t{};
    t.variance_mm2 = 0.005 * std::pow(1000.0, *rc::gen::inRange(0, 1001) / 1000.0);
    for (double& w : t.weight) w = 0.05 + *rc::gen::inRange(0, 951) / 1000.0;
    terms.push_back(t);
  }
  return GaussianSumProfile(terms);
}

ProfileMatrix random_matrix(const GaussianSumProfile& p) {
  const int taps = 2 * *rc::gen::inRange(2, 9) + 1;  // 5..17
  const double radius = p.extent_mm() * (0.3 + *rc::gen::inRange(0, 71) / 100.0);
  const TapSpacing spacing = *rc::gen::element(TapSpacing::uniform, TapSpacing::quadratic);
  return discretise_profile(p, make_tap_grid(taps, radius, spacing));
}

RC_GTEST_PROP(KernelFamilyProperties, SvdTruncationErrorIsTheSingularValueTail, ()) {
  const ProfileMatrix m = random_matrix(random_profile());
  const auto svd = decompose_profile(m);
  const int c = *rc::gen::inRange(0, 3);
  const int rank = *rc::gen::inRange(1, m.n() + 1);
  const auto a = low_rank_matrix(svd[idx(c)], rank, m.n());
  double err2 = 0.0, tail2 = 0.0;
  for (int i = 0; i < m.n() * m.n(); ++i) err2 += std::pow(a[idx(i)] - m.cells[idx(c)][idx(i)], 2);
  for (std::size_t k = idx(rank); k < svd[idx(c)].singular_values.size(); ++k) tail2 += std::pow(svd[idx(c)].singular_values[k], 2);
  // Eckart–Young; the matrix sums to 1, so absolute 1e-9 is far above rounding.
  RC_ASSERT(std::fabs(std::sqrt(err2) - std::sqrt(tail2)) < 1e-9);
  // Singular values descending and non-negative.
  for (std::size_t k = 1; k < svd[idx(c)].singular_values.size(); ++k) {
    RC_ASSERT(svd[idx(c)].singular_values[k] <= svd[idx(c)].singular_values[k - 1] + 1e-15);
    RC_ASSERT(svd[idx(c)].singular_values[k] >= 0.0);
  }
}

RC_GTEST_PROP(KernelFamilyProperties, PlansConserveEnergy, ()) {
  const GaussianSumProfile p = random_profile();
  const ProfileMatrix m = random_matrix(p);
  const int rank = *rc::gen::inRange(1, 7);
  for (const KernelPlan& plan : {preintegrated_plan(m), svd_plan(m, rank, true), gaussian_sum_plan(p, m.n())}) {
    for (std::size_t c = 0; c < 3; ++c) {
      double gain = 0.0;
      for (const auto& t : plan.terms) {
        double h = 0.0, v = 0.0;
        for (const auto& tap : t.horizontal) h += tap.weight[c];
        for (const auto& tap : t.vertical) v += tap.weight[c];
        gain += h * v;
      }
      RC_ASSERT(std::fabs(gain - 1.0) < 1e-5);  // float weights
    }
  }
}

RC_GTEST_PROP(KernelFamilyProperties, PreintegratedIsExactOnAdditivelySeparableIrradiance, ()) {
  const ProfileMatrix m = random_matrix(random_profile());
  const KernelPlan plan = preintegrated_plan(m);
  // E(x, y) = E1(x) + E2(y): one step edge along each axis plus a linear ramp.
  const double ex = *rc::gen::inRange(-100, 101) / 50.0, ey = *rc::gen::inRange(-100, 101) / 50.0;
  const double sx = *rc::gen::inRange(-10, 11) / 10.0, sy = *rc::gen::inRange(-10, 11) / 10.0;
  const double gx = *rc::gen::inRange(-10, 11) / 10.0, gy = *rc::gen::inRange(-10, 11) / 10.0;
  auto e = [&](double x, double y) { return (x > ex ? sx : 0.0) + gx * x + (y > ey ? sy : 0.0) + gy * y; };
  const double px = *rc::gen::inRange(-100, 101) / 50.0, py = *rc::gen::inRange(-100, 101) / 50.0;
  const std::size_t c = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  double full = 0.0, sep = 0.0;
  for (int i = 0; i < m.n(); ++i) {
    for (int j = 0; j < m.n(); ++j) full += m.at(static_cast<int>(c), i, j) * e(px - m.grid.offsets_mm[idx(i)], py - m.grid.offsets_mm[idx(j)]);
  }
  for (const auto& h : plan.terms[0].horizontal) {
    for (const auto& v : plan.terms[0].vertical) sep += double(h.weight[c]) * v.weight[c] * e(px - h.offset_mm, py - v.offset_mm);
  }
  // Float weights and offsets (2^-24 relative) against |E| ≤ ~10 with the ramps: 1e-5 absolute.
  RC_ASSERT(std::fabs(full - sep) < 1e-5);
}

}  // namespace
