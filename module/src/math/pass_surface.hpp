// How one pass of the separable filter walks the surface at a pixel: how many millimetres of surface
// one step of the pass spans there, along which screen line it steps, and how far a tap lies off the
// surface's tangent line. Math layer: no GL. The shaders (module/shaders/pass_surface.glsl) compute
// the same numbers in the same float operations; these functions are their model.
//
// Why
// ---
// A pass that steps through the screen by the centre's depth alone treats every surface as if it
// faced the camera. Where skin turns away (a cheek, the side of the nose, the neck: 45-80 degrees
// on most of a face) one pixel spans 1/cos(turn) times more surface along the turn, so such a pass
// spreads light several times too far there, and its depth test (the raw depth difference of a
// tap) fades taps on the slope as if they lay across a step.
//
// The surface around a pixel
// --------------------------
// View-space positions follow from a pixel's window position and view distance d (surface.hpp's
// formulas). Between the centre (window p, distance d0, clip w0) and a point at window p + o with
// distance d (clip w = -m11 d + m15) the offset is exactly
//
//   ΔP = (s_x · o_x · w + Δd · g_x,  s_y · o_y · w + Δd · g_y,  -Δd),   Δd = d - d0,
//
// where s_a = 2 / (m[0] · viewport width) (resp. m[5], height) is the world width of a window pixel
// per unit of clip w, and g_a = (m[8] - m11 · ndc_x) / m[0] (resp. m[9], ndc_y, m[5]) is the view
// ray's lateral slope at p (0 for an orthographic camera that looks down -Z): no cancellation of
// large view-space coordinates, so a float difference of neighbours stays accurate.
//
// The tangents T_x, T_y (world units per pixel) come from the two neighbours on the axis, where
// usable (finite distance, w > 0, inside the clamp rectangle, and with per-pixel profiles the same
// index), as a blend a·T+ + (1 - a)·T- of the one-sided differences T+ = P(+1) - P and
// T- = P - P(-1):
//   - where the surface is smooth, the depth's second difference at most a facing pixel's width
//     (the smoothness test of the reference's rule, surface.hpp's central_where_smooth): a = ½, the
//     central difference, exact on a plane at any turn;
//   - past twice that (a step, a fold): the side with the smaller depth change, a = 0 or 1, where
//     the two sides' depth changes differ by a facing pixel's width or more (so one side of a step
//     does not take the other surface's slope), and linearly towards ½ as they come closer;
//   - between the two a linear blend; with one usable neighbour its side; with none a facing
//     plane's tangent.
// The reference switches between central and one-sided at the threshold; a pass cannot: a depth
// quantised by a 24-bit buffer, or by the R8UI index's 8 bits, moves the second difference across
// it from pixel to pixel, and the switch changes the tangent by up to half a pixel's depth change.
// The blend is continuous in the distances. Measured against the reference's own rule, always the
// smaller step and always central (TangentRule): docs/benchmarks/surface-study.md.
//
// The two passes
// --------------
// An isotropic kernel on the surface is separable along any two perpendicular surface directions,
// so the passes step along two screen lines whose surface images are perpendicular:
//   - the horizontal pass along screen x, one pixel at a time: T_x, |T_x| mm per step;
//   - the vertical pass one row at a time, shifted `shear` = -(T_x·T_y)/(T_x·T_x) columns per row,
//     so that its step T_t = T_y + shear·T_x is perpendicular to T_x on the surface: |T_t| mm per
//     step, which is the pixel's area over |T_x|. Its taps read the whole pixel nearest to the line
//     (column floor(x + ½ + shear · k)).
// On a plane under an orthographic camera this is exactly the 2D reference's own model of the pixel
// (exact_reference.hpp: a rectangle |T_x| by area/|T_x| along T_x, rows shifted along it), so a
// sum of Gaussians is exact there at any turn about any axis, the sheared columns rounded to whole
// pixels; facing the camera, T_x·T_y = 0 and the passes are the screen's rows and columns as before.
// The step each pass reports is `ratio` = (a facing pixel's width at w0) / (the surface length of one
// step), which multiplies the facing-plane step pixels_per_mm · strength / w0.
//
// The depth test
// --------------
// Follow-surface measures how far a tap lies off the surface through the centre: on a plane every
// tap lies on it (distance 0, at any turn), across a step a tap lies off it by about the step.
//   - The horizontal pass knows T_x alone: it measures the distance off the tangent line within the
//     slice of space its row sees (the plane through the row and the centre's view ray), with
//     A⊥ the part of the ray's derivative A = (g_x, g_y, -1) perpendicular to T_x: the unit normal
//     n = A⊥ / |A⊥| of the line in the slice.
//   - The vertical pass knows both tangents: it measures the distance off the tangent plane, with
//     n the plane's unit normal (T_x × T_y, turned to face the ray). Its taps read the pixel
//     nearest to the sheared line, whose centre lies off the line but on the plane.
// For a tap whose pixel centre sits (ox, oy) window pixels from the centre's, at view distance d
// (clip w(d) = -m11 d + m15), ΔP above gives
//
//   h = α · (d - d0) + w(d) · (ox · β_x + oy · β_y),   α = n · A,  β_x = n_x s_x,  β_y = n_y s_y,
//
// a few fused multiply-adds per tap, as the raw depth difference was (the taps' actual offsets, so
// a tap kept inside the viewport measures where it reads). Where the surface is seen edge-on
// (α about 0) it falls back to the raw depth difference (α = 1, β = 0).
//
// Skin bends: over a few millimetres a cheek, a jaw or a facet of a scanned mesh leaves its tangent
// line by a fair share of the distance, and the follow-surface ramp faded such taps as if they lay
// across a step. So the ramp (SSS_FOLLOW_SURFACE 1) gives every tap a slack of kFollowSurfaceSlack
// times its distance along the line, |k| · |T| (the ramp then measures h - slack, at least 0): a
// bend of up to 14 degrees between the centre and the tap, or a curvature radius down to twice the
// tap's distance, while a step (nose over cheek, ear over neck) lies off the line by far more than
// that. The Gaussian depth correction (SSS_FOLLOW_SURFACE 2) is the profile's own law in the
// third dimension, exp(-h²/2v), and keeps no slack. No slack and twice the slack, measured on the
// head and on curved surfaces: docs/benchmarks/surface-study.md.
#pragma once

