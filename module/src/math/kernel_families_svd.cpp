// The kernel families that decompose the profile matrix (Eigen's SVD): SVD rank-N and the
// pre-integrated family with its residual terms (kernel_families.hpp). Tools library only: the
// runtime library builds the closed-form families (kernel_families.cpp) and reaches these through the
// fitters the tools register (fitters.hpp). Math layer: no GL.
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "kernel_families.hpp"

namespace sss::math {

namespace {
std::size_t idx(int i) { return static_cast<std::size_t>(i); }
}  // namespace

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
}  // namespace sss::math
