// Rounding to half float in the shader, before a pass writes a half-float target (u_round_to_half:
// the RGBA16F intermediate, an RGBA16F host colour or output, the RGBA16F sum of terms on ES; a
// uniform rather than a variant, so that no program is built twice for it).
// GL leaves the rounding of a float stored into a half-float target to the implementation, and
// llvmpipe (Mesa 22.3) rounds toward zero: every written value lost half a unit in the last place on
// average, always downwards. Where a channel needs a change smaller than that (blue and green at 1-2
// mm per pixel) that bias tripled its miss (the pre-integrated kernel's blue at 2 mm/px: 0.38 on the
// CPU model, 1.16 on llvmpipe). A value rounded here is a half float already, which every
// conversion stores exactly, so each driver writes what sss::math::round_to_half
// (module/src/math/half_float.cpp) gives the CPU model: nearest, ties to even.
#ifndef SSS_UNIFORM_u_round_to_half  // a pass kind's uniform struct declares it (module/src/gl/pass_uniforms.hpp)
uniform bool u_round_to_half;
#endif

vec4 sss_nearest_half(vec4 v) {
  if (!u_round_to_half) return v;
  // Branch-free on all four components at once (no per-channel branch for a SIMD group to diverge on).
  // Normal halves: keep 10 of the 23 fraction bits, rounding the 13 dropped ones to nearest, ties to
  // even; the sign bit stays as it is, so -0 stays -0, and a carry into the exponent is the rounding.
  uvec4 bits = floatBitsToUint(v);
  vec4 normal = uintBitsToFloat((bits + 0x0FFFu + ((bits >> 13u) & 1u)) & 0xFFFFE000u);
  // Below the smallest normal half (2^-14) the steps are 2^-24 (roundEven keeps the sign).
  vec4 subnormal = roundEven(v * 16777216.0) * (1.0 / 16777216.0);
  vec4 a = abs(v);
  vec4 rounded = mix(normal, subnormal, lessThan(a, vec4(6.103515625e-05)));
  // Infinite, NaN, or past the largest half (65504 and its rounding margin): the conversion's own.
  return mix(v, rounded, lessThan(a, vec4(65520.0)));
}
