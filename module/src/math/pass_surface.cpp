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

// The ratio, α and λ for a line whose step is `t` on the surface and `line` per unit of w on the
// screen, at a centre with ray slope g (A = (g, -1)) and clip w0; `span` the facing pixel's width
// per unit of w along the line.
PassGeometry walk_along(const std::array<float, 2>& g, float w0, float span, const Float3& t, const Float3& line,
                        float shear) {
  PassGeometry out;
  out.shear = shear;
  const float tt = dot3(t, t);
  const float inv_length = 1.0f / std::sqrt(tt);
  const float ratio = std::fabs(span) * w0 * inv_length;
  out.ratio = ratio > 0.0f && ratio < 1.0f / kTiny ? ratio : 1.0f;
  const Float3 ray = {g[0], g[1], -1.0f};
  const float along = dot3(ray, t) / tt;  // A's part along t, per unit of t
  const float alpha2 = dot3(ray, ray) - along * dot3(ray, t);
  const float alpha = std::sqrt(std::max(alpha2, 0.0f));
  const float lambda = (dot3(ray, line) - along * dot3(t, line)) / alpha;
  if (alpha > 1e-6f && std::fabs(lambda) < 1.0f / kTiny) {
    out.off_depth = alpha;
    out.off_step = lambda;
  }  // else the tangent along the ray (or not finite): the raw depth difference (1, 0)
  return out;
}

}  // namespace

std::array<float, 2> ray_slope(const PassConstants& k, float wx, float wy) {
  return {k.slope_scale[0] * wx + k.slope_bias[0], k.slope_scale[1] * wy + k.slope_bias[1]};
}

Float3 surface_tangent(const PassConstants& k, const std::array<float, 2>& g, int axis, float d0, const Neighbour& minus,
                       const Neighbour& plus) {
  const std::size_t a = axis == 0 ? 0 : 1;
  const float w0 = clip_w(k, d0);
  const float limit = std::fabs(k.pixel_span[a]) * w0;  // a facing pixel's width
  // The neighbours' depth changes, 0 where one does not serve.
  const float dp = plus.usable ? plus.distance - d0 : 0.0f;
  const float dm = minus.usable ? minus.distance - d0 : 0.0f;
  const float share = plus.usable ? (minus.usable ? plus_share(limit, dm, dp) : 1.0f) : (minus.usable ? 0.0f : 0.5f);
  // a·T+ + (1 - a)·(-T-), with T± = P(±1) - P: its depth change D and its clip w W.
  const float depth = share * dp - (1.0f - share) * dm;
  const float w = w0 - k.depth_terms[1] * (share * dp + (1.0f - share) * dm);
  const float lateral = k.pixel_span[a] * w;
  Float3 t = {depth * g[0], depth * g[1], -depth};
  (axis == 0 ? t.x : t.y) += lateral;
  return t;
}

PassGeometry horizontal_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx) {
  return walk_along(g, clip_w(k, d0), k.pixel_span[0], tx, {k.pixel_span[0], 0.0f, 0.0f}, 0.0f);
}

PassGeometry vertical_geometry(const PassConstants& k, const std::array<float, 2>& g, float d0, const Float3& tx,
                               const Float3& ty) {
  float shear = -dot3(tx, ty) / dot3(tx, tx);
  shear = std::fabs(shear) < 1.0f / kTiny ? std::clamp(shear, -kMaxShear, kMaxShear) : 0.0f;  // also NaN
  const Float3 tt = {ty.x + shear * tx.x, ty.y + shear * tx.y, ty.z + shear * tx.z};
  return walk_along(g, clip_w(k, d0), k.pixel_span[1], tt, {k.pixel_span[0] * shear, k.pixel_span[1], 0.0f}, shear);
}

float off_line_distance(const PassConstants& k, const PassGeometry& geometry, float factor, float offset, float d,
                        float d0) {
  // h = α (d - d0) + offset λ w(d) = d · (α - offset λ m11) + (offset λ m15 - α d0), the form the
  // shaders take per tap (two fused multiply-adds per pair of taps, one per tap).
  const float alpha = geometry.off_depth * factor;
  const float lambda = offset * (geometry.off_step * factor);
  const float slope = alpha - lambda * k.depth_terms[1];
  const float base = lambda * k.depth_terms[3] + -alpha * d0;
  return std::fabs(d * slope + base);
}

}  // namespace sss::math
