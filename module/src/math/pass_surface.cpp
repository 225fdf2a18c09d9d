#include "pass_surface.hpp"

#include <algorithm>
#include <cmath>

namespace sss::math {

namespace {

// The largest shift of the vertical pass, in columns per row. On a plane the shear is cot of the
// angle between the turn's axis and screen x at grazing turns (2.2 at an 80-degree turn about an
// axis 5 degrees off x); past a few columns per row the tangents come from a step or a sliver, not
// from a surface, and taps would fly far along the row.
constexpr float kMaxShear = 8.0f;
// Below this a squared length is taken for 0 (and above its inverse for infinite): the tangent or
// its part off the view ray is degenerate.
constexpr float kTiny = 1e-30f;

float dot3(const Float3& a, const Float3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The share a of T+ in the tangent (the header's blend): ½ where the surface is smooth, towards the
// side with the smaller depth change past a bend.
float plus_share(float limit, float dm, float dp) {
  if (!(limit > 0.0f)) return 0.5f;
  const float excess = std::fabs(dp + dm) - limit;  // dp, dm: the neighbours' depth changes
  const float sharp = std::clamp(excess / limit, 0.0f, 1.0f);
  const float toward_plus = std::clamp(0.5f + (std::fabs(dm) - std::fabs(dp)) / (2.0f * limit), 0.0f, 1.0f);
  return 0.5f + sharp * (toward_plus - 0.5f);
}

Float3 cross3(const Float3& a, const Float3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The step's ratio and slack for a line whose step is `t` on the surface, at a centre with clip w0;
// `span` the facing pixel's width per unit of w along the line.
PassGeometry step_along(float w0, float span, const Float3& t, float shear) {
  PassGeometry out;
  out.shear = shear;
  const float ratio = std::fabs(span) * w0 / std::sqrt(dot3(t, t));
  out.ratio = ratio > 0.0f && ratio < 1.0f / kTiny ? ratio : 1.0f;
  out.slack = kFollowSurfaceSlack * std::fabs(span) * w0 / out.ratio;  // the slack per step of |T|
  return out;
}

// α and β for the unit normal n (ray: the centre ray's derivative A): the raw depth difference
// where n is degenerate or the surface is seen edge-on.
void set_off_surface(const PassConstants& k, const Float3& ray, const Float3& n, PassGeometry* out) {
  const float alpha = dot3(n, ray);
  if (std::fabs(alpha) > 1e-6f && std::fabs(alpha) < 1.0f / kTiny) {
    const float sign = alpha < 0.0f ? -1.0f : 1.0f;  // n turned to face along A
    out->off_depth = sign * alpha;
    out->off_lateral = {sign * n.x * k.pixel_span[0], sign * n.y * k.pixel_span[1]};
  }
}

// The share a for the rules the passes do not take (TangentRule).
float rule_share(TangentRule rule, float limit, float dm, float dp) {
  switch (rule) {
    case TangentRule::reference:
      if (std::fabs(dp + dm) <= limit) return 0.5f;
      [[fallthrough]];
    case TangentRule::smaller_step:
      return std::fabs(dm) < std::fabs(dp) ? 0.0f : 1.0f;
    case TangentRule::central:
      return 0.5f;
    case TangentRule::blend:
      break;
  }
  return plus_share(limit, dm, dp);
}

}  // namespace

std::array<float, 2> ray_slope(const PassConstants& k, float wx, float wy) {
  return {k.slope_scale[0] * wx + k.slope_bias[0], k.slope_scale[1] * wy + k.slope_bias[1]};
}

Float3 surface_tangent(const PassConstants& k, const std::array<float, 2>& g, int axis, float d0, const Neighbour& minus,
                       const Neighbour& plus, TangentRule rule) {
  const std::size_t a = axis == 0 ? 0 : 1;
  const float w0 = clip_w(k, d0);
  const float limit = std::fabs(k.pixel_span[a]) * w0;  // a facing pixel's width
  // The neighbours' depth changes, 0 where one does not serve.
  const float dp = plus.usable ? plus.distance - d0 : 0.0f;
  const float dm = minus.usable ? minus.distance - d0 : 0.0f;
  const float share = plus.usable ? (minus.usable ? rule_share(rule, limit, dm, dp) : 1.0f) : (minus.usable ? 0.0f : 0.5f);
  // a·T+ + (1 - a)·(-T-), with T± = P(±1) - P: its depth change D and its clip w W.
  const float depth = share * dp - (1.0f - share) * dm;
  const float w = w0 - k.depth_terms[1] * (share * dp + (1.0f - share) * dm);
  const float lateral = k.pixel_span[a] * w;
  Float3 t = {depth * g[0], depth * g[1], -depth};
  (axis == 0 ? t.x : t.y) += lateral;
  return t;
}

PassGeometry horizontal_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx) {
  PassGeometry out = step_along(clip_w(k, d0), k.pixel_span[0], tx, 0.0f);
  // The line's normal within the slice: A's part perpendicular to T_x, normalised.
  const Float3 ray = {g[0], g[1], -1.0f};
  const float along = dot3(ray, tx) / dot3(tx, tx);
  Float3 perp = {ray.x - along * tx.x, ray.y - along * tx.y, ray.z - along * tx.z};
  const float inv = 1.0f / std::sqrt(dot3(perp, perp));
  perp = {perp.x * inv, perp.y * inv, perp.z * inv};
  set_off_surface(k, ray, perp, &out);
  out.off_lateral[1] = 0.0f;  // the row's taps move along x only
  return out;
}

PassGeometry vertical_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx,
                               const Float3& ty) {
  float shear = -dot3(tx, ty) / dot3(tx, tx);
  shear = std::fabs(shear) < 1.0f / kTiny ? std::clamp(shear, -kMaxShear, kMaxShear) : 0.0f;  // also NaN
  const Float3 tt = {ty.x + shear * tx.x, ty.y + shear * tx.y, ty.z + shear * tx.z};
  PassGeometry out = step_along(clip_w(k, d0), k.pixel_span[1], tt, shear);
  // The tangent plane's normal.
  Float3 n = cross3(tx, ty);
  const float inv = 1.0f / std::sqrt(dot3(n, n));
  n = {n.x * inv, n.y * inv, n.z * inv};
  set_off_surface(k, {g[0], g[1], -1.0f}, n, &out);
  return out;
}

float off_surface_distance(const PassConstants& k, const PassGeometry& geometry, float factor, float offset, float ox,
                           float oy, float d, float d0, bool slack) {
  // h = α (d - d0) + w(d) Λ with Λ = ox β_x + oy β_y, as the shaders take it per tap:
  // d · (α - Λ m11) + (Λ m15 - α d0).
  const float alpha = geometry.off_depth * factor;
  const float lateral = ox * (geometry.off_lateral[0] * factor) + oy * (geometry.off_lateral[1] * factor);
  const float slope = alpha - lateral * k.depth_terms[1];
  const float base = lateral * k.depth_terms[3] + -alpha * d0;
  const float h = std::fabs(d * slope + base);
  return slack ? std::max(h - std::fabs(offset) * (geometry.slack * factor), 0.0f) : h;
}

}  // namespace sss::math
