// One pass of the pseudo-separable cross-bilateral filter (Mikkelsen 2010, eq. 7-8): a 1D normalised
// cross-bilateral sum along the pass's line of the broad part of the profile, blended with the
// centre by the spike's share. The line and its footprint are the separable passes' walk over the
// surface (pass_surface.glsl: the horizontal pass along the row, the vertical one sheared so its
// steps are perpendicular to the row's on the surface, each with its own millimetres per step), from
// the depth of the neighbouring pixels or, with SSS_NORMALS, from the host's normal; its taps are the
// separable passes' footprint-aware ones (footprint_cells.glsl: whole pixels, each weighing the
// marginal over the pixels it stands for), each further weighted per channel by a range Gaussian on
// its distance off the centre's surface, exp(-h² / 2σ²); neighbours that are not translucent (alpha
// 0, which includes pixels outside the host's stencil) get no weight, and the sum is normalised.
// This must compute what sss::math::cpu_cbf_filter does (module/src/math/cpu_cbf_filter.cpp).
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp): SSS_OUTSIDE
// and SSS_LINEAR_DEPTH as in separable_blur.frag; SSS_AXIS 0 the horizontal pass, 1 the vertical;
// SSS_NORMALS 1: the surface's tangents come from the host's view-space normal texture; and the
// table's sizes for footprint_cells.glsl (SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS); SSS_ALBEDO (albedo.glsl:
// the vertical pass's result times A_post). The pieces it
// includes: nearest_half.glsl (u_round_to_half: the written colour rounded to half float here),
// colour_range.glsl, depth.glsl (view_distance, clip_w), pass_surface.glsl and footprint_cells.glsl.

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "pass_surface.glsl"
#include "footprint_cells.glsl"
#include "albedo.glsl"

SSS_BINDING(0) uniform sampler2D u_source;    // the pass input (host colour or its masked copy, then the intermediate)
SSS_BINDING(1) uniform sampler2D u_depth;     // the host's depth
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
#if SSS_NORMALS
SSS_BINDING(3) uniform sampler2D u_normals;   // view-space unit normal in xyz
#endif
// u_pixels_per_mm (along the pass's axis, at clip w = 1 and strength 1), u_clamp (tap positions
// are kept inside: xy min, zw max, in pixels), u_mm_per_world (profile millimetres per world unit
// at strength 1), u_spike_blend (rgb: b, result = b · centre + (1 - b) · normalised sum),
// u_inv_two_variance (rgb: 1 / (2 σ²) per channel, mm⁻²) and the pieces' numbers are the
// cross-bilateral pass's uniform struct, declared with the variant's #defines
// (module/src/gl/pass_uniforms.hpp).

out vec4 o_color;

void leave_untouched(ivec2 pixel, vec4 centre) {
#if SSS_OUTSIDE == 0
  o_color = centre;
#elif SSS_OUTSIDE == 1
  discard;
#else
  o_color = texelFetch(u_original, pixel, 0);
#endif
}

float depth_at(ivec2 texel) { return view_distance(texelFetch(u_depth, texel, 0).r); }

// The tangent along `axis` (0 x, 1 y) at this pixel.
vec3 sss_tangent(ivec2 pixel, vec2 g, int axis, float d0) {
#if SSS_NORMALS
  // The central difference of the steps of one window pixel either way along the axis to the plane
  // through the centre with the host's normal (pass_surface.hpp's ΔP, the depth change keeping the
  // step on that plane), as the tangent from depth takes it on a plane; a facing plane's where a
  // step is not finite (a zero normal, a plane seen edge-on).
  vec3 n = texelFetch(u_normals, pixel, 0).xyz;
  float w0 = clip_w(d0);
  float span = u_pixel_span[axis];
  float n_along = n[axis] * span;
  float n_ray = n.x * g.x + n.y * g.y - n.z;
  float plus = -w0 * n_along / (n_ray - u_depth_terms.y * n_along);
  float minus = w0 * n_along / (n_ray + u_depth_terms.y * n_along);
  bool finite = abs(plus) < 1e30 && abs(minus) < 1e30;  // false for NaN too
  plus = finite ? plus : 0.0;
  minus = finite ? minus : 0.0;
  float depth = 0.5 * plus - 0.5 * minus;
  float w = w0 - u_depth_terms.y * (0.5 * plus + 0.5 * minus);
  vec3 t = vec3(depth * g, -depth);
  t[axis] += span * w;
  return t;
#else
  bool um, up;
  float dm = 0.0, dp = 0.0;
  for (int side = 0; side < 2; ++side) {
    float along = gl_FragCoord[axis] + (side == 0 ? -1.0 : 1.0);
    bool inside = along >= u_clamp[axis] && along <= u_clamp[2 + axis];
    ivec2 texel = pixel;
    texel[axis] = int(inside ? along : gl_FragCoord[axis]);
    float d = depth_at(texel);
    bool usable = inside && sss_usable_distance(d);
    if (side == 0) {
      dm = d;
      um = usable;
    } else {
      dp = d;
      up = usable;
    }
  }
  return sss_surface_tangent(g, axis, d0, dm, um, dp, up);
#endif
}

