// The half-resolution path's inputs (sss.h SSS_PATH_HALF_RESOLUTION; module/src/math/half_resolution.hpp):
// each half-size texel from its 2x2 block of pass_inputs.frag's texels, in the same layout (colour
// and distance bits in an RGBA32UI texel, strength in an R32UI one, and the horizontal pass's
// target filled alike), so the separable passes run on it unchanged, at half the pixels per mm.
//
// The block's representative is its nearest translucent pixel (nearest opaque one where none is
// translucent): its distance (and R8UI index) is the texel's, so a silhouette's texel stays on one
// surface rather than between two. The block's pixels on that surface (the same index, and a
// distance within u_merge_reach of the kernel's reach: the follow-surface factor of the
// representative's profile) are averaged into the texel's colour and strength. This must compute
// what sss::math::cpu_half_resolution_filter does (module/src/math/cpu_half_resolution.cpp).
//
// Like pass_inputs.frag it marks the half-size culling depth: 0 where the texel is translucent.
// Switches: SSS_PROFILE_IDS 0 none, 1 R8UI indices in the blue colour word's low byte
// (pass_inputs.frag), which the texel takes from its representative.

SSS_BINDING(0) uniform highp usampler2D u_source;    // pass_inputs.frag's colour and distance bits
SSS_BINDING(1) uniform highp usampler2D u_strength;  // pass_inputs.frag's strength bits
uniform float u_depth_factor[16];      // per profile: 1 / the kernel's reach in world units (0: no follow-surface)
// u_rect (the drawn rectangle's first and last pixel: x0, y0, x1, y1), u_profile_count and
// u_merge_reach (math::kHalfResolutionMergeReach) are the reduction's uniform struct, declared with
// the variant's #defines (module/src/gl/pass_uniforms.hpp).

layout(location = 0) out uvec4 o_taps;
layout(location = 1) out uint o_strength;
layout(location = 2) out uvec4 o_intermediate;

float sss_distance(uint word) { return uintBitsToFloat(word); }
// A texel's colour: with R8UI indices the blue word's low byte is the index.
vec3 sss_colour(uvec3 bits) {
#if SSS_PROFILE_IDS == 1
  bits.b &= 0xFFFFFF00u;
#endif
  return uintBitsToFloat(bits);
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uvec4 t[4];
  float s[4];
  bool translucent[4];
  bool any_translucent = false;
  for (int k = 0; k < 4; ++k) {
    ivec2 pixel = clamp(2 * texel + ivec2(k & 1, k >> 1), u_rect.xy, u_rect.zw);
    t[k] = texelFetch(u_source, pixel, 0);
    s[k] = uintBitsToFloat(texelFetch(u_strength, pixel, 0).r);
    translucent[k] = s[k] > 0.0 && !isnan(sss_distance(t[k].a));
    any_translucent = any_translucent || translucent[k];
  }
  int r = -1;
  float nearest = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (translucent[k] != any_translucent) continue;
    float d = sss_distance(t[k].a);
    if (r < 0 || isnan(nearest) || d < nearest) {
      r = k;
      nearest = d;
    }
  }
  uint word = t[r].a;
  uint index = t[r].b & 0xFFu;
  int profile = 0;
#if SSS_PROFILE_IDS == 1
  profile = int(index & 15u);
  if (profile >= u_profile_count) profile = 0;
#endif
  float factor = u_depth_factor[profile];
  vec3 colour = vec3(0.0);
  float strength = 0.0, n = 0.0;
  for (int k = 0; k < 4; ++k) {
#if SSS_PROFILE_IDS == 1
    bool same = (t[k].b & 0xFFu) == index;
#else
    bool same = true;
#endif
    bool joins = k == r || (translucent[k] == any_translucent && same &&
                            factor * abs(sss_distance(t[k].a) - nearest) < u_merge_reach);
    if (!joins) continue;
    colour += sss_colour(t[k].rgb);
    strength += s[k];
    n += 1.0;
  }
  uvec3 bits = floatBitsToUint(colour / n);
#if SSS_PROFILE_IDS == 1
  bits.b = (bits.b & 0xFFFFFF00u) | index;
#endif
  o_taps = uvec4(bits, word);
  o_strength = floatBitsToUint(any_translucent ? strength / n : 0.0);
  o_intermediate = o_taps;
  gl_FragDepth = any_translucent ? 0.0 : 1.0;  // the half-size passes' culling, as pass_inputs.frag's
}
