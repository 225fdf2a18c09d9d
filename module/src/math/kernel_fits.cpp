#include "kernel_fits.hpp"

#ifndef SSS_NO_NLOPT
#include <nlopt.h>
#endif

#include <algorithm>
#include <cmath>

#include "kernel_families.hpp"
#include "separable_kernel.hpp"
#include "skin_profile.hpp"

namespace sss::math {

namespace {

constexpr double kPi = 3.14159265358979323846;
std::size_t idx(int i) { return static_cast<std::size_t>(i); }

// ---- Guided rank-1.

struct GuidedProblem {
  int n;
  std::vector<double> k;  // K_ij, one channel
  std::vector<double> w;  // Γ_ij / (A_i A_j), scaled to max 1
  double target;          // Σ K
  int evaluations = 0;
};

[[maybe_unused]] double guided_objective(unsigned n, const double* a, double* grad, void* data) {
  auto* p = static_cast<GuidedProblem*>(data);
  ++p->evaluations;
  double f = 0.0;
  if (grad) std::fill(grad, grad + n, 0.0);
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) {
      const std::size_t ij = i * n + j;
      const double r = p->k[ij] - a[i] * a[j];
      f += p->w[ij] * r * r;
      // Symmetric W and K: ∂f/∂a_i = −4 Σ_j W_ij r_ij a_j.
      if (grad) grad[i] -= 4.0 * p->w[ij] * r * a[j];
    }
  }
  return f;
}

[[maybe_unused]] double guided_constraint(unsigned n, const double* a, double* grad, void* data) {
  const auto* p = static_cast<const GuidedProblem*>(data);
  double s = 0.0;
  for (unsigned i = 0; i < n; ++i) s += a[i];
  if (grad) std::fill(grad, grad + n, 2.0 * s);
  return s * s - p->target;
}

// The density a_i / A_i of `from` interpolated linearly at the cells of `to`, times their widths.
std::vector<double> resample_taps(const TapGrid& from, const std::vector<double>& a, const TapGrid& to) {
  std::vector<double> density(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) density[i] = a[i] / (from.edges_mm[i + 1] - from.edges_mm[i]);
  std::vector<double> out(idx(to.size()));
  for (int i = 0; i < to.size(); ++i) {
    const double x = to.offsets_mm[idx(i)];
    const auto it = std::lower_bound(from.offsets_mm.begin(), from.offsets_mm.end(), x);
    std::size_t hi = static_cast<std::size_t>(it - from.offsets_mm.begin());
    hi = std::clamp<std::size_t>(hi, 1, from.offsets_mm.size() - 1);
    const std::size_t lo = hi - 1;
    const double t = std::clamp((x - from.offsets_mm[lo]) / (from.offsets_mm[hi] - from.offsets_mm[lo]), 0.0, 1.0);
    out[idx(i)] = ((1.0 - t) * density[lo] + t * density[hi]) * (to.edges_mm[idx(i) + 1] - to.edges_mm[idx(i)]);
  }
  return out;
}

}  // namespace

double guide(double x, double y, double k, double b) {
  return std::pow(x * x + y * y, 0.5 * k) * (1.0 - std::exp(-b * x * x)) * (1.0 - std::exp(-b * y * y));
}

