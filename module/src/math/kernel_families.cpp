#include "kernel_families.hpp"

#include <algorithm>
#include <cmath>

#include "separable_kernel.hpp"
#include "skin_profile.hpp"

namespace sss::math {

namespace {

std::size_t idx(int i) { return static_cast<std::size_t>(i); }

// ∫_a^b of the 1D-normalised Gaussian of variance v.
double gaussian_1d_integral(double v, double a, double b) {
  const double k = std::sqrt(2.0 * v);
  return 0.5 * (std::erf(b / k) - std::erf(a / k));
}

}  // namespace

SeparableTerm make_term(const TapGrid& grid, const std::array<std::vector<double>, 3>& horizontal,
                        const std::array<std::vector<double>, 3>& vertical) {
  SeparableTerm term;
  for (int i = 0; i < grid.size(); ++i) {
    KernelTap h{}, v{};
    h.offset_mm = v.offset_mm = static_cast<float>(grid.offsets_mm[idx(i)]);
    for (std::size_t c = 0; c < 3; ++c) {
      h.weight[c] = static_cast<float>(horizontal[c][idx(i)]);
      v.weight[c] = static_cast<float>(vertical[c][idx(i)]);
    }
    term.horizontal.push_back(h);
    term.vertical.push_back(v);
  }
  return term;
}

float plan_reach_mm(const KernelPlan& plan) {
  float reach = 0.0f;
  for (const auto& t : plan.terms) {
    for (const auto* taps : {&t.horizontal, &t.vertical}) {
      for (const auto& tap : *taps) reach = std::max(reach, std::fabs(tap.offset_mm));
    }
    reach = std::max({reach, t.horizontal_table.reach_mm, t.vertical_table.reach_mm});
  }
  return reach;
}

KernelPlan separable_plan(int samples, const std::array<float, 3>& strength, const std::array<float, 3>& falloff,
                          double kernel_mm_per_mm) {
  KernelPlan plan;
  SeparableTerm term;
  term.horizontal = separable_kernel(samples, strength, falloff);
  const double range = kSeparableKernelRangeMm;  // kernel mm
  for (KernelTap& tap : term.horizontal) {
    tap.offset_mm = static_cast<float>(static_cast<double>(tap.offset_mm) / kernel_mm_per_mm);
  }
  term.vertical = term.horizontal;
  Rgb3 norm{}, half_total{}, delta{};
  for (std::size_t c = 0; c < 3; ++c) {
    norm[c] = separable_base_profile_integral(falloff[c], -range, range);
    half_total[c] = 0.5 * strength[c];
    delta[c] = 1.0 - strength[c];
  }
  auto half_cdf = [&](double x_mm) {
    const double x = std::min(x_mm * kernel_mm_per_mm, range);
    Rgb3 out{};
    for (std::size_t c = 0; c < 3; ++c) out[c] = strength[c] * separable_base_profile_integral(falloff[c], 0.0, x) / norm[c];
    return out;
  };
  term.horizontal_table = tabulate_footprint_table(half_cdf, half_total, delta, range / kernel_mm_per_mm);
  term.vertical_table = term.horizontal_table;
  plan.terms.push_back(std::move(term));
  plan.reach_mm = plan_reach_mm(plan);
  return plan;
}

KernelPlan gaussian_sum_plan(const GaussianSumProfile& profile, int taps) {
  KernelPlan plan;
  for (const auto& g : profile.terms()) {
    if (g.weight[0] <= 0.0 && g.weight[1] <= 0.0 && g.weight[2] <= 0.0) continue;  // no pass for nothing
    const TapGrid grid = make_tap_grid(taps, 3.0 * std::sqrt(g.variance_mm2), TapSpacing::uniform);
    std::vector<double> w(idx(taps));
    double sum = 0.0;
    for (int i = 0; i < taps; ++i) {
      w[idx(i)] = gaussian_1d_integral(g.variance_mm2, grid.edges_mm[idx(i)], grid.edges_mm[idx(i) + 1]);
      sum += w[idx(i)];
    }
    for (double& x : w) x /= sum;
    std::array<std::vector<double>, 3> h, v;
    for (std::size_t c = 0; c < 3; ++c) {
      v[c] = w;
      h[c] = w;
      for (double& x : h[c]) x *= g.weight[c];
    }
    plan.terms.push_back(make_term(grid, h, v));
    plan.terms.back().horizontal_table = footprint_table_gaussians({{g.variance_mm2, g.weight}});
    plan.terms.back().vertical_table = footprint_table_gaussians({{g.variance_mm2, {1.0, 1.0, 1.0}}});
  }
  plan.reach_mm = plan_reach_mm(plan);
  // Every term is one Gaussian. A single term stays on the cube: it may be a per-pixel profile
  // (sss_set_profiles takes one-term kernels), and the profiles of a frame share one layout
  // (u_spacing), so each profile gives what it gives alone.
  if (plan.terms.size() > 1) plan.layout = FootprintLayout::gaussian;
  return plan;
}

KernelPlan artist_plan(const ArtistModel& model, int taps) {
  double tau_max = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    tau_max = std::max({tau_max, model.near_variance_mm2[c], model.far_variance_mm2[c]});
  }
  // Quadratic spacing: the near Gaussian is narrow next to the far one's ±3σ reach.
  const TapGrid grid = make_tap_grid(taps, 3.0 * std::sqrt(tau_max), TapSpacing::quadratic);
  std::array<std::vector<double>, 3> w;
  for (std::size_t c = 0; c < 3; ++c) {
    w[c].assign(idx(taps), 0.0);
    double sum = 0.0;
    for (int i = 0; i < taps; ++i) {
      const double a = grid.edges_mm[idx(i)], b = grid.edges_mm[idx(i) + 1];
      const double near = model.near_variance_mm2[c] > 0.0 ? gaussian_1d_integral(model.near_variance_mm2[c], a, b)
                                                            : (a <= 0.0 && 0.0 < b ? 1.0 : 0.0);  // a delta
      const double far = model.far_variance_mm2[c] > 0.0 ? gaussian_1d_integral(model.far_variance_mm2[c], a, b)
                                                          : (a <= 0.0 && 0.0 < b ? 1.0 : 0.0);
      w[c][idx(i)] = model.near_weight[c] * near + (1.0 - model.near_weight[c]) * far;
      sum += w[c][idx(i)];
    }
    for (double& x : w[c]) x /= sum;
  }
  KernelPlan plan;
  plan.terms.push_back(make_term(grid, w, w));
  plan.terms.back().depth_variance_mm2 = static_cast<float>(tau_max);
  std::vector<LineGaussian> mixture;
  for (std::size_t c = 0; c < 3; ++c) {
    LineGaussian near{model.near_variance_mm2[c], {}}, far{model.far_variance_mm2[c], {}};
    near.weight[c] = model.near_weight[c];
    far.weight[c] = 1.0 - model.near_weight[c];
    mixture.push_back(near);
    mixture.push_back(far);
  }
  plan.terms.back().horizontal_table = footprint_table_gaussians(mixture);
  plan.terms.back().vertical_table = plan.terms.back().horizontal_table;
  plan.reach_mm = plan_reach_mm(plan);
  return plan;
}

}  // namespace sss::math
