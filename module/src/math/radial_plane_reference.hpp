// The exact reference for a fronto-parallel plane with any radial profile (Burley's normalized
// diffusion, a dipole), where plane_reference.hpp's separable form needs Gaussians. Math layer: no GL.
//
// On a plane facing the camera every pixel's footprint is the same rectangle (sx × sy mm) and the
// 3D distance between two pixels is their in-plane distance, so for receiver p and source q
//
//   M_c(p) = Σ_q K_c[q − p] · E_c(q),   K_c[i, j] = ∫∫ R_c over the cell [(i ± ½) sx] × [(j ± ½) sy]
//
// exactly as exact_reference.hpp's I(p, q) with h = 0, now for a profile that is not a sum of
// Gaussians. K comes from rectangle_integral (radial_integrals.hpp): exact at the centre cell,
// where Burley's R is infinite. The kernel is not separable, so each receiver sums every source of
// the frame (no truncation: light from anywhere in the frame counts; the plane ends at the frame
// edge as in plane_reference.hpp): receivers × frame pixels, for the receivers asked for only.
// Deterministic: each receiver's sum in a fixed order, whatever the thread count.
#pragma once

#include <vector>

#include "burley_profile.hpp"
#include "exact_reference.hpp"
#include "plane_reference.hpp"
#include "radial_profile.hpp"

namespace sss::math {

// K[|i|, |j|] for 0 <= i < nx, 0 <= j < ny (the kernel is symmetric in both signs): rectangle
// integrals of `profile` over the cells of a grid of pixel_x_mm × pixel_y_mm pixels centred on it.
class RadialPixelKernel {
 public:
  RadialPixelKernel(const RadialProfile& profile, double pixel_x_mm, double pixel_y_mm, int nx, int ny,
                    int threads = 0);
  const Rgb& at(int i, int j) const;  // |i| < nx, |j| < ny
  double pixel_x_mm() const { return sx_; }
  double pixel_y_mm() const { return sy_; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }

 private:
  int nx_ = 0, ny_ = 0;
  double sx_ = 0.0, sy_ = 0.0;
  std::vector<Rgb> k_;  // k_[j * nx + i]
};

// M for the pixels of `receivers` into out_rgb (width · height · 3 doubles, row 0 at the bottom;
// other pixels are not written); with stride s > 1 only those with x % s == s / 2 and
// y % s == s / 2 (the benchmark's reference grid). Throws std::invalid_argument on a bad size, a
// null pointer, a non-positive footprint or stride, or a region outside the frame.
void convolve_plane_radial(const PlaneInput& input, const RadialProfile& profile, const PixelRegion& receivers,
                           double* out_rgb, int threads = 0, int stride = 1);
// The same with the kernel built once for frames of one pixel size (its cells dominate the cost of
// a few receivers): the kernel must reach the whole frame (nx >= width, ny >= height) and have
// been built for input's pixel sides.
void convolve_plane_radial(const PlaneInput& input, const RadialPixelKernel& kernel, const PixelRegion& receivers,
                           double* out_rgb, int threads = 0, int stride = 1);

// Burley's line (marginal) profile ∫ R(√(x² + y²)) dy over the whole line, per channel: since
// ∫ e^{-√(x²+y²)/c} / √(x²+y²) dy = 2 K0(|x|/c), it is A (K0(|x|/d) + K0(|x|/(3d))) / (4π d), mm⁻¹
// (infinite at x = 0, integrating to A).
Rgb burley_line_profile(const BurleyProfile& profile, double x_mm);

}  // namespace sss::math