GuidedFit guided_fit(const RadialProfile& profile, int taps, double radius_mm, double k) {
  std::vector<int> levels;
  for (int n = 9; n < taps; n = 2 * n - 1) levels.push_back(n);
  levels.push_back(taps);

  GuidedFit fit;
  TapGrid previous_grid;
  std::array<std::vector<double>, 3> previous;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const int n = levels[level];
    const TapGrid grid = make_tap_grid(n, radius_mm, TapSpacing::uniform);
    ProfileMatrix m = discretise_profile(profile, grid);
    // Γ averaged over each cell (4-point Gauss-Legendre per axis), divided by the cell areas: the
    // discrete sum then approximates ∫ Γ (R − a a)² for any grid. Point values at the cell centres
    // would give the centre row and column zero weight (Γ vanishes on the axes) and leave the centre
    // tap free to soak up the L1 constraint.
    static constexpr double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static constexpr double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    std::vector<double> w(idx(n * n));
    double wmax = 0.0;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double xa = grid.edges_mm[idx(i)], xb = grid.edges_mm[idx(i) + 1];
        const double ya = grid.edges_mm[idx(j)], yb = grid.edges_mm[idx(j) + 1];
        double avg = 0.0;
        for (int p = 0; p < 4; ++p) {
          for (int q = 0; q < 4; ++q) {
            const double x = 0.5 * (xa + xb) + 0.5 * (xb - xa) * gx[p];
            const double y = 0.5 * (ya + yb) + 0.5 * (yb - ya) * gx[q];
            avg += 0.25 * gw[p] * gw[q] * guide(x / radius_mm, y / radius_mm, k);
          }
        }
        w[idx(i * n + j)] = avg / ((xb - xa) * (yb - ya));
        wmax = std::max(wmax, w[idx(i * n + j)]);
      }
    }
    for (double& x : w) x /= wmax;
    const auto start = level == 0 ? preintegrated_taps(m) : previous;
    for (std::size_t c = 0; c < 3; ++c) {
      GuidedProblem problem{n, m.cells[c], w, 0.0};
      for (double x : problem.k) problem.target += x;
      std::vector<double> a = level == 0 ? start[c] : resample_taps(previous_grid, start[c], grid);
      double sum = 0.0;
      for (double x : a) sum += x;
      for (double& x : a) x *= std::sqrt(problem.target) / sum;  // start on the constraint

#ifdef SSS_NO_NLOPT
      throw OptimiserUnavailable("the guided rank-1 fit");
#else
      nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, static_cast<unsigned>(n));
      nlopt_set_min_objective(opt, guided_objective, &problem);
      nlopt_add_equality_constraint(opt, guided_constraint, &problem, 1e-12);
      nlopt_set_lower_bounds1(opt, 0.0);
      nlopt_set_xtol_rel(opt, 1e-9);
      nlopt_set_ftol_rel(opt, 1e-14);
      nlopt_set_maxeval(opt, 3000);
      double f = 0.0;
      nlopt_optimize(opt, a.data(), &f);  // a stays the best point found whatever the stop reason
      nlopt_destroy(opt);
#endif
      fit.evaluations += problem.evaluations;
      previous[c] = std::move(a);
    }
    previous_grid = grid;
    if (level + 1 == levels.size()) fit.matrix = std::move(m);
  }
  fit.taps = previous;
  return fit;
}

double guided_radius_mm(const RadialProfile& profile) { return radius_enclosing(profile, 0.9); }

KernelPlan guided_plan(const RadialProfile& profile, int taps, double radius_mm, double k) {
  const GuidedFit fit = guided_fit(profile, taps, radius_mm, k);
  KernelPlan plan;
  plan.terms.push_back(make_term(fit.matrix.grid, fit.taps, fit.taps));
  plan.reach_mm = plan_reach_mm(plan);
  return plan;
}

// ---- Sum of Gaussians fit.

