// The exact reference for a fronto-parallel plane, as separable 1D convolutions. Math layer: no GL.
//
// Why it is exact
// ---------------
// On a plane facing the camera every pixel's footprint is the same rectangle (sides sx, sy mm) and
// the 3D distance between two pixels is their in-plane distance, so the 2D surface convolution of
// exact_reference.hpp factors: for each Gaussian term t (variance v, per-channel weights w_t,c),
//
//   M_c(x, y) = Σ_t w_t,c Σ_i Σ_j  k_t,x[i - x] · k_t,y[j - y] · E_c(i, j)
//
//   k[d] = ∫ over [(d - ½) s, (d + ½) s] of the 1D-normalised Gaussian of variance v
//        = ½ [erf((d + ½) s / √(2v)) - erf((d - ½) s / √(2v))]
//
// which is exactly I_t of exact_reference.hpp with h = 0, u0 = d·sx, v0 = e·sy (the 2D Gaussian is
// the product of two 1D ones). Each term costs two 1D passes over the image, so any footprint and
// size is cheap. Only taps of weight below 1e-18 are skipped (together under 1e-14 of the light,
// below the double sums' rounding): every source pixel of the frame that matters contributes.
//
// Past the frame edge the plane is taken to end, as the 2D reference does: sources outside the
// frame contribute nothing, and light a receiver would scatter past the edge is lost (the same rule
// as at a silhouette). A renormalising filter instead behaves as if the edge pixels repeated, so
// near the edge the two differ by construction: the benchmark reports that band apart.
#pragma once

#include <vector>

#include "exact_reference.hpp"

namespace sss::math {

// k[d] for d = -radius..radius (2·radius + 1 values, k[radius] is d = 0): the share of a 1D Gaussian
// of variance `variance_mm2` centred on a pixel that falls on the pixel d pixels away (pixel size
// `pixel_mm`). Differences of erfc where both bounds lie on one side of 0, so far tails keep their
// relative precision. Each value is in [0, 1]; the sum over all d (radius -> infinity) is 1.
// Throws std::invalid_argument for variance <= 0, pixel_mm <= 0 or radius < 0.
std::vector<double> pixel_integrated_gaussian(double variance_mm2, double pixel_mm, int radius);

struct PlaneInput {
  int width = 0, height = 0;
  const float* irradiance = nullptr;  // RGBA (alpha ignored), row 0 at the bottom; every pixel on the plane
  double pixel_x_mm = 0.0;            // the footprint's sides (mm)
  double pixel_y_mm = 0.0;
};

// M for every pixel into out_rgb (width · height · 3 doubles, row 0 at the bottom). Throws
// std::invalid_argument on a bad size, a null pointer or a non-positive footprint.
void convolve_fronto_parallel_plane(const PlaneInput& input, const GaussianProfile& profile, double* out_rgb);

// The pixel footprint (mm) of a plane facing the camera at view distance `distance` for the
// projection m (surface.hpp's s_x, s_y, divided by world_units_per_mm): the values the 2D reference
// derives for such a plane, so that both references integrate over the same rectangles.
double plane_pixel_mm_x(const Matrix4& m, int width, double distance, double world_units_per_mm);
double plane_pixel_mm_y(const Matrix4& m, int height, double distance, double world_units_per_mm);

}  // namespace sss::math
