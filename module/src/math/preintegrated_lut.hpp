// Pre-integrated skin shading (Penner and Borshukov 2011, papers/penner-2011-preintegrated-skin.md):
// the diffuse falloff D(θ, r) of eq. (1.1) and the shadow falloff P_S(s, w) of §1.6, per channel,
// for any RadialProfile. Math layer: no GL; the generators fill RGBA float rows on std::thread.
//
// Grids are endpoint-inclusive: texel x of a W-wide LUT stands for u = x / (W - 1) exactly, so the
// first and last texels hold the values at the ends of the ranges (N·L = -1 and 1, the curvature or
// penumbra limits). A shader samples texel centres with uv = (0.5 + u·(W - 1)) / W (the include in
// integration/ does). Alpha is 1.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "radial_profile.hpp"

namespace sss::math {

// Diffuse LUT: columns N·L from -1 to 1, rows curvature 1/r from curvature_min to curvature_max
// (1/mm, linear). Curvature 0 is a flat surface (r = ∞): D = saturate(N·L) exactly.
struct DiffuseLutDesc {
  int width = 256;
  int height = 256;
  double curvature_min_per_mm = 0.0;
  double curvature_max_per_mm = 1.0;
};

// The shadow filter whose penumbra the shadow LUT inverts.
enum class ShadowFilter {
  box,       // box-filtered PCF: the penumbra is a linear ramp, P^-1(s) = s
  gaussian,  // Gaussian-weighted PCF: P(t) = Φ((t - ½)/σ), σ = ¼ of the penumbra (it spans ±2σ)
};

// Shadow LUT: columns shadow value s from 0 to 1, rows the filter's penumbra width in world units
// from penumbra_min to penumbra_max (linear). new_penumbra is the width of the sharp penumbra P'
// as a fraction of the filter's (a centred linear ramp); the rest of the filter's penumbra carries
// the light the profile scatters across P'.
struct ShadowLutDesc {
  int width = 256;
  int height = 256;
  double penumbra_min = 0.001;       // world units (1 mm in a scene in metres)
  double penumbra_max = 0.032;       // world units
  double world_units_per_mm = 0.001; // scene scale: the profile is in mm
  double new_penumbra = 0.25;        // (0, 1]
  ShadowFilter filter = ShadowFilter::box;
};

// The energy fraction the LUT integrals leave out, and the radius (mm) that leaves it out
// (RadialProfile::support_mm): far below the profile's own extent_mm() (1e-4), so the 1e-3 accuracy
// of the LUTs is not spent on the truncation.
inline constexpr double kLutTailFraction = 1e-9;
double lut_support_mm(const RadialProfile& profile);

// Eq. (1.1) at one point: the ring integral of saturate(cos(θ + x)) weighted by R(2r·sin(|x|/2)),
// over the same integral of the weights, θ = acos(ndotl), r = 1 / curvature. ndotl in [-1, 1],
// curvature >= 0 (1/mm). Gauss–Legendre panels split at the lighting kinks and at distances
// doubling from 0.01 mm, so the narrowest and the widest terms are both resolved.
std::array<double, 3> preintegrated_diffuse(const RadialProfile& profile, double ndotl, double curvature_per_mm);

// The representative penumbra of the filter inverted: the position (in penumbra widths, the
// penumbra spanning [0, 1]) where the filtered shadow of a straight edge equals s.
double shadow_penumbra_position(ShadowFilter filter, double s);
// The sharp penumbra P'(t): a linear ramp of width `fraction` centred in [0, 1].
double new_penumbra_value(double fraction, double t);

// §1.6 at one point: ∫ P'(P^-1(s) + y·u/w) R(|y|) dy / ∫ R(|y|) dy (y in mm, u = world units per mm,
// w = penumbra width in world units), then rescaled so that s = 0 gives 0 and s = 1 gives 1: where
// the profile is wider than the penumbra, the scattered light is squeezed into the penumbra (the
// paper's "clamped to fit the space provided"), so the umbra stays dark and the lit side stays lit.
// As the penumbra grows against the profile (w/u → ∞) this tends to P'(P^-1(s)).
std::array<double, 3> preintegrated_shadow(const RadialProfile& profile, const ShadowLutDesc& desc, double s,
                                           double penumbra_world);

// The Gauss–Legendre rule of every panel (10 points on [-1, 1]); the GPU generator takes it as uniforms.
constexpr int kLutQuadratureOrder = 10;
struct LutQuadratureRule {
  std::array<double, kLutQuadratureOrder> node{}, weight{};
};
const LutQuadratureRule& lut_quadrature_rule();

// Texel coordinates of the endpoint-inclusive grids.
double diffuse_lut_ndotl(const DiffuseLutDesc& desc, int x);
double diffuse_lut_curvature(const DiffuseLutDesc& desc, int y);
double shadow_lut_value(const ShadowLutDesc& desc, int x);
double shadow_lut_penumbra(const ShadowLutDesc& desc, int y);

// Whole LUTs, width·height RGBA floats row by row (row 0 = the first curvature / penumbra), rows
// shared among `threads` std::threads (0: std::thread::hardware_concurrency()). Every row is computed
// the same way on any thread count, so the result does not depend on it.
void generate_diffuse_lut(const RadialProfile& profile, const DiffuseLutDesc& desc, int threads, float* out_rgba);
void generate_shadow_lut(const RadialProfile& profile, const ShadowLutDesc& desc, int threads, float* out_rgba);

// Every input of a LUT as text (profile identity, kind, all fields at full precision): the cache key.
std::string diffuse_lut_key(const RadialProfile& profile, const DiffuseLutDesc& desc);
std::string shadow_lut_key(const RadialProfile& profile, const ShadowLutDesc& desc);
// 64-bit FNV-1a of a key: what the cache and the GL labels show.
std::uint64_t lut_hash(const std::string& key);

}  // namespace sss::math
