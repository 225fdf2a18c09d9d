// The d'Eon–Luebke sum-of-Gaussians skin diffusion profile (DESIGN.md §5) and the 1D base profile
// of the separable kernel (paper eq. 1). Math layer: no GL.
#pragma once

#include <array>

namespace sss::math {

// One Gaussian term: variance in mm², 2D-normalised (1 / (2π v)), per-channel weights.
struct GaussianTerm {
  double variance_mm2;
  std::array<double, 3> weight;  // r, g, b
};

// d'Eon and Luebke's six Gaussians for skin. Each channel's weights sum to 1.
const std::array<GaussianTerm, 6>& skin_gaussians();

// 2D-normalised Gaussian exp(-r²/2v) / (2πv).
double gaussian_2d(double variance_mm2, double r_mm);

// The integral of the 2D-normalised Gaussian of variance v, evaluated along a line through its
// centre and scaled radially by `scale` (r -> r / scale), over [a, b] (mm).
double gaussian_2d_line_integral(double variance_mm2, double scale, double a_mm, double b_mm);

// Base 1D profile of the separable kernel: the red channel of the skin profile without its
// narrowest term (that one is the delta the strength parameter stands for), radially scaled by
// 1 / (0.001 + falloff) per channel, integrated over [a, b] mm.
double separable_base_profile_integral(double falloff, double a_mm, double b_mm);

}  // namespace sss::math
