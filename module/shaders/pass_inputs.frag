// The separable fragment passes' inputs, drawn once per frame before them: each pixel's colour and
// view distance in one RGBA32UI texel (rgb the colour's float bits, a the distance's), so that
// every tap of both passes reads both with one fetch and linearises no depth (issue 24: on
// llvmpipe a tap's depth fetch was a sixth of the passes' work, its linearisation 1 %). The
// strength (the colour's alpha) goes to its own R32UI target: only the centre pixel reads it.
// Unsigned integer targets because they are renderable on OpenGL 3.3 and OpenGL ES 3.0 alike
// (RGBA32F and R32F are not on ES 3.0), and they keep every bit: the passes get exactly the float
// view_distance() gives, NaN and infinity included.
//
// A colour that is not finite, or past colour_range.glsl's bound, is written as kSssUnusableColour
// at distance NaN: the follow-surface blend turns such a tap into the centre's colour exactly, as
// the test per tap it replaces did (footprint_taps.glsl; the compute path sanitises its cache the
// same way); a pass without follow-surface finds the colour out of range, as it found the
// original; and a centre with a NaN distance is left alone, as one with such a colour was. The
// strength is written as it is.
//
// Compile-time switches (module/src/gl/shader_variants.cpp):
//   SSS_LINEAR_DEPTH   0: hardware depth, linearised here; 1: the host's depth is a view distance
//   SSS_PROFILE_IDS    0: none; 1: an R8UI index texture, its byte put in the low 8 bits of the
//                      blue colour word (they count as 0 in the colour: an RGBA16F or
//                      R11F_G11F_B10F colour has none there, an RGBA32F one keeps 15 fraction bits,
//                      3e-5 of its blue), so the distance, from which the passes take the surface's
//                      tangents, stays whole; 2: an R16UI one, which the passes read per tap instead
//   SSS_MARK_DEPTH     1: mark the pixels the passes may change in the module's depth buffer
//                      (0 where alpha is above 0, 1 elsewhere), which both passes then test
//                      against (GL_GREATER at the full-screen triangle's depth), so the rasteriser
//                      shades translucent pixels only: the paper's stencil culling, without a
//                      draw of its own (a stencil can only be marked by discarding fragments,
//                      which this draw must not do). 0: the host's (or the MSAA path's) stencil culls.
//   SSS_COLOR_IMAGE    1: the colour is read through image unit 0 (imageLoad, its format
//                      SSS_COLOR_IMAGE_FORMAT), where the context has image units (desktop GL 4.3+,
//                      GLSL 4.20) and the colour texture is complete: on llvmpipe a texelFetch from
//                      any texture but an 8-bit one calls a sampling function, which made the colour's
//                      read a sixth of this draw's time (1080p); 0: the sampler on unit 0
//   SSS_ALBEDO         albedo.glsl's: the colour divided by A_post (a texturing mode), rounded as
//                      the module's colour copy rounds it (u_round_to_half: where the copy would be
//                      RGBA16F), so that every path blurs the same values; 3: by each pixel's
//                      profile's mode (u_texturing)
// The texel goes into the horizontal pass's target too: that pass skips the pixels the culling
// rejects, and the vertical taps read them there.
#include "colour_range.glsl"
#include "depth.glsl"
#include "albedo.glsl"
#include "nearest_half.glsl"

#if SSS_COLOR_IMAGE
layout(binding = 0, SSS_COLOR_IMAGE_FORMAT) readonly uniform highp image2D u_color;  // as below, complete
#else
SSS_BINDING(0) uniform sampler2D u_color;       // the host's colour (or the module's copy of it)
#endif
SSS_BINDING(1) uniform highp sampler2D u_depth;  // the host's depth (hardware or linear)
#if SSS_PROFILE_IDS == 1 || (SSS_PROFILE_IDS == 2 && SSS_ALBEDO == 3)
SSS_BINDING(4) uniform highp usampler2D u_profile_ids;  // the host's R8UI (or, for the modes, R16UI) indices
#endif
#if SSS_ALBEDO == 3
uniform float u_texturing[SSS_PROFILES];  // each profile's mode (0-2)
#endif

// The colour over A_post (albedo.glsl), rounded as the colour copy rounds it.
vec4 sss_over_albedo(vec4 color, ivec2 pixel) {
#if SSS_ALBEDO == 3
  int profile = int(texelFetch(u_profile_ids, pixel, 0).r & 15u);
  color.rgb /= sss_albedo_post(pixel, profile < SSS_PROFILES ? int(u_texturing[profile]) : 0);
  return vec4(sss_nearest_half(color).rgb, color.a);
#elif SSS_ALBEDO
  color.rgb /= sss_albedo_post(pixel, SSS_ALBEDO);
  return vec4(sss_nearest_half(color).rgb, color.a);
#else
  return color;
#endif
}

layout(location = 0) out uvec4 o_taps;
layout(location = 1) out uint o_strength;
layout(location = 2) out uvec4 o_intermediate;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#if SSS_COLOR_IMAGE
  vec4 color = imageLoad(u_color, pixel);
#else
  vec4 color = texelFetch(u_color, pixel, 0);
#endif
  color = sss_over_albedo(color, pixel);
  uint distance = floatBitsToUint(view_distance(texelFetch(u_depth, pixel, 0).r));
  if (!sss_in_range(color.rgb)) {
    color.rgb = vec3(kSssUnusableColour);
    distance = 0x7FC00000u;  // NaN
  }
  uvec3 bits = floatBitsToUint(color.rgb);
#if SSS_PROFILE_IDS == 1
  bits.b = (bits.b & 0xFFFFFF00u) | (texelFetch(u_profile_ids, pixel, 0).r & 0xFFu);
#endif
  o_taps = uvec4(bits, distance);
  o_strength = floatBitsToUint(color.a);
  o_intermediate = o_taps;
#if SSS_MARK_DEPTH
  gl_FragDepth = color.a > 0.0 ? 0.0 : 1.0;  // NaN alpha: not marked (the passes leave it alone)
#endif
}
