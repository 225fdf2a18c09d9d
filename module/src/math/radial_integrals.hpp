// Integrals of a radial profile over rectangles, exact at the centre whatever R does there (Burley's
// R is infinite at r = 0). Math layer: no GL.
//
// How: seen from the profile's centre O (at height h above the rectangle's plane, h = 0 in it), the
// rectangle is a signed sum of the triangles O-v_k-v_k+1 over its edges. In polar coordinates about
// the foot of O, a triangle's integral is
//
//   ∫ dφ ∫_0^{ρ(φ)} R(√(h² + s²)) s ds = ∫ [out(h) − out(√(h² + ρ(φ)²))] dφ / 2π
//
// with out(r) the profile's energy outside radius r (RadialProfile::outside: closed form for Burley
// and the dipole), because ∫ R(u) u du = −out(u)/2π. The out(h) terms sum to out(h) × the winding
// number (1 inside, 0 outside), so
//
//   ∫∫_rect R = [O's foot inside] · out(h) − Σ_edges ∫ out(√(h² + p² / cos² ψ)) dψ / 2π
//
// ψ the angle from the edge's perpendicular foot (p its distance), each edge's ψ interval signed by
// its orientation. The remaining integrands are smooth and bounded, integrated by adaptive
// Gauss–Legendre; a far rectangle is the difference of two small tails, not of two totals, so it
// keeps its relative precision.
#pragma once

#include "radial_profile.hpp"

namespace sss::math {

// ∫∫ R_c(√(h² + x² + y²)) dx dy over [x0, x1] × [y0, y1] (mm, x0 < x1, y0 < y1, the profile centred
// at x = y = 0). The foot (0, 0) must not lie on an edge (then it is taken as outside). Absolute
// accuracy about 1e-13 of the profile's total per channel.
Rgb rectangle_integral(const RadialProfile& profile, double x0, double x1, double y0, double y1, double h_mm = 0.0);

}  // namespace sss::math
