// A screen-space kernel as the GPU runs it: a sum of separable (rank-1) terms plus a share of the
// unfiltered input. Every kernel family (paper eq. 1, sum of Gaussians, SVD rank-N, pre-integrated,
// guided rank-1, the artist two-Gaussian model) is built into this one shape by the math layer, and
// the gl layer runs any plan: one horizontal and one vertical pass per term, accumulated.
// Math layer: no GL.
//
//   out_c(p) = identity_c · in_c(p) + Σ_i  Σ_x Σ_y  h_i,c(x) · v_i,c(y) · in_c(p + (x, y))
//
// per colour channel c, with tap offsets in profile millimetres (scaled on screen per pixel by the
// projected scene scale and the pixel's alpha, exactly as for the eq. (1) kernel).
#pragma once

#include <array>
#include <vector>

#include "footprint_kernel.hpp"
#include "separable_kernel.hpp"

namespace sss::math {

struct SeparableTerm {
  std::vector<KernelTap> horizontal;  // taps along x; weights may be negative (SVD terms)
  std::vector<KernelTap> vertical;    // taps along y
  // > 0: every tap's weight is multiplied by exp(-dz² / (2 · depth_variance_mm2)), dz the depth
  // difference to the centre in profile millimetres (supplementary §E, the exact depth correction
  // of a Gaussian term). 0: the follow-surface setting applies as for eq. (1).
  float depth_variance_mm2 = 0.0f;
  // The terms' continuous 1D kernels for the footprint-aware taps (footprint_kernel.hpp), where the
  // family knows them in closed form (eq. (1), Gaussians); empty: the tap lists above stand for them
  // (each tap's weight spread over its cell).
  FootprintTable horizontal_table, vertical_table;
};

// The most terms a plan has (sum of Gaussians or SVD at rank 6; sss_kernels.h SSS_KERNEL_MAX_TERMS).
inline constexpr std::size_t kMaxPlanTerms = 6;

struct KernelPlan {
  std::vector<SeparableTerm> terms;
  std::array<float, 3> identity = {0.0f, 0.0f, 0.0f};  // share of the unfiltered input per channel
  float reach_mm = 0.0f;  // the largest |offset| of any tap: the follow-surface reach
  // Where the footprint-aware passes put their sparse taps: set by the family, which knows the shape
  // of its terms (footprint_kernel.hpp).
  FootprintLayout layout = FootprintLayout::cubic;
};

}  // namespace sss::math
