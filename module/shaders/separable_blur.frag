// One pass of the separable subsurface-scattering filter (Jimenez et al. 2012, §3): the 1D kernel
// along `u_axis`, its footprint scaled per pixel by depth and by the strength in alpha, taps blended
// back to the centre colour as their depth leaves the kernel's reach (follow-surface).
//
// Compile-time switches (prepended by the module):
//   SSS_OUTSIDE   what a pixel that is not blurred writes: 0 its own value (horizontal pass, which
//                 fills the intermediate everywhere), 1 nothing (discard: vertical pass writing back
//                 into the host's colour), 2 the host's original colour (vertical pass into a
//                 separate output texture)
//   SSS_FOLLOW_SURFACE  0 or 1
//   SSS_LINEAR_DEPTH    0: hardware depth, linearised with the projection; 1: view distance
// and from the dialect's header (module/src/gl/glsl_variant.cpp):
//   SSS_BINDING(unit)        layout(binding = unit) where the dialect has it, else nothing (the
//                            module sets the unit with glUniform1i)
//   SSS_MANUAL_DEPTH_FILTER  1 on OpenGL ES: depth textures cannot be filtered there (and R32F only
//                            with an extension), so the depth taps are filtered here from four
//                            texel fetches, the way GL_LINEAR with clamp-to-edge would

SSS_BINDING(0) uniform sampler2D u_source;    // the pass input (host colour, then the intermediate)
SSS_BINDING(1) uniform sampler2D u_depth;     // the host's depth
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
uniform vec4 u_kernel[SSS_MAX_TAPS];  // rgb weights, a = offset in profile mm; centre first
uniform int u_tap_count;
uniform vec2 u_axis;                  // (1, 0) or (0, 1)
uniform float u_pixels_per_mm;        // along u_axis, at clip w = 1 and strength 1
uniform float u_follow_surface;       // 1 / the kernel's reach in world units
uniform vec2 u_ndc_from_depth;        // z_ndc = depth · x + y
uniform vec4 u_depth_terms;           // projection m10, m11, m14, m15
uniform vec4 u_clamp;                 // tap positions are kept inside (xy min, zw max), in pixels

out vec4 o_color;

float view_distance(float raw_depth) {
#if SSS_LINEAR_DEPTH
  return raw_depth;
#else
  float zn = raw_depth * u_ndc_from_depth.x + u_ndc_from_depth.y;
  return (zn * u_depth_terms.w - u_depth_terms.z) / (zn * u_depth_terms.y - u_depth_terms.x);
#endif
}

// The raw depth at `position` (pixels), bilinear with clamp-to-edge.
float depth_at(vec2 position, vec2 texel_size) {
#if SSS_MANUAL_DEPTH_FILTER
  vec2 p = position - 0.5;
  vec2 base = floor(p);
  vec2 f = p - base;
  ivec2 last = textureSize(u_depth, 0) - 1;
  ivec2 i0 = clamp(ivec2(base), ivec2(0), last);
  ivec2 i1 = clamp(ivec2(base) + 1, ivec2(0), last);
  float bottom = texelFetch(u_depth, i0, 0).r * (1.0 - f.x) + texelFetch(u_depth, ivec2(i1.x, i0.y), 0).r * f.x;
  float top = texelFetch(u_depth, ivec2(i0.x, i1.y), 0).r * (1.0 - f.x) + texelFetch(u_depth, i1, 0).r * f.x;
  return bottom * (1.0 - f.y) + top * f.y;
#else
  return texture(u_depth, position * texel_size).r;
#endif
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

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_source, pixel, 0);
  // Not translucent, or a non-finite colour or strength: the pixel keeps its own value.
  if (!(centre.a > 0.0) || any(isnan(centre)) || any(isinf(centre))) {
    leave_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);  // alpha is documented as 0..1; more must not widen the kernel
  float centre_distance = view_distance(texelFetch(u_depth, pixel, 0).r);
  float w = -u_depth_terms.y * centre_distance + u_depth_terms.w;
  if (!(w > 0.0) || isinf(w)) {  // behind the camera, on an infinite far plane, or NaN
    leave_untouched(pixel, centre);
    return;
  }

  vec2 texel_size = 1.0 / vec2(textureSize(u_source, 0));
  float step_pixels = u_pixels_per_mm * strength / w;
  float follow_surface = u_follow_surface / strength;  // the reach scales with alpha like the taps
  vec3 sum = centre.rgb * u_kernel[0].rgb;
  for (int i = 1; i < u_tap_count; ++i) {
    vec2 position = clamp(gl_FragCoord.xy + u_axis * (u_kernel[i].a * step_pixels), u_clamp.xy, u_clamp.zw);
    vec2 uv = position * texel_size;
    vec3 tap = texture(u_source, uv).rgb;
    // A non-finite neighbour must not spread: it counts as the centre's colour (its weight goes to
    // the centre), like a tap across a depth step.
    if (any(isnan(tap)) || any(isinf(tap))) tap = centre.rgb;
#if SSS_FOLLOW_SURFACE
    float s = follow_surface * abs(centre_distance - view_distance(depth_at(position, texel_size)));
    if (!(s < 1.0)) s = 1.0;  // also when the tap's distance is not finite
    tap = mix(tap, centre.rgb, s);
#endif
    sum += u_kernel[i].rgb * tap;
  }
#if SSS_OUTSIDE == 2
  o_color = vec4(sum, texelFetch(u_original, pixel, 0).a);
#else
  o_color = vec4(sum, centre.a);
#endif
}
