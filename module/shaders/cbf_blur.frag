// One pass of the pseudo-separable cross-bilateral filter (Mikkelsen 2010, eq. 7-8): a 1D
// normalised cross-bilateral sum along `u_axis` whose footprint is the projected r_max sphere,
// shrunk by the cosine between the surface and the view ray in the plane of the axis and Z; taps
// are weighted by the profile (importance-placed), by a spatial Gaussian on the screen-parallel
// distance and a range Gaussian on the depth difference; neighbours that are not translucent
// (alpha 0, which includes pixels outside the host's stencil) get no weight.
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp): SSS_OUTSIDE
// and SSS_LINEAR_DEPTH as in separable_blur.frag; SSS_NORMALS 1: the surface's orientation comes
// from the host's view-space normal texture instead of the depth of the neighbouring pixels;
// SSS_MAX_TAPS the size of u_kernel. The pieces it includes: nearest_half.glsl (u_round_to_half:
// the written colour rounded to half float here) and depth.glsl (view_distance, clip_w).

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"

SSS_BINDING(0) uniform sampler2D u_source;    // the pass input (host colour or its masked copy, then the intermediate)
SSS_BINDING(1) uniform sampler2D u_depth;     // the host's depth
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
uniform vec4 u_kernel[SSS_MAX_TAPS];  // rgb weights of the broad part, a = offset in profile mm; centre first
uniform int u_tap_count;
#if SSS_NORMALS
SSS_BINDING(3) uniform sampler2D u_normals;   // view-space unit normal in xyz
#endif
uniform vec2 u_axis;                  // (1, 0) or (0, 1)
uniform float u_pixels_per_mm;        // along u_axis, at clip w = 1 and strength 1
uniform vec4 u_clamp;                 // tap positions are kept inside (xy min, zw max), in pixels
uniform vec4 u_xy_terms;              // projection m0, m5, m8, m9
uniform vec2 u_xy_offset;             // projection m12, m13
uniform vec4 u_viewport;              // x, y, width, height in pixels
uniform float u_world_per_mm;         // world units per profile mm at strength 1
uniform float u_orthographic;         // 1: the view direction is -Z everywhere
uniform vec4 u_spike_blend;           // rgb: b, result = b · centre + (1 - b) · normalised sum
uniform vec4 u_inv_two_variance;      // rgb: 1 / (2 σ²) per channel, mm⁻²

out vec4 o_color;

vec3 view_point(vec2 position, float distance) {
  vec2 ndc = (position - u_viewport.xy) / u_viewport.zw * 2.0 - 1.0;
  float w = clip_w(distance);
  float z = -distance;
  return vec3((ndc * w - u_xy_terms.zw * z - u_xy_offset) / u_xy_terms.xy, z);
}

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
  vec3 p0 = view_point(gl_FragCoord.xy, d0);

  // The surface's tangent in the plane of the axis and Z (from the normal, or from the neighbour whose
  // depth is closer: one side of a depth step is the other surface), and the direction to the eye.
#if SSS_NORMALS
  vec3 n = texelFetch(u_normals, pixel, 0).xyz;
  float ta = n.z, tz = -dot(n.xy, u_axis);
#else
  ivec2 step_texel = ivec2(u_axis);
  ivec2 lo = ivec2(floor(u_clamp.xy)), hi = ivec2(floor(u_clamp.zw));
  ivec2 tp = clamp(pixel + step_texel, lo, hi), tm = clamp(pixel - step_texel, lo, hi);
  float dp = depth_at(tp), dm = depth_at(tm);
  // At the viewport's edge the clamped neighbour on one side is the pixel itself: take the other.
  // A NaN depth on either side picks +, as the CPU model's !(a < b) does (spelt out for NVIDIA).
  bool plus = tm == pixel || (tp != pixel && (isnan(dm) || isnan(dp) || !(abs(dm - d0) < abs(dp - d0))));
  ivec2 tn = plus ? tp : tm;
  vec3 pn = view_point(vec2(tn) + 0.5, plus ? dp : dm);
  float ta = dot(pn.xy - p0.xy, u_axis), tz = pn.z - p0.z;
#endif
  float ea = u_orthographic > 0.5 ? 0.0 : -dot(p0.xy, u_axis);
  float ez = u_orthographic > 0.5 ? 1.0 : -p0.z;
  float cosine = abs(ta * ez - tz * ea) / (sqrt(ta * ta + tz * tz) * sqrt(ea * ea + ez * ez));
  if (isnan(cosine) || !(cosine <= 1.0)) cosine = 1.0;  // degenerate directions (NaN) and rounding: no correction
  float sine2 = 1.0 - cosine * cosine;

  float step_pixels = u_pixels_per_mm * strength / w0 * cosine;
  float mm_per_world = 1.0 / (u_world_per_mm * strength);
  vec3 weight_sum = u_kernel[0].rgb;
  vec3 sum = centre.rgb * weight_sum;
  for (int i = 1; i < u_tap_count; ++i) {
    float offset = u_kernel[i].a;
    vec2 position = clamp(gl_FragCoord.xy + u_axis * (offset * step_pixels), u_clamp.xy, u_clamp.zw);
    // Nearest texel: neighbouring pixels can be far apart on the surface, so no filtering.
    ivec2 texel = ivec2(floor(position));
    vec4 tap = texelFetch(u_source, texel, 0);
    if (!(tap.a > 0.0) || !sss_in_range(tap)) continue;
    float dz = (depth_at(texel) - d0) * mm_per_world;
    if (isnan(dz) || isinf(dz)) continue;
    // Spatial Gaussian on the screen-parallel distance times range Gaussian on the depth
    // difference, relative to the profile weight of the tap's distance along the surface: exactly 1
    // on a plane, falling off across a depth step.
    float spread = offset * offset * sine2 - dz * dz;
    vec3 w = u_kernel[i].rgb * exp(min(spread * u_inv_two_variance.rgb, vec3(0.0)));
    sum += w * tap.rgb;
    weight_sum += w;
  }
  vec3 result = u_spike_blend.rgb * centre.rgb + (1.0 - u_spike_blend.rgb) * (sum / weight_sum);
#if SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(result, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(result, centre.a));
#endif
}
