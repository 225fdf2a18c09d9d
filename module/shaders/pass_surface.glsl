// How a pass of the separable filter walks the surface at a pixel, for separable_blur.frag and
// .comp: the per-axis footprint (one step's millimetres of surface), the vertical pass's shear and
// the coefficients of the tap's distance off the surface's tangent line. This must compute exactly
// what module/src/math/pass_surface.cpp computes, in the same float operations; its header says why
// and how (the surface from the four neighbours' view distances, the sheared vertical pass, the
// off-line depth test). Before this piece the shader includes depth.glsl (clip_w).

uniform vec2 u_pixel_span;  // world width of a window pixel per unit of clip w, x and y (signed)
uniform vec4 u_ray_slope;   // the view ray's lateral slope at window position p: p · xy + zw

struct SssWalk {
  float ratio;      // a facing pixel's width over the surface length of one step
  float shear;      // columns per row (the vertical pass); 0 along x
  float off_depth;  // α: the off-line distance per unit of (d - d0)
  float off_step;   // λ: the off-line distance per step along the line per unit of clip w
};

// The largest shear, columns per row (pass_surface.cpp's kMaxShear says why).
const float kSssMaxShear = 8.0;

vec2 sss_ray_slope(vec2 window) { return u_ray_slope.xy * window + u_ray_slope.zw; }

// A neighbour's distance may serve the tangent: finite, in front of the camera (NaN fails too).
bool sss_usable_distance(float d) {
  float w = clip_w(d);
  return !isnan(w) && w > 0.0 && !isinf(w);
}

// The view-space offset from the centre (distance d0, ray slope g) to the point at window offset o
// with view distance d.
vec3 sss_view_offset(vec2 g, vec2 o, float d, float d0) {
  float w = clip_w(d);
  float dd = d - d0;
  return vec3(u_pixel_span * o * w + dd * g, -dd);
}

// The share of the one-sided difference towards +o in the tangent: ½ where the surface is smooth,
// towards the side with the smaller depth change past a bend (pass_surface.hpp).
float sss_plus_share(float span, float d0, float dm, float dp) {
  float limit = abs(span) * clip_w(d0);
  float excess = abs(dp - 2.0 * d0 + dm) - limit;
  float sharp = limit > 0.0 ? clamp(excess / limit, 0.0, 1.0) : 1.0;
  float cp = abs(dp - d0), cm = abs(dm - d0);
  float toward_plus = limit > 0.0 ? clamp(0.5 + (cm - cp) / (2.0 * limit), 0.0, 1.0) : 0.5;
  return 0.5 + sharp * (toward_plus - 0.5);
}

// The tangent along the axis o ((1, 0) or (0, 1)) from the neighbours at -o (distance dm, usable
// um) and +o (dp, up).
vec3 sss_surface_tangent(vec2 g, vec2 o, float span, float d0, float dm, bool um, float dp, bool up) {
  if (!um && !up) return vec3(o * (span * clip_w(d0)), 0.0);
  vec3 tp = sss_view_offset(g, o, dp, d0);
  vec3 tm = sss_view_offset(g, -o, dm, d0);
  if (!um) return tp;
  if (!up) return -tm;
  float a = sss_plus_share(span, d0, dm, dp);
  return a * tp - (1.0 - a) * tm;
}

float sss_step_ratio(float span, float w0, vec3 step) {
  float ratio = abs(span) * w0 / length(step);
  return !isnan(ratio) && ratio > 0.0 && !isinf(ratio) ? ratio : 1.0;
}

// α and λ for the line with tangent t and window step `line` per unit of w.
void sss_set_off_line(vec2 g, vec3 t, vec3 line, inout SssWalk walk) {
  vec3 ray = vec3(g, -1.0);
  float along = dot(ray, t) / dot(t, t);
  vec3 perp = ray - along * t;
  float alpha = length(perp);
  float lambda = dot(perp, line) / alpha;
  bool usable = !isnan(alpha) && alpha > 0.0 && !isinf(alpha) && !isnan(lambda) && !isinf(lambda);
  walk.off_depth = usable ? alpha : 1.0;
  walk.off_step = usable ? lambda : 0.0;
}

SssWalk sss_horizontal_walk(vec2 g, float d0, vec3 tx) {
  SssWalk walk = SssWalk(sss_step_ratio(u_pixel_span.x, clip_w(d0), tx), 0.0, 1.0, 0.0);
  sss_set_off_line(g, tx, vec3(u_pixel_span.x, 0.0, 0.0), walk);
  return walk;
}

SssWalk sss_vertical_walk(vec2 g, float d0, vec3 tx, vec3 ty) {
  float shear = -dot(tx, ty) / dot(tx, tx);
  if (isnan(shear) || isinf(shear)) shear = 0.0;
  shear = clamp(shear, -kSssMaxShear, kSssMaxShear);
  vec3 tt = ty + shear * tx;
  SssWalk walk = SssWalk(sss_step_ratio(u_pixel_span.y, clip_w(d0), tt), shear, 1.0, 0.0);
  sss_set_off_line(g, tt, vec3(u_pixel_span.x * shear, u_pixel_span.y, 0.0), walk);
  return walk;
}
