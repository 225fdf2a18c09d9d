// MSAA resolve (the first pass of the multisampled path, Jimenez et al. 2012 §4): the box average
// of the colour samples, and one depth per pixel as a LINEAR view distance. Averaging hardware
// depth would mix non-linear values (a silhouette pixel half on a near face and half on the far
// background lands far behind both); averaging the samples' view distances gives the distance of
// the pixel's mean surface, which is what the follow-surface test compares.
//
// Writing back into the host's samples (SSS_WRITE_BACK 1), the same loop also keeps what the
// write-back needs to know about each pixel's translucent samples (msaa_write.frag), so that pass
// never reads the host's colour, the texture it draws into: which samples they are, their mean
// colour and their smallest value per channel.
//
// With a texturing mode (SSS_ALBEDO 1 or 2, albedo.glsl) each sample's colour is divided by its own
// A_post before anything is summed, so that the resolved colour, the passes' inputs and the
// translucent samples' mean and lowest values are all of the quotient (the light the passes blur).
// Per sample rather than the resolved colour over the resolved albedo: a pixel's samples may lie
// on different albedos (a freckle's edge, a checker finer than the pixel), and only the samples'
// own quotients make uniform light come back as that light at every sample (mean(E·A_s / A_s) = E,
// where mean(E·A_s) / mean(A_s) holds for post-scatter alone, not for sqrt(A) nor where the floor
// clips), and let the write-back add A_post_s times one change to each sample. Into a separate
// output (SSS_WRITE_BACK 0) the resolve also writes the undivided mean (location 2: the colour a
// pixel the passes leave alone gets) and the samples' mean A_post (location 7: what the last pass
// multiplies the blurred quotient by).
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp):
// SSS_LINEAR_DEPTH 0: hardware depth, linearised per sample (depth.glsl's view_distance); 1: the
// host's depth already holds view distance. SSS_WRITE_BACK 1: the translucent samples' outputs too.
// SSS_ALBEDO 0: pre-scatter (no albedo read); 1, 2: the mode whose A_post divides each sample.
// Desktop GL only: assembled after version_330.glsl or version_420.glsl (sampler2DMS is not in GLSL ES 3.00).

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "albedo.glsl"

SSS_BINDING(0) uniform sampler2DMS u_color;
SSS_BINDING(1) uniform sampler2DMS u_depth;
// u_samples (the textures' sample count, both have the same), u_depth_mode (0 average, 1 sample
// 0, 2 minimum: nearest, 3 maximum: farthest) and the pieces' numbers are the resolve's uniform struct,
// declared with the variant's #defines (module/src/gl/pass_uniforms.hpp).

layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_distance;
// The fragment passes' inputs, as pass_inputs.frag writes them from a single-sample frame (its
// comment says why this layout): the resolved colour's and distance's bits, the strength's, and the
// horizontal pass's target filled alike. So the passes on the resolved images draw no inputs of
// their own, and the distance is linearised once.
layout(location = 4) out uvec4 o_taps;
layout(location = 5) out uint o_strength;
layout(location = 6) out uvec4 o_intermediate;
#if SSS_WRITE_BACK
layout(location = 2) out vec4 o_translucent;  // the translucent samples' mean colour (rgb), count (a)
layout(location = 3) out uvec4 o_lowest;      // their smallest value per channel (float bits, rgb), mask (a)

// A sample the write-back changes: some strength, and nothing infinite or NaN in it (NaN fails
// every comparison).
bool translucent(vec4 c) { return c.a > 0.0 && all(lessThanEqual(abs(c), vec4(uintBitsToFloat(0x7f7fffffu)))); }
#elif SSS_ALBEDO
layout(location = 2) out vec4 o_original;  // the undivided mean colour (rounded as o_color is)
layout(location = 7) out vec4 o_albedo;    // the samples' mean A_post (rgb), 1 (a)
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 color = vec4(0.0);
  float first = view_distance(texelFetch(u_depth, pixel, 0).r);
  float sum = 0.0, nearest = first, farthest = first;
#if SSS_WRITE_BACK
  vec3 translucent_sum = vec3(0.0);
  vec3 lowest = vec3(uintBitsToFloat(0x7f7fffffu));  // the largest finite float: any translucent value is below
  uint mask = 0u;
  float count = 0.0;
#endif
#if SSS_ALBEDO
  vec4 original = vec4(0.0);
  vec3 albedo_sum = vec3(0.0);
#endif
  for (int i = 0; i < u_samples; ++i) {
    vec4 c = texelFetch(u_color, pixel, i);
#if SSS_ALBEDO
    vec3 post = sss_albedo_post_at(pixel, i, SSS_ALBEDO);
    original += c;
    albedo_sum += post;
    c.rgb /= post;
#endif
    color += c;
#if SSS_WRITE_BACK
    // Selects, not a branch: the samples of neighbouring pixels differ.
    bool t = translucent(c);
    translucent_sum += t ? c.rgb : vec3(0.0);
    lowest = t ? min(lowest, c.rgb) : lowest;
    mask |= t ? 1u << uint(i) : 0u;
    count += t ? 1.0 : 0.0;
#endif
    float d = view_distance(texelFetch(u_depth, pixel, i).r);
    sum += d;
    nearest = min(nearest, d);
    farthest = max(farthest, d);
  }
  float n = float(u_samples);
  o_color = sss_nearest_half(color / n);  // what the resolved colour stores, exactly
  o_distance = u_depth_mode == 0 ? sum / n : u_depth_mode == 1 ? first : u_depth_mode == 2 ? nearest : farthest;
  uint distance = floatBitsToUint(o_distance);
  vec3 rgb = o_color.rgb;
  if (!sss_in_range(rgb)) {  // as pass_inputs.frag: kSssUnusableColour at distance NaN
    rgb = vec3(kSssUnusableColour);
    distance = 0x7FC00000u;
  }
  o_taps = uvec4(floatBitsToUint(rgb), distance);
  o_strength = floatBitsToUint(o_color.a);
  o_intermediate = o_taps;
#if SSS_WRITE_BACK
  o_translucent = vec4(count > 0.0 ? translucent_sum / count : vec3(0.0), count);
  o_lowest = uvec4(floatBitsToUint(lowest), mask);
#elif SSS_ALBEDO
  o_original = sss_nearest_half(original / n);
  o_albedo = vec4(albedo_sum / n, 1.0);
#endif
}
