// The exact reference (DESIGN.md §6, reference 1): the 2D surface convolution of the irradiance with
// the full radially symmetric diffusion profile, over the visible translucent surface
// reconstructed from depth, in world-space (millimetre) distances. CPU, double precision: small
// images whole, or chosen pixels of large ones. Math layer: no GL.
//
// What it computes
// ----------------
// For a translucent receiver pixel p (usable in the sense of surface.hpp) and each channel c:
//
//   M_c(p) = sum over usable source pixels q with |P_q - P_p| <= R + hd_q
//              E_c(q) · sum over terms t of  weight_t,c · I_t(p, q)
//
//   I_t(p, q) = the integral of the 2D-normalised Gaussian G_v(r) = exp(-r²/2v) / (2πv),
//               v = variance_t (mm²), r = the 3D distance from P_p, over q's footprint rectangle
//               (surface.hpp: centre P_q, axes t1, t2, sides a, b), irradiance constant on it:
//             = exp(-h²/2v) · ¼ · [erf((u0 + a/2)/√(2v)) - erf((u0 - a/2)/√(2v))]
//                           · [erf((v0 + b/2)/√(2v)) - erf((v0 - b/2)/√(2v))]
//               with Δ = P_q - P_p, u0 = Δ·t1, v0 = Δ·t2, h² = |Δ|² - u0² - v0² (clamped at 0).
//
// All lengths in mm: world positions divided by world_units_per_mm. No renormalisation: each
// channel of the profile integrates to 1 over a plane, so a uniformly lit plane gives M = E and a
// surface that ends (silhouette, mask edge) loses the energy that would have landed beyond it.
// Non-translucent pixels neither receive (their output is their input RGB) nor contribute.
// The alpha channel of the irradiance is ignored (the per-pixel strength belongs to the filters
// under test, not to the physics of the reference).
//
// Truncation
// ----------
// A 2D-normalised Gaussian of variance v has exp(-R²/2v) of its mass beyond radius R, so term t
// is dropped beyond R_t = sqrt(2 v ln(1/tail_mass)) (plus the source footprint's half-diagonal
// hd_q = ½·sqrt(a² + b²), so that no footprint that reaches inside R_t is cut); tail_mass = 1e-9
// loses < 1e-9 of each term's mass, < 1e-9 per channel in all. The profile's cutoff radius R is
// the largest R_t (the widest term with a non-zero weight): 17.5 mm for skin.
//
// Candidate source pixels are restricted to the screen rectangle that holds the projection of the
// axis-aligned box of half-side R + h0 (world units) around P_p: with w > 0 over the box, NDC x and
// y are monotone in each coordinate, so the corners bound it (conservative; if w <= 0 somewhere
// in the box, the whole image is scanned). h0 is the 99th percentile of the footprints'
// half-diagonals; the few pixels with larger ones (grazing or isolated pixels) are checked
// explicitly for every receiver. So the result does not depend on the bound (tested).
//
// Evaluation
// ----------
// Where a footprint is small against a term, i.e. for both axes δ = (side/2)/√(2v) <= 0.15 and
// (|x| + δ)·δ <= 0.25 with x = u0/√(2v) (resp. v0), each erf difference is evaluated by its Hermite
// series (4δ/√π)·e^{-x²}·Σ_{k<=4} H_2k(x)·δ^{2k}/(2k+1)!, relative error < 1.4e-11 there (checked
// against 40-digit quadrature); the two e^{-x²} and exp(-h²/2v) combine into exp(-|Δ|²/2v), so a
// term costs one exp instead of four erfc: with 0.25 mm pixels the widest skin term always takes
// this path and the next two out to 5.5σ and 2.8σ from the receiver, and the reference needs
// 2.2x less time (128x128 plane at 4 px/mm: 5.4 s of CPU instead of 12 s). ExactOptions::series = false uses the closed form everywhere (the tests compare
// the two).
//
// Cost and memory: about 100 bytes per translucent pixel; time ~ receivers × sources within R
// (a 128x128 plane at 4 px/mm has 1.5e8 pairs within R = 17.5 mm and takes 5.4 s of CPU, ~37 ns
// a pair, 2.7 s on two idle cores).
// Each receiver's sum is independent of the others and summed in a fixed order, so results are
// bit-identical for any thread count.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "projection.hpp"
#include "skin_profile.hpp"
#include "surface.hpp"

