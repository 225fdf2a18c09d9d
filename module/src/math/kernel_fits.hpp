// The optimisation-based kernels (NLopt): the eq. (2-3) fit of the separable kernel's width,
// strength and falloff, the guided rank-1 fit (supplementary S.7-S.9) and a sum-of-Gaussians fit
// of any radial profile. Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "fitters.hpp"
#include "kernel_plan.hpp"
#include "profile_grid.hpp"
#include "radial_profile.hpp"

namespace sss::math {

// A build without NLopt (SSS_NO_NLOPT) throws OptimiserUnavailable (fitters.hpp) from the fits below.

// ---- Guided rank-1 (S.7-S.9).
inline constexpr double kGuideB = 50.0;          // suppression along the axes, on [-1, 1]²
inline constexpr double kGuideDefaultK = 1.55;   // the supplementary's Figure S.1b

// Γ(x, y; k) = (x² + y²)^(k/2) (1 − e^{−b x²})(1 − e^{−b y²}), x and y in [-1, 1].
double guide(double x, double y, double k, double b = kGuideB);

// a minimising ∫ Γ (R − a(x)a(y))² subject to ‖a‖₁² = ‖R‖₁, per channel: discretised on a
// uniform grid of `taps` cells on ±radius_mm (scaled to [-1, 1] for Γ) as
// Σ_ij Γ̄_ij (K_ij − a_i a_j)² / (A_i A_j), K the cell integrals, A the cell widths, Γ̄ the guide
// averaged over the cell. Uniform, not quadratic: the guide vanishes on the axes, and the tiny
// centre cells of a quadratic grid would let the centre tap absorb the L1 constraint almost for
// free (a spike the continuous problem also allows in the limit of a vanishing cell).
// The default radius (guided_radius_mm) is where every channel holds 90% of its energy. SLSQP, coarse to fine: 9, 17, 33, … taps up
// to `taps`, each level started from the previous solution interpolated as a density, the first
// from the pre-integrated taps. Returns the taps a per channel on the final grid (Σ a = 1).
struct GuidedFit {
  ProfileMatrix matrix;                // the final level's matrix (for comparisons)
  std::array<std::vector<double>, 3> taps;
  int evaluations = 0;
};
GuidedFit guided_fit(const RadialProfile& profile, int taps, double radius_mm, double k);
KernelPlan guided_plan(const RadialProfile& profile, int taps, double radius_mm, double k);
double guided_radius_mm(const RadialProfile& profile);

// ---- Sum of N Gaussians fitted to a profile (d'Eon et al.'s L1 constraint: weights sum to 1).
// Minimises Σ_r (E(r)/‖R‖ − Σ w_i E_i(r))², E the encircled energy, on 240 radii out to the extent
// (quadratically denser near 0); variances shared by the channels, per-channel weights ≥ 0 summing
// to 1; NLopt SLSQP with analytic gradients in log variance.
std::vector<GaussianTerm> fit_gaussian_sum(const RadialProfile& profile, int count);

// ---- Separable eq. (1) fit (paper eq. 2-3).
struct SeparableFit {
  double scale;                   // kernel profile mm per target mm (width ∝ 1 / scale, see docs)
  std::array<double, 3> strength;
  std::array<double, 3> falloff;
  double residual;                // f_s of eq. (3) at the optimum
  int evaluations;
};
// Fits s(x) = t·p(x·scale/(0.001+f)) + (1−t)δ(x), as the 2D kernel s(x)s(y), to the profile's 2D
// cell integrals on a quadratic grid (denser near the centre) of `taps` cells out to `radius_mm`.
// Eq. (3) on a given matrix: Σ over channels and cells of (K − s sᵀ)², s the eq. (1) kernel's cells.
double separable_residual(const ProfileMatrix& target, double scale, const std::array<double, 3>& strength,
                          const std::array<double, 3>& falloff);
SeparableFit fit_separable(const RadialProfile& target, int taps, double radius_mm,
                           TapSpacing spacing = TapSpacing::quadratic);

}  // namespace sss::math
