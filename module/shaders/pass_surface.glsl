// How a pass of the separable filter walks the surface at a pixel, for separable_blur.frag and
// .comp: the per-axis footprint (one step's millimetres of surface), the vertical pass's shear and
// the coefficients of the tap's distance off the surface's tangent line. This must compute what
// module/src/math/pass_surface.cpp computes, in the same float operations; its header says why and
// how (the surface from the four neighbours' view distances, the sheared vertical pass, the off-line
// depth test). Written without branches (each choice a select): a SIMD rasteriser runs both sides
// of every `if` anyway. Before this piece the shader includes depth.glsl (u_depth_terms, clip_w).

#ifndef SSS_UNIFORM_u_ray_slope  // a pass kind's uniform struct declares it (module/src/gl/pass_uniforms.hpp)
uniform vec2 u_pixel_span;  // world width of a window pixel per unit of clip w, x and y (signed)
uniform vec4 u_ray_slope;   // the view ray's lateral slope at window position p: p · xy + zw
#endif

struct SssWalk {
  float ratio;      // a facing pixel's width over the surface length of one step
  float shear;      // columns per row (the vertical pass); 0 along x
  float off_depth;  // α: the off-surface distance per unit of (d - d0)
  vec2 off_lateral; // β: the off-surface distance per window pixel of the tap's offset per unit of clip w
  float slack;      // kSssFollowSurfaceSlack times the surface length of one step
};

// The largest shear, columns per row, and the degenerate lengths (pass_surface.cpp says why).
const float kSssMaxShear = 8.0;
const float kSssTiny = 1e-30;
// math::kFollowSurfaceSlack: the share of a tap's distance along the line that the ramp leaves unfaded.
const float kSssFollowSurfaceSlack = 0.25;

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

// The step's ratio and slack for a line whose step is `t` on the surface, at a centre with clip w0;
// `span` a facing pixel's width along the line (α and β: the raw depth difference until set).
SssWalk sss_step_along(float w0, float span, vec3 t, float shear) {
  float ratio = abs(span) * w0 / sqrt(dot(t, t));
  ratio = ratio > 0.0 && ratio < 1.0 / kSssTiny ? ratio : 1.0;
  return SssWalk(ratio, shear, 1.0, vec2(0.0), kSssFollowSurfaceSlack * abs(span) * w0 / ratio);
}

// α and β for the unit normal n, turned to face along the ray's derivative A; the raw depth
// difference where n is degenerate or the surface is seen edge-on.
void sss_set_off_surface(vec3 ray, vec3 n, inout SssWalk walk) {
  float alpha = dot(n, ray);
  bool usable = abs(alpha) > 1e-6 && abs(alpha) < 1.0 / kSssTiny;
  float sign = alpha < 0.0 ? -1.0 : 1.0;
  walk.off_depth = usable ? sign * alpha : 1.0;
  walk.off_lateral = usable ? sign * n.xy * u_pixel_span : vec2(0.0);
}

SssWalk sss_horizontal_walk(vec2 g, float d0, vec3 tx) {
  SssWalk walk = sss_step_along(clip_w(d0), u_pixel_span.x, tx, 0.0);
  // The line's normal within the slice: A's part perpendicular to T_x, normalised.
  vec3 ray = vec3(g, -1.0);
  float along = dot(ray, tx) / dot(tx, tx);
  vec3 perp = ray - along * tx;
  perp = perp * (1.0 / sqrt(dot(perp, perp)));
  sss_set_off_surface(ray, perp, walk);
  walk.off_lateral.y = 0.0;  // the row's taps move along x only
  return walk;
}

SssWalk sss_vertical_walk(vec2 g, float d0, vec3 tx, vec3 ty) {
  float shear = -dot(tx, ty) / dot(tx, tx);
  shear = abs(shear) < 1.0 / kSssTiny ? clamp(shear, -kSssMaxShear, kSssMaxShear) : 0.0;  // also NaN
  SssWalk walk = sss_step_along(clip_w(d0), u_pixel_span.y, ty + shear * tx, shear);
  // The tangent plane's normal.
  vec3 n = cross(tx, ty);
  n = n * (1.0 / sqrt(dot(n, n)));
  sss_set_off_surface(vec3(g, -1.0), n, walk);
  return walk;
}

// The follow-surface factor times the off-surface distance of a tap whose pixel centre sits
// `moved` window pixels from the centre's is |d · x + y| for its distance d (pass_surface.cpp's
// off_surface_distance), (x, y) from `follow` = (α, β_x, β_y, -α d0) times the factor; the ramp
// takes the tap's slack off it (sss_follow_slack).
vec2 sss_off_surface(vec4 follow, vec2 moved) {
  float lateral = moved.x * follow.y + moved.y * follow.z;
  return vec2(follow.x - lateral * u_depth_terms.y, lateral * u_depth_terms.w + follow.w);
}

// `follow` above for a pixel at distance d0 whose follow-surface factor is `factor`.
vec4 sss_follow(SssWalk walk, float factor, float d0) {
  float alpha = walk.off_depth * factor;
  return vec4(alpha, walk.off_lateral * factor, -alpha * d0);
}
// The slack per step along the line, times the factor.
float sss_follow_slack(SssWalk walk, float factor) { return walk.slack * factor; }