namespace {

struct GaussianFitProblem {
  int count;
  std::vector<double> r;                      // sample radii
  std::array<std::vector<double>, 3> target;  // encircled energy E_c(r) / ‖R_c‖
  int evaluations = 0;
};

// x = [log v_0..N-1, w_r(0..N-1), w_g(...), w_b(...)]. Residuals on the encircled energy: what a
// blurred image sees, and it keeps the dipole's long tail in the fit (a fit of the density puts
// too little energy out there).
[[maybe_unused]] double gaussian_fit_objective(unsigned n, const double* x, double* grad, void* data) {
  auto* p = static_cast<GaussianFitProblem*>(data);
  ++p->evaluations;
  const int count = p->count;
  if (grad) std::fill(grad, grad + n, 0.0);
  double f = 0.0;
  std::vector<double> e(idx(count)), de(idx(count));
  for (std::size_t s = 0; s < p->r.size(); ++s) {
    const double r2 = p->r[s] * p->r[s];
    for (int i = 0; i < count; ++i) {
      const double u = r2 / (2.0 * std::exp(x[i]));
      e[idx(i)] = 1.0 - std::exp(-u);  // a 2D Gaussian's encircled energy
      de[idx(i)] = -u * std::exp(-u);  // its derivative in log v
    }
    for (int c = 0; c < 3; ++c) {
      double model = 0.0;
      for (int i = 0; i < count; ++i) model += x[count * (1 + c) + i] * e[idx(i)];
      const double res = model - p->target[idx(c)][s];
      f += res * res;
      if (grad) {
        for (int i = 0; i < count; ++i) {
          grad[i] += 2.0 * res * x[count * (1 + c) + i] * de[idx(i)];
          grad[count * (1 + c) + i] += 2.0 * res * e[idx(i)];
        }
      }
    }
  }
  return f;
}

struct ChannelSum {
  int count, channel;
};
[[maybe_unused]] double weights_sum_constraint(unsigned n, const double* x, double* grad, void* data) {
  const auto* cs = static_cast<const ChannelSum*>(data);
  if (grad) std::fill(grad, grad + n, 0.0);
  double s = 0.0;
  for (int i = 0; i < cs->count; ++i) {
    s += x[cs->count * (1 + cs->channel) + i];
    if (grad) grad[cs->count * (1 + cs->channel) + i] = 1.0;
  }
  return s - 1.0;
}

}  // namespace

std::vector<GaussianTerm> fit_gaussian_sum(const RadialProfile& profile, int count) {
  const double extent = profile.extent_mm();
  const Rgb total = profile.integral();
  GaussianFitProblem p;
  p.count = count;
  const int samples = 240;
  Rgb cumulative{};
  static constexpr double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static constexpr double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  for (int s = 0; s < samples; ++s) {
    // Quadratic in r: dense near the peak, where the narrow Gaussians must fit. The encircled
    // energy accumulates 2πr R(r) by 4-point Gauss-Legendre per interval.
    const double t0 = static_cast<double>(s) / samples, t1 = static_cast<double>(s + 1) / samples;
    const double r0 = extent * t0 * t0, r1 = extent * t1 * t1;
    for (int q = 0; q < 4; ++q) {
      const double r = 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * gx[q];
      const Rgb v = profile.evaluate(r);
      for (std::size_t c = 0; c < 3; ++c) cumulative[c] += 0.5 * (r1 - r0) * gw[q] * 2.0 * kPi * r * v[c];
    }
    p.r.push_back(r1);
    for (std::size_t c = 0; c < 3; ++c) p.target[c].push_back(total[c] > 0.0 ? cumulative[c] / total[c] : 0.0);
  }
  const unsigned n = static_cast<unsigned>(4 * count);
  std::vector<double> x(n), lo(n), hi(n);
  const double vmin = std::pow(extent / 400.0, 2), vmax = std::pow(extent / 3.0, 2);
  for (int i = 0; i < count; ++i) {
    // Start with variances spread geometrically over the profile's scales, equal weights.
    const double t = count == 1 ? 0.5 : static_cast<double>(i) / (count - 1);
    x[idx(i)] = std::log(vmin * 4.0) + t * (std::log(vmax / 2.0) - std::log(vmin * 4.0));
    lo[idx(i)] = std::log(vmin);
    hi[idx(i)] = std::log(vmax);
    for (int c = 0; c < 3; ++c) {
      x[idx(count * (1 + c) + i)] = 1.0 / count;
      lo[idx(count * (1 + c) + i)] = 0.0;
      hi[idx(count * (1 + c) + i)] = 1.0;
    }
  }
#ifdef SSS_NO_NLOPT
  throw OptimiserUnavailable("the sum-of-Gaussians fit");
#else
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, n);
  nlopt_set_min_objective(opt, gaussian_fit_objective, &p);
  std::array<ChannelSum, 3> sums = {{{count, 0}, {count, 1}, {count, 2}}};
  for (auto& cs : sums) nlopt_add_equality_constraint(opt, weights_sum_constraint, &cs, 1e-12);
  nlopt_set_lower_bounds(opt, lo.data());
  nlopt_set_upper_bounds(opt, hi.data());
  nlopt_set_xtol_rel(opt, 1e-8);
  nlopt_set_maxeval(opt, 4000);
  double f = 0.0;
  nlopt_optimize(opt, x.data(), &f);
  nlopt_destroy(opt);
