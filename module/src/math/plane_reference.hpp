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
#include "surface.hpp"

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

// A plane at any orientation under an orthographic camera
// -------------------------------------------------------
// There every pixel has the same tangents T_x, T_y (surface.hpp), so every source footprint is the
// same rectangle: sides a = |T_x| along t1 = T_x / a and b = |T_x x T_y| / a along t2, in the plane.
// The source d = (Δi, Δj) pixels from a receiver lies at Δi T_x + Δj T_y from it, which is
// u0 = aΔi + cΔj along t1 and v0 = bΔj along t2 with c = T_y · t1 (the shift along t1 from one row
// to the next: 0 where the rows' steps are perpendicular on the surface), and h = 0. So the 2D
// reference's I_t (exact_reference.hpp) is a product of two pixel integrals, and exactly
//
//   M_c(p) = Σ_t w_t,c Σ_Δj K_b,t(Δj) Σ_Δi K_a,t(Δi, Δj) E_c(p + (Δi, Δj))
//
//   K_b,t(Δj)     = ½ [erf((bΔj + b/2) / √(2v)) - erf((bΔj - b/2) / √(2v))]
//   K_a,t(Δi, Δj) = ½ [erf((aΔi + cΔj + a/2) / √(2v)) - erf((aΔi + cΔj - a/2) / √(2v))]
//
// With c = 0 it is convolve_fronto_parallel_plane's product of 1D convolutions; otherwise each row
// offset Δj takes its own fractional shift of the row kernel, so it does not separate, and it is
// summed as a 2D convolution (the terms' weights added into one 2D kernel per channel first). The
// same rules as the facing plane: factors below 1e-18 skipped, sources past the frame absent.
struct TurnedPlaneFootprint {
  double a_mm = 0.0;  // |T_x|: the side along t1
  double b_mm = 0.0;  // |T_x x T_y| / a: the side along t2
  double c_mm = 0.0;  // T_y · t1: one row's shift along t1
};

// a, b and c of tangents given in millimetres. Throws std::invalid_argument when they span no area.
TurnedPlaneFootprint turned_plane_footprint(const Vec3& tx_mm, const Vec3& ty_mm);

// a, b and c at pixel (x, y) of a width x height frame for the projection m and the plane through
// `point` with normal `normal` (view space, world units): the tangents as surface.hpp's central
// differences take them from the plane's depth at the neighbouring pixels' centres (the same at
// every pixel under an orthographic m). Throws std::invalid_argument when a neighbour's ray misses
// the plane or meets it behind the camera.
TurnedPlaneFootprint turned_plane_footprint(const Matrix4& m, int width, int height, const Vec3& point,
                                            const Vec3& normal, double world_units_per_mm, int x, int y);

struct TurnedPlaneInput {
  int width = 0, height = 0;
  const float* irradiance = nullptr;  // RGBA (alpha ignored), row 0 at the bottom; every pixel on the plane
  TurnedPlaneFootprint footprint;
};

// M for the pixels of `receivers` into out_rgb (width · height · 3 doubles, row 0 at the bottom; the
// other pixels are not written). Cost: receivers × the kernel's taps (every source pixel within
// about 6.5 σ of the widest term, per channel). Rows of receivers are split over `threads`
// (0: std::thread::hardware_concurrency()); each receiver is summed in a fixed order, so the result
// does not depend on the thread count. Throws std::invalid_argument on a bad size, a null pointer,
// a footprint that is not finite with a, b > 0, or a region outside the frame.
void convolve_turned_plane(const TurnedPlaneInput& input, const GaussianProfile& profile, const PixelRegion& receivers,
                           double* out_rgb, int threads = 0);

}  // namespace sss::math
