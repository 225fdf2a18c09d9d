#include "kernel_families.hpp"

#include <Eigen/SVD>
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
  const double range = separable_kernel_range_mm(samples);  // kernel mm
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
  return plan;
}

std::array<ChannelSvd, 3> decompose_profile(const ProfileMatrix& m) {
  const int n = m.n();
  std::array<ChannelSvd, 3> out;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd a(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) a(i, j) = m.at(c, i, j);
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    ChannelSvd& s = out[idx(c)];
    for (int k = 0; k < n; ++k) {
      s.singular_values.push_back(svd.singularValues()(k));
      std::vector<double> u(idx(n)), v(idx(n));
      double usum = 0.0;
      for (int i = 0; i < n; ++i) {
        u[idx(i)] = svd.matrixU()(i, k);
        v[idx(i)] = svd.matrixV()(i, k);
        usum += u[idx(i)];
      }
      if (usum < 0.0) {  // u σ vᵀ is unchanged when both flip
        for (int i = 0; i < n; ++i) u[idx(i)] = -u[idx(i)], v[idx(i)] = -v[idx(i)];
      }
      s.u.push_back(std::move(u));
      s.v.push_back(std::move(v));
    }
  }
  return out;
}

std::vector<double> low_rank_matrix(const ChannelSvd& svd, int rank, int n) {
  std::vector<double> a(idx(n * n), 0.0);
  for (int k = 0; k < rank; ++k) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        a[idx(i * n + j)] += svd.singular_values[idx(k)] * svd.u[idx(k)][idx(i)] * svd.v[idx(k)][idx(j)];
      }
    }
  }
  return a;
}

KernelPlan svd_plan(const ProfileMatrix& m, int rank, bool rescale_energy) {
  const int n = m.n();
  rank = std::clamp(rank, 1, n);
  const auto svd = decompose_profile(m);
  std::vector<std::array<std::vector<double>, 3>> h(idx(rank)), v(idx(rank));
  for (std::size_t c = 0; c < 3; ++c) {
    double plan_sum = 0.0;
    for (int k = 0; k < rank; ++k) {
      const double root = std::sqrt(svd[c].singular_values[idx(k)]);
      h[idx(k)][c] = svd[c].u[idx(k)];
      v[idx(k)][c] = svd[c].v[idx(k)];
      double hs = 0.0, vs = 0.0;
      for (int i = 0; i < n; ++i) {
        h[idx(k)][c][idx(i)] *= root;
        v[idx(k)][c][idx(i)] *= root;
        hs += h[idx(k)][c][idx(i)];
        vs += v[idx(k)][c][idx(i)];
      }
      plan_sum += hs * vs;
    }
    double matrix_sum = 0.0;
    for (double x : m.cells[c]) matrix_sum += x;
    if (rescale_energy && plan_sum != 0.0) {
      for (int k = 0; k < rank; ++k) {
        for (double& x : h[idx(k)][c]) x *= matrix_sum / plan_sum;
      }
    }
  }
  KernelPlan plan;
  for (int k = 0; k < rank; ++k) plan.terms.push_back(make_term(m.grid, h[idx(k)], v[idx(k)]));
  plan.reach_mm = plan_reach_mm(plan);
  return plan;
}

Rgb first_singular_energy_fraction(const std::array<ChannelSvd, 3>& svd) {
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    double total = 0.0;
    for (double s : svd[c].singular_values) total += s * s;
    out[c] = total > 0.0 ? svd[c].singular_values[0] * svd[c].singular_values[0] / total : 0.0;
  }
  return out;
}

std::array<std::vector<double>, 3> preintegrated_taps(const ProfileMatrix& m) {
  const int n = m.n();
  std::array<std::vector<double>, 3> a;
  for (int c = 0; c < 3; ++c) {
    a[idx(c)].assign(idx(n), 0.0);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) a[idx(c)][idx(i)] += m.at(c, i, j);
    }
  }
  return a;
}

KernelPlan preintegrated_plan(const ProfileMatrix& m, int rank) {
  const int n = m.n();
  const auto a = preintegrated_taps(m);
  auto h = a;
  std::array<double, 3> norm{};  // ‖R‖₁ = Σ a_p (the matrix is non-negative)
  for (std::size_t c = 0; c < 3; ++c) {
    for (double x : a[c]) norm[c] += x;
    if (norm[c] > 0.0) {
      for (double& x : h[c]) x /= norm[c];
    }
  }
  KernelPlan plan;
  plan.terms.push_back(make_term(m.grid, h, a));
  rank = std::clamp(rank, 1, n);
  if (rank > 1) {
    // The residual R − h aᵀ and its SVD; term k: √σ_k u_k horizontally, √σ_k v_k vertically.
    ProfileMatrix residual = m;
    for (std::size_t c = 0; c < 3; ++c) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) residual.cells[c][idx(i * n + j)] -= h[c][idx(i)] * a[c][idx(j)];
      }
    }
    const auto svd = decompose_profile(residual);
    for (int k = 0; k + 1 < rank; ++k) {
      std::array<std::vector<double>, 3> hk, vk;
      for (std::size_t c = 0; c < 3; ++c) {
        const double root = std::sqrt(svd[c].singular_values[idx(k)]);
        hk[c] = svd[c].u[idx(k)];
        vk[c] = svd[c].v[idx(k)];
        for (int i = 0; i < n; ++i) {
          hk[c][idx(i)] *= root;
          vk[c][idx(i)] *= root;
        }
      }
      plan.terms.push_back(make_term(m.grid, hk, vk));
    }
  }
  plan.reach_mm = plan_reach_mm(plan);
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
