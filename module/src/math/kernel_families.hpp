// The kernel families of the separable SSS paper and its supplementary, each built into a
// KernelPlan (kernel_plan.hpp) that the gl layer runs. Math layer: no GL.
//
// Every plan redistributes irradiance: each channel's kernel sums to 1 (the diffuse albedo stays the
// host's), except where a family's definition says otherwise (SVD without rescaling).
#pragma once

#include <array>
#include <vector>

#include "kernel_plan.hpp"
#include "profile_grid.hpp"
#include "radial_profile.hpp"

namespace sss::math {

// (a) Paper eq. (1): one term, the separable_kernel() taps both ways, its offsets divided by
// kernel_mm_per_mm (the kernel's own millimetres per millimetre of the surface: the calibration
// that makes it physical, see sss_settings.separable_scale). Its footprint table is the kernel's
// closed form: strength times the base profile over ±R normalised, plus 1 − strength at the centre.
KernelPlan separable_plan(int samples, const std::array<float, 3>& strength, const std::array<float, 3>& falloff,
                          double kernel_mm_per_mm = 1.0);

// (c) Sum of Gaussians (d'Eon et al. 2007): one term per Gaussian, 2N passes. Each term's taps are
// uniform on ±3σ of that Gaussian, its weights the 1D Gaussian integrated over each cell and
// renormalised (the 0.27% outside ±3σ is folded back); the channel weights go on the horizontal pass.
// Each channel's weights sum to 1 because the profile's do.
// Each term's footprint table is its Gaussian in closed form (the channel weights on the horizontal
// one), so the footprint-aware passes run the exact discrete sum of Gaussians on a plane, with the
// sparse taps of a Gaussian (FootprintLayout::gaussian) from two terms on (one term keeps the cube:
// it may be a per-pixel profile, and a frame's profiles share one layout).
KernelPlan gaussian_sum_plan(const GaussianSumProfile& profile, int taps);

// Singular value decomposition of each channel's profile matrix (supplementary S.2), descending.
struct ChannelSvd {
  std::vector<double> singular_values;
  std::vector<std::vector<double>> u;  // u[i]: the i-th left singular vector (along x)
  std::vector<std::vector<double>> v;  // v[i]: the i-th right singular vector (along y)
};
std::array<ChannelSvd, 3> decompose_profile(const ProfileMatrix& m);

// (d) SVD rank-N (S.4): term i is √σ_i u_i horizontally and √σ_i v_i vertically (signs chosen so
// each u_i sums to ≥ 0). rescale_energy: every channel scaled so the plan sums to the matrix's sum
// (1), the energy conservation of S.4 (for the sign-definite rank-1 term the same as the L1 ratio).
KernelPlan svd_plan(const ProfileMatrix& m, int rank, bool rescale_energy);

// σ1² / Σσ² per channel: the share of the matrix's Frobenius energy in the first term.
Rgb first_singular_energy_fraction(const std::array<ChannelSvd, 3>& svd);

// The rank-N approximation U Σ_N Vᵀ of channel c as a dense n×n matrix (row i along x).
std::vector<double> low_rank_matrix(const ChannelSvd& svd, int rank, int n);

// (e) Pre-integrated (S.5-S.6): a_p(x) = Σ_y R(x, y), the profile matrix's row sums, both ways,
// divided once by ‖R‖₁. Exact for additively separable irradiance E1(x) + E2(y).
// rank > 1 adds the first rank − 1 terms of the SVD of the residual R − a_p a_pᵀ / ‖R‖₁ (ours, not
// the supplementary's). The residual's rows and columns sum to 0, so its singular vectors do too:
// the added terms move no light along either axis, and the kernel stays exact for additively
// separable irradiance (a straight shadow edge along an axis) while its 2D shape, where light varies
// both ways (a spot, a corner), comes closer to the profile's with each term.
KernelPlan preintegrated_plan(const ProfileMatrix& m, int rank = 1);
std::array<std::vector<double>, 3> preintegrated_taps(const ProfileMatrix& m);  // a_p per channel

// (g) The artist-friendly model (supplementary §E): per channel a'(x) = w·G(x; τ_near) +
// (1 - w)·G(x; τ_far), 1D Gaussians integrated over each tap's cell (area integration), normalised,
// both ways; one term whose depth correction is exp(-dz² / 2τ_max), τ_max the largest variance.
struct ArtistModel {
  Rgb near_variance_mm2;
  Rgb far_variance_mm2;
  Rgb near_weight;  // w in [0, 1]
};
KernelPlan artist_plan(const ArtistModel& model, int taps);

// A plan term from per-channel 1D weights on a grid (shared by the builders and the fits).
SeparableTerm make_term(const TapGrid& grid, const std::array<std::vector<double>, 3>& horizontal,
                        const std::array<std::vector<double>, 3>& vertical);
// The largest |offset| of any tap in the plan, or reach of a term's footprint table if larger.
float plan_reach_mm(const KernelPlan& plan);

}  // namespace sss::math
