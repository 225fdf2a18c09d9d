// The cells of the footprint-aware taps (footprint_kernel.hpp), for footprint_taps.glsl and
// cbf_blur.frag: the pass's cumulative table and tap layout, where the i-th tap sits (tap_position)
// and how much of the kernel the pixels up to a point hold (half_cdf). This must compute exactly
// what sss::math::footprint_taps does (module/src/math/footprint_kernel.cpp).
//
// Switches: SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS (the sizes of u_cdf and u_spacing), SSS_HALF_TAPS (when
// defined: the tap count as a constant instead of a uniform), SSS_JITTER, SSS_FOLLOW_SURFACE,
// SSS_PROFILE_IDS and SSS_PROFILES (see separable_blur.frag). The reach and centre delta
// (u_footprint), the tap count (u_half_taps), the first tap that jitters (u_jitter_from) and the
// depth Gaussian's u_inv_two_variance are fields of the pass's uniform struct (the blur's or the
// cross-bilateral pass's, module/src/gl/pass_uniforms.hpp); the tables are uniforms of their own.

#if SSS_PROFILE_IDS
// Per-pixel profiles (SSS_PROFILE_IDS 1): every profile's table for this pass in one uniform block
// (module/src/math/profile_set.hpp's layout: SSS_CDF_ENTRIES cumulative entries, then the reach and
// centre delta), picked by the centre pixel's index; main() sets sss_table_base and
// sss_inv_two_variance before the taps.
layout(std140) uniform SssProfileTables {
  vec4 u_tables[SSS_PROFILES * (SSS_CDF_ENTRIES + 1)];
};
int sss_table_base;
float sss_inv_two_variance;
#define SSS_CDF(j) u_tables[sss_table_base + (j)]
#define SSS_FOOTPRINT u_tables[sss_table_base + SSS_CDF_ENTRIES]
#define SSS_INV_TWO_VARIANCE sss_inv_two_variance
#else
uniform vec4 u_cdf[SSS_CDF_ENTRIES];          // rgb: ∫_0^x kernel at x = reach·(j/(N-1))²; the last: up to ∞
#define SSS_CDF(j) u_cdf[j]
#define SSS_FOOTPRINT u_footprint             // x: the table's reach in profile mm, yzw: the centre delta
#define SSS_INV_TWO_VARIANCE u_inv_two_variance  // 1 / (2v) of the term's depth Gaussian, v in mm²
#endif
uniform float u_spacing[SSS_MAX_HALF_TAPS];   // sparse layout: tap i at reach·u_spacing[i-1] (pixels)
#ifdef SSS_HALF_TAPS
// The tap count as a constant of the variant (the fragment passes at a preset count), so the
// compiler sees the loop's bound and unrolls it. The spacing stays the uniform array: unrolled,
// each step reads one element at a constant index, inside the array even where the last step
// looks one tap ahead in code that never runs. (As a const array of SSS_HALF_TAPS literals that
// index was past its end, which NVIDIA's compiler refused; a chain of selects in its place cost
// llvmpipe 1.8 % more on the 1080p close-up, the uniform 0.2 % more than the literals.)
const int kSssHalfTaps = SSS_HALF_TAPS;       // the most taps on either side
#else
#define kSssHalfTaps u_half_taps              // the most taps on either side
#endif

// The pass's kernel integrated from 0 to `fraction` of its reach, as
// sss::math::footprint_half_cdf_at_fraction. The taps pass the sum of two positions times
// footprint_sum's midpoint scale: one division per pixel, not two per tap (llvmpipe's tap loop
// waited on them).
vec3 half_cdf(float fraction) {
  float u = sqrt(min(fraction, 1.0)) * float(SSS_CDF_ENTRIES - 1);
  int j = min(int(u), SSS_CDF_ENTRIES - 2);
  float f = u - float(j);
  return SSS_CDF(j).rgb * (1.0 - f) + SSS_CDF(j + 1).rgb * f;
}

// The kernel's reach in pixels at a step of `step_pixels` pixels per profile mm, and how many taps a
// side the passes read for it (footprint_sum, cbf_blur.frag): every pixel out to the reach where
// that takes at most kSssHalfTaps, else kSssHalfTaps (the debug views show the count).
float sss_reach_pixels(float step_pixels) { return min(SSS_FOOTPRINT.x * step_pixels, 1.0e6); }
bool sss_dense_taps(float reach_pixels) { return reach_pixels <= float(kSssHalfTaps) + 0.5; }
int sss_tap_count(float reach_pixels) {
  return sss_dense_taps(reach_pixels) ? max(int(ceil(reach_pixels - 0.5)), 0) : kSssHalfTaps;
}

// The i-th tap's distance from the centre in pixels (i >= 1), after the previous one's.
float tap_position(int i, float previous, bool dense, float reach_pixels) {
  return dense ? float(i) : max(previous + 1.0, floor(reach_pixels * u_spacing[i - 1] + 0.5));
}