// The pass's walk over the surface at this pixel: the horizontal pass needs T_x, the vertical one
// T_x and T_y.
SssWalk sss_walk(ivec2 pixel, float d0) {
  vec2 g = sss_ray_slope(gl_FragCoord.xy);
  vec3 tx = sss_tangent(pixel, g, 0, d0);
#if SSS_AXIS == 0
  return sss_horizontal_walk(g, d0, tx);
#else
  return sss_vertical_walk(g, d0, tx, sss_tangent(pixel, g, 1, d0));
#endif
}

// One tap `offset` steps along the line (the vertical pass's sheared): its weight per channel (0
// where it is not translucent or not usable, else the cell's mass `cell` times the range Gaussian
// of its distance off the centre's surface, in profile millimetres through `follow`) into
// `weight_sum`, its colour times that into `sum`.
void add_tap(float offset, vec3 cell, float shear, vec4 follow, inout vec3 sum, inout vec3 weight_sum) {
  vec2 position = gl_FragCoord.xy;
#if SSS_AXIS == 0
  position.x += offset;
#else
  position += vec2(shear * offset, offset);
#endif
  ivec2 texel = ivec2(clamp(position, u_clamp.xy, u_clamp.zw));
  vec4 tap = texelFetch(u_source, texel, 0);
  vec2 line = sss_off_surface(follow, vec2(texel) + 0.5 - gl_FragCoord.xy);
  float h = abs(depth_at(texel) * line.x + line.y);
  if (!(tap.a > 0.0) || !sss_in_range(tap) || isnan(h) || isinf(h)) return;
  vec3 w = cell * exp(-h * h * u_inv_two_variance.rgb);
  sum += w * tap.rgb;
  weight_sum += w;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_source, pixel, 0);
  if (!(centre.a > 0.0) || !sss_in_range(centre)) {
    leave_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);
  float d0 = depth_at(pixel);
  float w0 = clip_w(d0);
  if (isnan(w0) || !(w0 > 0.0) || isinf(w0)) {  // isnan(): see separable_blur.frag
    leave_untouched(pixel, centre);
    return;
  }
  SssWalk walk = sss_walk(pixel, d0);
  float step_pixels = u_pixels_per_mm * strength / w0 * walk.ratio;
  vec4 follow = sss_follow(walk, u_mm_per_world / strength, d0);

  // The footprint-aware taps (footprint_taps.glsl's footprint_sum, without jitter): every pixel out
  // to the reach where the kernel spans at most kSssHalfTaps on a side, else that many spread out.
  float reach_pixels = sss_reach_pixels(step_pixels);
  bool dense = sss_dense_taps(reach_pixels);
  int count = sss_tap_count(reach_pixels);
  vec3 total = SSS_CDF(SSS_CDF_ENTRIES - 1).rgb;
  vec3 below = total;
  float p = 0.0;
  float midpoint_scale = 0.5 / (SSS_FOOTPRINT.x * step_pixels);
  if (count > 0) {
    p = tap_position(1, 0.0, dense, reach_pixels);
    below = half_cdf(p * midpoint_scale);
  }
  vec3 weight_sum = 2.0 * below;
  vec3 sum = centre.rgb * weight_sum;
  for (int i = 1; i <= count; ++i) {
    float next = i < count ? tap_position(i + 1, p, dense, reach_pixels) : 0.0;
    vec3 upto = i < count ? half_cdf((p + next) * midpoint_scale) : total;
    add_tap(p, upto - below, walk.shear, follow, sum, weight_sum);
    add_tap(-p, upto - below, walk.shear, follow, sum, weight_sum);
    below = upto;
    p = next;
  }
  vec3 result = u_spike_blend.rgb * centre.rgb + (1.0 - u_spike_blend.rgb) * (sum / weight_sum);
  result = sss_times_albedo_post(result, pixel, SSS_ALBEDO);  // the vertical pass's (SSS_ALBEDO 1 or 2)
#if SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(result, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(result, centre.a));
#endif
}