#include <array>

#include "filter_constants.hpp"

namespace sss::math {

struct Float3 {
  float x = 0.0f, y = 0.0f, z = 0.0f;
};

// A neighbour's view distance along the pass's axis, and whether it may serve the tangent (finite,
// in front of the camera, inside the clamp rectangle).
struct Neighbour {
  float distance = 0.0f;
  bool usable = false;
};

// The view ray's lateral slope g (x, y) at window position (wx, wy).
std::array<float, 2> ray_slope(const PassConstants& k, float wx, float wy);

// How the tangent weighs its two one-sided differences where both neighbours serve: the passes'
// blend (above), or, to measure that choice against (tests/bench/surface_study.cpp), the reference's
// switch (central where smooth, else the smaller depth change), always the smaller depth change, or
// always the central difference.
enum class TangentRule { blend, reference, smaller_step, central };

// The surface tangent along `axis` (0 x, 1 y) at the centre from its two neighbours on that axis (at
// window offsets -1 and +1), by the rule above.
Float3 surface_tangent(const PassConstants& k, const std::array<float, 2>& g, int axis, float d0, const Neighbour& minus,
                       const Neighbour& plus, TangentRule rule = TangentRule::blend);

// The share of a tap's distance along the line that follow-surface's ramp leaves unfaded (above).
inline constexpr float kFollowSurfaceSlack = 0.25f;

struct PassGeometry {
  float ratio = 1.0f;       // facing pixel width at w0 over the surface length of one step
  float shear = 0.0f;       // columns per row (vertical pass); 0 along x
  float off_depth = 1.0f;   // α of the off-surface distance
  std::array<float, 2> off_lateral = {0.0f, 0.0f};  // β_x, β_y of the off-surface distance
  float slack = 0.0f;       // kFollowSurfaceSlack times the surface length of one step (world units)
};

// The horizontal pass's geometry from T_x; the vertical pass's from T_x and T_y.
PassGeometry horizontal_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx);
PassGeometry vertical_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx,
                               const Float3& ty);

// |h| above, times `factor` (the follow-surface factor), for a tap `offset` steps along the line
// (either sign) whose pixel centre sits (ox, oy) window pixels from the centre's, at view distance d:
// in the shaders' order, factor folded into α and β once per pixel. `slack`: less the tap's slack
// (the ramp's), |offset| steps' worth, at least 0.
float off_surface_distance(const PassConstants& k, const PassGeometry& geometry, float factor, float offset, float ox,
                           float oy, float d, float d0, bool slack);

}  // namespace sss::math
