// One pass of the separable subsurface-scattering filter (Jimenez et al. 2012, §3): at each
// translucent pixel the pass's 1D kernel along its axis, its footprint scaled by the pixel's depth,
// its strength and the surface's turn, its taps blended back to the centre's colour where they
// leave the surface (follow-surface). What it reads and how it walks the surface: blur_pixel.glsl;
// the taps and their weights: footprint_taps.glsl. A kernel of several terms runs the pair of
// passes once per term, a later term's vertical pass adding the earlier terms' sum.
//
// The variant's switches (module/src/gl/shader_variants.hpp, which says why each exists):
//   SSS_PACKED_OUTPUT  1: the horizontal pass, writing RGBA32UI texels like its input (the blurred
//                      colour's bits and the centre's distance word); 0: a vertical pass
//   SSS_OUTSIDE        what a pixel the pass leaves alone gets: 0 its own value, 1 nothing
//                      (discard), 2 the host's original colour (into a separate output)
//   SSS_ACCUMULATE     1: add the earlier terms' sum (u_accumulated)
//   SSS_ALBEDO         the pass that writes the target: the sum times A_post (albedo.glsl)
// and blur_pixel.glsl's and footprint_taps.glsl's. The debug views are blur_debug_view.frag.

#include "blur_pixel.glsl"

#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
#if SSS_ACCUMULATE
SSS_BINDING(3) uniform sampler2D u_accumulated;  // the earlier terms' vertical sums (the module's own target)
#endif
#if SSS_PACKED_OUTPUT
out uvec4 o_packed;
#else
out vec4 o_color;
#endif

// A pixel the pass leaves alone; `texel`: its own input texel.
void leave_untouched(ivec2 pixel, uvec4 texel) {
#if SSS_OUTSIDE == 0 && SSS_PACKED_OUTPUT
  o_packed = texel;
#elif SSS_OUTSIDE == 0
  o_color = vec4(sss_colour(texel.rgb), 0.0);
#elif SSS_OUTSIDE == 1
  discard;
#else
  o_color = texelFetch(u_original, pixel, 0);
#endif
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  SssCentre c;
  if (!sss_read_centre(pixel, c)) {
    leave_untouched(pixel, c.texel);
    return;
  }
  SssWalk walk = sss_walk(pixel, c.distance);
  vec3 sum = footprint_sum(sss_tap_site(walk.shear), c.colour.rgb, sss_step_pixels(c, walk),
                           sss_follow(walk, c.follow_surface, c.distance), sss_follow_slack(walk, c.follow_surface),
                           pixel, kSssAxis);
#if SSS_ACCUMULATE
  sum += texelFetch(u_accumulated, pixel, 0).rgb;
#endif
  sum = sss_times_albedo_post(sum, pixel, sss_centre_texturing());
#if SSS_PACKED_OUTPUT
  uvec3 bits = floatBitsToUint(sss_nearest_half(vec4(sum, 0.0)).rgb);
#if SSS_PROFILE_IDS == 1
  bits.b = (bits.b & 0xFFFFFF00u) | (c.texel.b & 0xFFu);  // the index rides on for the vertical taps
#endif
  o_packed = uvec4(bits, c.texel.a);
#elif SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(sum, c.colour.a));
#endif
}
