// The module's copy of the colour that the passes read instead of the host's: its rgb divided by
// A_post where a texturing mode keeps the albedo out of the blur (albedo.glsl), and its alpha from
// the host's separate strength texture (sss_frame.strength_texture: a colour format without alpha,
// R11F_G11F_B10F, or an alpha kept for something else) or the colour's own. Rounded to half float
// where the copy is RGBA16F (u_round_to_half, nearest_half.glsl), so that the copy holds what an
// RGBA16F colour uploaded with those values would hold, whatever rounding the driver's conversion
// does.
//   SSS_STRENGTH_TEXTURE  1: alpha from u_strength's red; 0: the colour's alpha
//   SSS_ALBEDO            albedo.glsl's; with 3 the pixel's profile index picks its mode
//   SSS_PROFILE_IDS       with SSS_ALBEDO 3: 1 R8UI, 2 R16UI indices (value & 15 the profile)
#include "nearest_half.glsl"
#include "albedo.glsl"
SSS_BINDING(0) uniform sampler2D u_source;    // the host's colour
#if SSS_STRENGTH_TEXTURE
SSS_BINDING(1) uniform sampler2D u_strength;  // the host's strength (R8, R16F or R32F: red)
#endif
#if SSS_ALBEDO == 3
SSS_BINDING(4) uniform highp usampler2D u_profile_ids;  // the host's indices
uniform float u_texturing[SSS_PROFILES];                // each profile's mode (0-2)
#endif
out vec4 o_color;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 colour = texelFetch(u_source, pixel, 0);
#if SSS_STRENGTH_TEXTURE
  colour.a = texelFetch(u_strength, pixel, 0).r;
#endif
#if SSS_ALBEDO == 3
  int profile = int(texelFetch(u_profile_ids, pixel, 0).r & 15u);
  // An index without a profile is left alone by the passes; its copy is divided by nothing.
  colour.rgb /= sss_albedo_post(pixel, profile < SSS_PROFILES ? int(u_texturing[profile]) : 0);
#elif SSS_ALBEDO
  colour.rgb /= sss_albedo_post(pixel, SSS_ALBEDO);
#endif
  o_color = sss_nearest_half(colour);
}
