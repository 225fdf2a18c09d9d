// The debug views of the separable passes (sss.h SSS_DEBUG_VIEW, SSS_DEBUG_VIEW 1-5 and 7 here; the tiles
// view is tile_view.frag): the first term's two fragment passes as the filter runs them
// (blur_pixel.glsl: the same culling, walk and footprint), writing what they would use instead of
// the blurred colour. The horizontal pass (SSS_PACKED_OUTPUT) writes its footprint (profile mm per
// pixel step) and tap count into the texel's r and g, and keeps b and a (the R8UI index and the
// distance the vertical walk reads); the vertical pass writes the view into the separate output,
// (0, 0, 0, 1) at a pixel the passes leave alone and everywhere with u_debug_fill set (the module
// draws it over the pixels the culling keeps from the passes).

#include "blur_pixel.glsl"

#if SSS_PACKED_OUTPUT
out uvec4 o_packed;
#else
out vec4 o_color;
#endif

// The view of one pixel from the vertical pass's numbers and the horizontal pass's (`across`).
vec3 sss_view(ivec2 pixel, SssCentre c, vec2 across, float footprint, float taps) {
#if SSS_DEBUG_VIEW == 7
  return sss_times_albedo_post(vec3(1.0), pixel, sss_centre_texturing());  // A_post (albedo.glsl)
#elif SSS_DEBUG_VIEW == 1
  return vec3(1.0);
#elif SSS_DEBUG_VIEW == 2
  return vec3(c.distance);
#elif SSS_DEBUG_VIEW == 3
  return vec3(across.x, footprint, 0.0);
#elif SSS_DEBUG_VIEW == 4
  return vec3(across.y, taps, 0.0);
#elif SSS_PROFILE_IDS
  return vec3(float(sss_centre_id & 15u), float(sss_centre_id >> 4u), 1.0);
#else
  return vec3(0.0, 0.0, 1.0);  // b 1: profile 0 and object 0 told apart from a pixel left alone
#endif
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#if !SSS_PACKED_OUTPUT
  if (u_debug_fill != 0) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
#endif
  SssCentre c;
  if (!sss_read_centre(pixel, c)) {
#if SSS_PACKED_OUTPUT
    o_packed = c.texel;  // as the filter's horizontal pass: its own value
#else
    o_color = vec4(0.0, 0.0, 0.0, 1.0);  // a pixel the passes leave alone
#endif
    return;
  }
  SssWalk walk = sss_walk(pixel, c.distance);
  float step_pixels = sss_step_pixels(c, walk);
  // This pass's footprint and taps (footprint_taps.glsl's count), as the filter would run them.
  float footprint = 1.0 / step_pixels;
  float taps = float(1 + 2 * sss_tap_count(sss_reach_pixels(step_pixels)));
#if SSS_PACKED_OUTPUT
  o_packed = uvec4(floatBitsToUint(footprint), floatBitsToUint(taps), c.texel.b, c.texel.a);
#else
  vec2 across = vec2(uintBitsToFloat(c.texel.r), uintBitsToFloat(c.texel.g));
  o_color = sss_nearest_half(vec4(sss_view(pixel, c, across, footprint, taps), 1.0));
#endif
}