namespace sss::math {

// The profile as a list of Gaussian terms (GaussianTerm: variance mm², per-channel weights).
using GaussianProfile = std::vector<GaussianTerm>;

// d'Eon–Luebke skin: all six terms, including the narrowest (0.0064 mm²).
GaussianProfile skin_profile_terms();

struct ExactInput {
  int width = 0, height = 0;
  const float* irradiance = nullptr;      // RGBA (alpha ignored), row 0 at the bottom
  const float* distance = nullptr;        // view distance (-Z_view) per pixel, world units ...
  const double* distance_f64 = nullptr;   // ... or this instead (exactly one of the two)
  const uint8_t* mask = nullptr;          // non-zero: translucent; nullptr: every pixel
  Matrix4 projection{};                   // column-major GL projection (check_projection: ok)
  double world_units_per_mm = 1.0;        // > 0
  FootprintRule footprint = FootprintRule::central_where_smooth;
};

// A rectangle of pixels: x in [x, x + width), y in [y, y + height).
struct PixelRegion {
  int x = 0, y = 0, width = 0, height = 0;
};

struct ExactOptions {
  double tail_mass = 1e-9;    // in (0, 1): mass of each term allowed beyond its cutoff
  int threads = 0;            // convolve(): 0 = std::thread::hardware_concurrency()
  bool screen_bound = true;   // false: scan the whole image for every receiver (for tests)
  bool series = true;         // false: the erf closed form for every term (see "Evaluation")
};

// sqrt(2 v ln(1 / tail_mass)): the radius beyond which a 2D-normalised Gaussian of variance v has
// `tail_mass` of its mass.
double gaussian_tail_radius_mm(double variance_mm2, double tail_mass);

// The largest gaussian_tail_radius_mm over the terms with a non-zero weight in some channel.
double profile_cutoff_radius_mm(const GaussianProfile& profile, double tail_mass);

// The footprint integral I above for one term (all lengths mm; h2 = h²). The erf differences are
// formed with erfc where both arguments have the same sign, so far tails keep their relative
// precision.
double gaussian_rectangle_integral(double variance_mm2, double u0, double v0, double h2, double a, double b);

// Prepares the surface (footprints of every usable pixel) once; then answers per pixel or per
// region. Throws std::invalid_argument on bad input (message names the field and value). The
// input arrays must outlive the object.
class ExactSurfaceConvolution {
 public:
  ExactSurfaceConvolution(const ExactInput& input, GaussianProfile profile, const ExactOptions& options = {});

  // M(p) for pixel (x, y); the input RGB if the pixel is not usable.
  std::array<double, 3> at(int x, int y) const;

  // M for every pixel of `receivers` into out_rgb (width·height·3 doubles, row 0 at the bottom);
  // pixels outside the region are not written. Multithreaded over rows (options.threads).
  void convolve(const PixelRegion& receivers, double* out_rgb) const;

  double cutoff_radius_mm() const { return cutoff_mm_; }
  double large_footprint_threshold_mm() const { return h0_mm_; }
  std::size_t large_footprint_count() const { return large_.size(); }
  std::size_t source_count() const { return sources_.size(); }

 private:
  struct Term {
    std::array<double, 3> weight;
    double inv_two_v;       // 1 / (2v)
    double inv_sqrt_two_v;  // 1 / sqrt(2v)
    double reach_mm;        // R_t
  };
  struct Source {
    Vec3 p, t1, t2;         // mm
    double half_a, half_b;  // mm
    double half_diagonal;   // mm
    std::array<double, 3> e;
    bool large;
  };

  void accumulate(const Source& q, const Vec3& p, std::array<double, 3>* sum) const;

  ExactInput input_;
  SurfaceImage surface_;
  ExactOptions options_;
  std::vector<Term> terms_;
  double cutoff_mm_ = 0.0;
  double h0_mm_ = 0.0;
  std::vector<int32_t> index_;        // per pixel: index into sources_, or -1
  std::vector<Source> sources_;
  std::vector<int32_t> large_;        // sources with half_diagonal > h0, checked explicitly
};

// One-shot convenience: ExactSurfaceConvolution(input, profile, options).convolve(receivers, out).
void exact_surface_convolution(const ExactInput& input, const GaussianProfile& profile,
                               const PixelRegion& receivers, double* out_rgb,
                               const ExactOptions& options = {});

}  // namespace sss::math
