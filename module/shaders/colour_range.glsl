// The colours the passes blur: finite, and within +-2^125 (4.25e37). Past that the passes' float
// arithmetic could overflow (a difference of two such values reaches 2^126, under float's 2^128;
// a weighted sum stays within its largest term), which an RGBA32F colour and its RGBA32F
// intermediate would otherwise carry as infinity or NaN into its neighbours. A colour outside the
// range is treated like NaN and infinity: the pixel keeps its value, and as a tap counts as the
// centre's colour. The CPU model's bound is the same (cpu_passes::kColourLimit, cpu_filter_passes.hpp).
// isnan() as well as the comparison: see separable_blur.frag on NVIDIA's negated comparisons.
const float kSssColourLimit = 4.2535296e37;  // 2^125
// What the passes' inputs hold for such a colour (pass_inputs.frag, msaa_resolve.frag), at distance
// NaN: finite, so that no sum it might enter turns NaN, and past the bound, so that a pass without
// follow-surface (which reads no distance) still finds it out of range and takes the centre.
const float kSssUnusableColour = -8.507059e37;  // -2^126

bool sss_in_range(vec4 c) {
  return !any(isnan(c)) && !any(isinf(c)) && all(lessThanEqual(abs(c), vec4(kSssColourLimit)));
}
bool sss_in_range(vec3 c) { return sss_in_range(vec4(c, 0.0)); }
