// Writes the blurred result back into the host's multisampled colour. Only translucent samples
// change: each gets the pixel's change x = (blurred - resolved) · samples / translucent samples, so
// the box resolve of the written pixel equals the blurred pixel while opaque samples (the background
// side of a silhouette) keep their exact values and per-sample detail survives for a host that
// tone-maps before it resolves.
//
// The pass never reads the host's colour (it draws into it: reading it would be a feedback loop,
// and copying it first cost a full multisampled copy): the resolve kept what it needs per pixel
// (msaa_resolve.frag), and blending applies the change to each sample's own value. With dual-source
// blending (src0 · 1 + dst · src1) every translucent sample s of the pixel becomes a + b · s:
// - a = x, b = 1 where the pixel's smallest translucent value m stays >= 0 (m + x >= 0): s + x;
// - otherwise (irradiance cannot go below 0) the samples are pulled towards m, which lands on 0:
//   b = (t + x) / (t - m), a = -m · b with t their mean, so their mean is still t + x (and the
//   resolve still the blurred pixel); where t + x <= 0 itself, every translucent sample becomes 0.
//   b is rounded down to a multiple of 2^-11, exact in half float too, so that a blender computing
//   in the target's precision still maps m to exactly 0 (and b · m is exact for a half-float m).
// Per channel; alpha is masked (glColorMask) and keeps the host's exact value.
//
// With a texturing mode (SSS_ALBEDO 1 or 2) the resolve gave the quotient colour / A_post (its mean,
// translucent mean and lowest value: msaa_resolve.frag) and the passes blurred it, so the above is
// the change of each sample's quotient q_s; its colour is A_post_s · q_s, so the sample becomes
// A_post_s · a + b · s (src0 scaled by the sample's own A_post, read from the host's multisampled
// albedo): a sample whose light does not change (x = 0) is discarded and keeps its value exactly,
// and the quotients' mean is still the blurred pixel. Each sample needs its own src0, so the one-draw
// variant reads gl_SampleID there (which runs the shader once per sample) and the per-sample draws
// u_sample. (b · s less A_post_s · m · b lands on 0 only to rounding where q_s = m: the product
// A_post_s · q_s is the colour to within a float ulp, not exactly.)
//
// Compile-time switch (module/src/gl/shader_variants.cpp): SSS_SAMPLE_MASK_OUTPUT 1 (GLSL 4.00+):
// one draw, gl_SampleMask selects the pixel's translucent samples; 0 (GLSL 3.30): one draw per
// sample under glSampleMaski, u_sample says which, and the draw discards where it is not translucent.
SSS_BINDING(0) uniform usampler2D u_lowest;     // resolve: the translucent samples' smallest rgb (float bits), mask (a)
SSS_BINDING(1) uniform sampler2D u_blurred;     // the vertical pass's single-sample result
SSS_BINDING(2) uniform sampler2D u_resolved;    // the resolve pass's colour
SSS_BINDING(3) uniform sampler2D u_translucent; // resolve: the translucent samples' mean rgb (read where one would go below 0)
// u_samples and (SSS_SAMPLE_MASK_OUTPUT 0) u_sample, the sample this draw writes (the one
// glSampleMaski lets through), are the write-back's uniform struct, declared with the variant's
// #defines (module/src/gl/pass_uniforms.hpp).
#include "albedo.glsl"
layout(location = 0, index = 0) out vec4 o_add;    // a (src0)
layout(location = 0, index = 1) out vec4 o_scale;  // b (src1, the destination's factor)

// No NaN (which fails every comparison) and no infinity.
bool finite(vec4 v) { return all(lessThanEqual(abs(v), vec4(uintBitsToFloat(0x7f7fffffu)))); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uvec4 lowest = texelFetch(u_lowest, pixel, 0);
  uint mask = lowest.a;
#if SSS_SAMPLE_MASK_OUTPUT
  if (mask == 0u) discard;
  gl_SampleMask[0] = int(mask);
  float count = float(bitCount(mask));
#else
  if (((mask >> uint(u_sample)) & 1u) == 0u) discard;
  float count = 0.0;
  for (int i = 0; i < u_samples; ++i) count += float((mask >> uint(i)) & 1u);
#endif
  // Pixels the module's mask left out (msaa_mask.frag's test: alpha > 0, all finite) were not
  // drawn by the passes: the blurred image holds nothing there (behind the host's stencil, its copy
  // of the resolved colour). A non-finite resolved colour makes the change non-finite.
  vec4 resolved = texelFetch(u_resolved, pixel, 0);
  vec3 delta = texelFetch(u_blurred, pixel, 0).rgb - resolved.rgb;
  if (!(resolved.a > 0.0 && finite(vec4(delta, resolved.a))) || all(equal(delta, vec3(0.0)))) discard;
  vec3 x = delta * (float(u_samples) / count);
  vec3 m = uintBitsToFloat(lowest.rgb);
  vec3 add = x, scale = vec3(1.0);
  bvec3 fits = greaterThanEqual(m + x, vec3(0.0));
  if (!all(fits)) {  // rare: the mean is needed only here
    vec3 t = texelFetch(u_translucent, pixel, 0).rgb;
    vec3 pulled = clamp((t + x) / max(t - m, vec3(1e-30)), 0.0, 1.0);
    pulled = mix(floor(pulled * 2048.0) / 2048.0, vec3(0.0), lessThanEqual(t + x, vec3(0.0)));
    scale = mix(pulled, vec3(1.0), fits);
    add = mix(-(m * pulled), x, fits);
  }
#if SSS_ALBEDO
#if SSS_SAMPLE_MASK_OUTPUT
  add *= sss_albedo_post_at(pixel, gl_SampleID, SSS_ALBEDO);
#else
  add *= sss_albedo_post_at(pixel, u_sample, SSS_ALBEDO);
#endif
#endif
  if (!finite(vec4(add, 0.0))) discard;  // an overflowing change leaves the pixel as it was
  o_add = vec4(add, 0.0);
  o_scale = vec4(scale, 1.0);
}
