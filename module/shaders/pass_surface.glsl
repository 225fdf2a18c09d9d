// How a pass of the separable filter walks the surface at a pixel, for separable_blur.frag and
// .comp: the per-axis footprint (one step's millimetres of surface), the vertical pass's shear and
// the coefficients of the tap's distance off the surface's tangent line. This must compute what
// module/src/math/pass_surface.cpp computes, in the same float operations; its header says why and
// how (the surface from the four neighbours' view distances, the sheared vertical pass, the off-line
// depth test). Written without branches (each choice a select): a SIMD rasteriser runs both sides
// of every `if` anyway. Before this piece the shader includes depth.glsl (u_depth_terms, clip_w).

uniform vec2 u_pixel_span;  // world width of a window pixel per unit of clip w, x and y (signed)
uniform vec4 u_ray_slope;   // the view ray's lateral slope at window position p: p · xy + zw

struct SssWalk {
  float ratio;      // a facing pixel's width over the surface length of one step
  float shear;      // columns per row (the vertical pass); 0 along x
  float off_depth;  // α: the off-line distance per unit of (d - d0)
  float off_step;   // λ: the off-line distance per step along the line per unit of clip w
};

// The largest shear, columns per row, and the degenerate lengths (pass_surface.cpp says why).
const float kSssMaxShear = 8.0;
const float kSssTiny = 1e-30;

vec2 sss_ray_slope(vec2 window) { return u_ray_slope.xy * window + u_ray_slope.zw; }

// A neighbour's distance may serve the tangent: finite and in front of the camera (NaN fails).
bool sss_usable_distance(float d) {
  float w = clip_w(d);
  return w > 0.0 && w < 1.0 / kSssTiny;
}

// The share of the one-sided difference towards +1 in the tangent, from the neighbours' depth
// changes dm, dp and a facing pixel's width `limit`: ½ where the surface is smooth, towards the side
// with the smaller depth change past a bend (pass_surface.hpp).
float sss_plus_share(float limit, float dm, float dp) {
  float excess = abs(dp + dm) - limit;
  float sharp = clamp(excess / limit, 0.0, 1.0);
  float toward_plus = clamp(0.5 + (abs(dm) - abs(dp)) / (2.0 * limit), 0.0, 1.0);
  return limit > 0.0 ? 0.5 + sharp * (toward_plus - 0.5) : 0.5;
}

// The tangent along axis `axis` (0 x, 1 y) from the neighbours at -1 (distance dm, usable um) and
// +1 (dp, up): a·T+ + (1 - a)·(-T-), through its depth change and its clip w.
vec3 sss_surface_tangent(vec2 g, int axis, float d0, float dm, bool um, float dp, bool up) {
  float w0 = clip_w(d0);
  float span = u_pixel_span[axis];
  float limit = abs(span) * w0;
  float cp = up ? dp - d0 : 0.0;
  float cm = um ? dm - d0 : 0.0;
  float share = up ? (um ? sss_plus_share(limit, cm, cp) : 1.0) : (um ? 0.0 : 0.5);
  float depth = share * cp - (1.0 - share) * cm;
  float w = w0 - u_depth_terms.y * (share * cp + (1.0 - share) * cm);
  vec3 t = vec3(depth * g, -depth);
  t[axis] += span * w;
  return t;
}

// The ratio, α and λ for a line whose step is `t` on the surface and `line` per unit of w on the
// screen, at a centre with ray slope g and clip w0; `span` a facing pixel's width along the line.
SssWalk sss_walk_along(vec2 g, float w0, float span, vec3 t, vec3 line, float shear) {
  float tt = dot(t, t);
  float inv_length = 1.0 / sqrt(tt);
  float ratio = abs(span) * w0 * inv_length;
  vec3 ray = vec3(g, -1.0);
  float along = dot(ray, t) / tt;
  float alpha2 = dot(ray, ray) - along * dot(ray, t);
  float alpha = sqrt(max(alpha2, 0.0));
  float lambda = (dot(ray, line) - along * dot(t, line)) / alpha;
  bool usable = alpha > 1e-6 && abs(lambda) < 1.0 / kSssTiny;
  return SssWalk(ratio > 0.0 && ratio < 1.0 / kSssTiny ? ratio : 1.0, shear, usable ? alpha : 1.0,
                 usable ? lambda : 0.0);
}

SssWalk sss_horizontal_walk(vec2 g, float d0, vec3 tx) {
  return sss_walk_along(g, clip_w(d0), u_pixel_span.x, tx, vec3(u_pixel_span.x, 0.0, 0.0), 0.0);
}

SssWalk sss_vertical_walk(vec2 g, float d0, vec3 tx, vec3 ty) {
  float shear = -dot(tx, ty) / dot(tx, tx);
  shear = abs(shear) < 1.0 / kSssTiny ? clamp(shear, -kSssMaxShear, kSssMaxShear) : 0.0;  // also NaN
  vec3 tt = ty + shear * tx;
  return sss_walk_along(g, clip_w(d0), u_pixel_span.y, tt, vec3(u_pixel_span.x * shear, u_pixel_span.y, 0.0), shear);
}

// The follow-surface factor times the off-line distance of a tap `offset` steps along the line is
// |d · x + y| for its distance d (pass_surface.cpp's off_line_distance): (x, y) from `follow` =
// (α, λ, -α d0) times the factor, once per tap pair and side.
vec2 sss_off_line(vec3 follow, float offset) {
  float lambda = offset * follow.y;
  return vec2(follow.x - lambda * u_depth_terms.y, lambda * u_depth_terms.w + follow.z);
}

// `follow` above for a pixel at distance d0 whose follow-surface factor is `factor`.
vec3 sss_follow(SssWalk walk, float factor, float d0) {
  float alpha = walk.off_depth * factor;
  return vec3(alpha, walk.off_step * factor, -alpha * d0);
}
