// The colour with its strength taken from the host's separate strength texture (sss_frame.
// strength_texture: a colour format without alpha, R11F_G11F_B10F, or an alpha kept for something
// else): rgb from the colour, alpha from the strength's red channel, into the module's copy that the
// passes then read as their colour. Rounded to half float where the copy is RGBA16F
// (u_round_to_half, nearest_half.glsl), so that the copy holds what an RGBA16F colour uploaded
// with that alpha would hold, whatever rounding the driver's conversion does.
#include "nearest_half.glsl"
SSS_BINDING(0) uniform sampler2D u_source;    // the host's colour
SSS_BINDING(1) uniform sampler2D u_strength;  // the host's strength (R8, R16F or R32F: red)
out vec4 o_color;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  o_color = sss_nearest_half(vec4(texelFetch(u_source, pixel, 0).rgb, texelFetch(u_strength, pixel, 0).r));
}