#endif

  std::vector<GaussianTerm> terms(idx(count));
  for (int i = 0; i < count; ++i) {
    terms[idx(i)].variance_mm2 = std::exp(x[idx(i)]);
    for (int c = 0; c < 3; ++c) terms[idx(i)].weight[idx(c)] = std::max(0.0, x[idx(count * (1 + c) + i)]);
  }
  std::sort(terms.begin(), terms.end(), [](const GaussianTerm& a, const GaussianTerm& b) { return a.variance_mm2 < b.variance_mm2; });
  return terms;
}

// ---- Separable eq. (1) fit.

namespace {

struct SeparableProblem {
  ProfileMatrix target;
  int evaluations = 0;
};

// The 1D eq. (1) kernel on the target's cells for one channel: t·p(x·scale/(0.001+f)) integrated
// over each cell and normalised over the grid, plus (1 − t) on the centre cell.
std::vector<double> eq1_cells(const TapGrid& grid, double scale, double t, double f) {
  std::vector<double> s(idx(grid.size()));
  double sum = 0.0;
  for (int i = 0; i < grid.size(); ++i) {
    // ∫_a^b p(x·scale/(0.001+f)) dx = (1/scale) ∫_{a·scale}^{b·scale} p(u/(0.001+f)) du.
    s[idx(i)] = separable_base_profile_integral(f, grid.edges_mm[idx(i)] * scale, grid.edges_mm[idx(i) + 1] * scale);
    sum += s[idx(i)];
  }
  for (double& x : s) x = sum > 0.0 ? t * x / sum : 0.0;
  s[idx(grid.size() / 2)] += 1.0 - t;
  return s;
}

// x = [scale, t_r, t_g, t_b, f_r, f_g, f_b]: eq. (3), Σ over cells and channels of (K − s sᵀ)².
double separable_objective(unsigned, const double* x, double*, void* data) {
  auto* p = static_cast<SeparableProblem*>(data);
  ++p->evaluations;
  const int n = p->target.n();
  double f = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto s = eq1_cells(p->target.grid, x[0], x[1 + c], x[4 + c]);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double r = p->target.at(c, i, j) - s[idx(i)] * s[idx(j)];
        f += r * r;
      }
    }
  }
  return f;
}

}  // namespace

double separable_residual(const ProfileMatrix& target, double scale, const std::array<double, 3>& strength,
                          const std::array<double, 3>& falloff) {
  SeparableProblem p{target};
  const double x[7] = {scale, strength[0], strength[1], strength[2], falloff[0], falloff[1], falloff[2]};
  return separable_objective(7, x, nullptr, &p);
}

SeparableFit fit_separable(const RadialProfile& target, int taps, double radius_mm, TapSpacing spacing) {
  SeparableProblem p{discretise_profile(target, make_tap_grid(taps, radius_mm, spacing))};
  // Start from the reference implementation's defaults (DESIGN.md §5) at scale 1.
  std::vector<double> x = {1.0, 0.48, 0.41, 0.28, 1.0, 0.37, 0.3};
  const std::vector<double> lo = {0.05, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const std::vector<double> hi = {20.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  double f = 0.0;
#ifdef SSS_NO_NLOPT
  throw OptimiserUnavailable("the eq. (2-3) separable fit");
#else
  nlopt_opt opt = nlopt_create(NLOPT_LN_BOBYQA, 7);
  nlopt_set_min_objective(opt, separable_objective, &p);
  nlopt_set_lower_bounds(opt, lo.data());
  nlopt_set_upper_bounds(opt, hi.data());
  nlopt_set_xtol_rel(opt, 1e-7);
  nlopt_set_maxeval(opt, 20000);
  nlopt_optimize(opt, x.data(), &f);
  nlopt_destroy(opt);
#endif
  return SeparableFit{x[0], {x[1], x[2], x[3]}, {x[4], x[5], x[6]}, f, p.evaluations};
}

}  // namespace sss::math
