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

float dot3(const Float3& a, const Float3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float length3(const Float3& a) { return std::sqrt(dot3(a, a)); }

bool finite_positive(float v) { return v > 0.0f && std::isfinite(v); }

// α and λ of the off-line distance for a line with tangent `t` and window step `line` per unit of
// w, at a centre whose ray slope is g.
void set_off_line(const std::array<float, 2>& g, const Float3& t, const Float3& line, PassGeometry* out) {
  const Float3 ray = {g[0], g[1], -1.0f};
  const float along = dot3(ray, t) / dot3(t, t);
  const Float3 perp = {ray.x - along * t.x, ray.y - along * t.y, ray.z - along * t.z};
  const float alpha = length3(perp);
  const float lambda = dot3(perp, line) / alpha;
  if (finite_positive(alpha) && std::isfinite(lambda)) {
    out->off_depth = alpha;
    out->off_step = lambda;
  } else {  // the tangent along the ray (or not finite): the raw depth difference
    out->off_depth = 1.0f;
    out->off_step = 0.0f;
  }
}

// A facing pixel's width over the surface length of one step; 1 where that is not a positive number.
float step_ratio(float span, float w0, const Float3& step) {
  const float ratio = std::fabs(span) * w0 / length3(step);
  return finite_positive(ratio) ? ratio : 1.0f;
}

// The share a of T+ in the tangent (the header's blend): ½ where the surface is smooth, towards the
// side with the smaller depth change past a bend.
float plus_share(const PassConstants& k, int axis, float d0, float dm, float dp) {
  const float limit = std::fabs(k.pixel_span[axis == 0 ? 0 : 1]) * clip_w(k, d0);
  const float excess = std::fabs(dp - 2.0f * d0 + dm) - limit;
  const float sharp = limit > 0.0f ? std::clamp(excess / limit, 0.0f, 1.0f) : 1.0f;
  const float cp = std::fabs(dp - d0), cm = std::fabs(dm - d0);
  const float toward_plus = limit > 0.0f ? std::clamp(0.5f + (cm - cp) / (2.0f * limit), 0.0f, 1.0f) : 0.5f;
  return 0.5f + sharp * (toward_plus - 0.5f);
}

}  // namespace

std::array<float, 2> ray_slope(const PassConstants& k, float wx, float wy) {
  return {k.slope_scale[0] * wx + k.slope_bias[0], k.slope_scale[1] * wy + k.slope_bias[1]};
}

Float3 view_offset(const PassConstants& k, const std::array<float, 2>& g, float ox, float oy, float d, float d0) {
  const float w = clip_w(k, d);
  const float dd = d - d0;
  return {k.pixel_span[0] * ox * w + dd * g[0], k.pixel_span[1] * oy * w + dd * g[1], -dd};
}

Float3 surface_tangent(const PassConstants& k, const std::array<float, 2>& g, int axis, float d0, const Neighbour& minus,
                       const Neighbour& plus) {
  const float ox = axis == 0 ? 1.0f : 0.0f, oy = axis == 0 ? 0.0f : 1.0f;
  if (!minus.usable && !plus.usable) {  // a facing plane's
    const float facing = k.pixel_span[axis == 0 ? 0 : 1] * clip_w(k, d0);
    return {ox * facing, oy * facing, 0.0f};
  }
  const Float3 tp = view_offset(k, g, ox, oy, plus.distance, d0);
  const Float3 tm = view_offset(k, g, -ox, -oy, minus.distance, d0);
  if (!minus.usable) return tp;
  if (!plus.usable) return {-tm.x, -tm.y, -tm.z};
  const float a = plus_share(k, axis, d0, minus.distance, plus.distance);
  return {a * tp.x - (1.0f - a) * tm.x, a * tp.y - (1.0f - a) * tm.y, a * tp.z - (1.0f - a) * tm.z};
}

PassGeometry horizontal_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx) {
  PassGeometry out;
  out.ratio = step_ratio(k.pixel_span[0], clip_w(k, d0), tx);
  set_off_line(g, tx, {k.pixel_span[0], 0.0f, 0.0f}, &out);
  return out;
}

PassGeometry vertical_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx,
                               const Float3& ty) {
  PassGeometry out;
  float shear = -dot3(tx, ty) / dot3(tx, tx);
  if (!std::isfinite(shear)) shear = 0.0f;
  shear = std::fmin(std::fmax(shear, -kMaxShear), kMaxShear);
  out.shear = shear;
  const Float3 tt = {ty.x + shear * tx.x, ty.y + shear * tx.y, ty.z + shear * tx.z};
  out.ratio = step_ratio(k.pixel_span[1], clip_w(k, d0), tt);
  set_off_line(g, tt, {k.pixel_span[0] * shear, k.pixel_span[1], 0.0f}, &out);
  return out;
}

float off_line_distance(const PassConstants& k, const PassGeometry& geometry, float factor, float offset, float d,
                        float d0) {
  const float alpha = geometry.off_depth * factor;
  const float lambda = geometry.off_step * factor;
  return std::fabs(alpha * (d - d0) + offset * lambda * clip_w(k, d));
}

}  // namespace sss::math
