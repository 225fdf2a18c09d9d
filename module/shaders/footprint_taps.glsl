// The footprint-aware taps of a separable blur pass, for separable_blur.frag and .comp: they sit on
// whole pixels chosen from this pixel's footprint (no bilinear read blends a neighbour into a tap)
// and each weighs the pass's kernel integrated over the pixels it stands for, from its cumulative
// table u_cdf. This must compute exactly what sss::math::footprint_taps does
// (module/src/math/footprint_kernel.cpp).
//
// Switches: footprint_cells.glsl's (the tables and the layout, which it includes), SSS_JITTER and
// SSS_FOLLOW_SURFACE (see separable_blur.frag). Before this piece
// the shader includes depth.glsl and jitter.glsl, and defines how its taps are read (GLSL has no
// function pointers):
//   struct TapSite      what the shader needs to find this pixel's taps
//   vec4 sss_fetch_tap(TapSite site, float offset, out vec2 moved)
//                       the pixel `offset` steps from the centre along the pass's line (the
//                       vertical pass's sheared: pass_surface.glsl; `moved`: its centre's window
//                       offset from the centre's, where the read really is), kept in
//                       u_clamp: rgb its colour, a its view distance (read only with
//                       SSS_FOLLOW_SURFACE); a colour that is not finite or past colour_range.glsl's
//                       bound as kSssUnusableColour at distance NaN (the fragment passes' inputs
//                       draw and the compute path's cache sanitise once per texel)
//   bool sss_tap_foreign   (SSS_PROFILE_IDS only) set by sss_fetch_tap: the pixel it read has
//                       another profile or object index than the centre, and counts as the centre

#include "footprint_cells.glsl"

// A tap's colour as it enters the sum: a non-finite neighbour (or one past colour_range.glsl's bound)
// must not spread, so it counts as the
// centre's colour (its weight goes to the centre), like a tap across a depth step; with
// follow-surface it is blended back to the centre's as it leaves the surface: by its distance off
// the centre's surface (pass_surface.glsl), |d · line.x + line.y| times the follow-surface factor
// for its distance d (sss_off_surface), so that a slope is not taken for a step; the ramp less the
// tap's `slack` (a bend of the skin is not a step either).
vec3 settled_tap(vec4 fetched, vec3 centre, vec2 line, float slack) {
  vec3 tap = fetched.rgb;
#if !SSS_FOLLOW_SURFACE
  // With follow-surface such a tap's distance, NaN, makes the blend below the centre exactly: no
  // test per tap. Without, its colour, kSssUnusableColour, is found out of range here.
  if (!sss_in_range(tap)) tap = centre;  // colour_range.glsl
#endif
#if SSS_FOLLOW_SURFACE
  float d = abs(fetched.a * line.x + line.y);
#if SSS_FOLLOW_SURFACE == 2
  float s = 1.0 - exp(-d * d * SSS_INV_TWO_VARIANCE);
#else
  float s = max(d - slack, 0.0);
#endif
  // Past the reach, or an unusable tap (its distance NaN, so d is): the centre itself, not
  // mix(tap, centre, 1), which a driver may compute as tap + (centre - tap), inexact for a large
  // tap. The NaN is tested on d, not on s: max() may drop a NaN, and so may a compiler that turns
  // `x < 0.0 ? 0.0 : x` into max() (Mesa's NIR does, which let kSssUnusableColour into the sum).
  tap = isnan(d) || !(s < 1.0) ? centre : mix(tap, centre, s);
#endif
  return tap;
}

// The pass's weighted sum at one pixel (centre colour `centre`, taps step_pixels apart per profile
// mm; `follow` and `slack`: the off-surface coefficients and the slack per step, sss_follow and
// sss_follow_slack; `pixel` and `axis` (0 horizontal, 1 vertical)
// seed the jitter). Taps on whole pixels (of the pass's line: pass_surface.glsl): every
// pixel out to the reach where the kernel spans at most u_half_taps on a side, else u_half_taps
// spread denser at the centre (never two on one pixel). A tap's weight is the kernel over the
// pixels between the midpoints to its neighbours; the last one takes the tail.
vec3 footprint_sum(TapSite site, vec3 centre, float step_pixels, vec4 follow, float slack, ivec2 pixel, int axis) {
  float reach_pixels = sss_reach_pixels(step_pixels);
  bool dense = sss_dense_taps(reach_pixels);
  int count = sss_tap_count(reach_pixels);
#if SSS_JITTER
  int jitter_from = dense ? count + 1 : u_jitter_from;
  float noise = jitter_noise(pixel, axis);
  float inner = 0.0;
#endif
  // Without taps the whole kernel stays on the centre. With taps the centre keeps the kernel out to
  // the midpoint to the first tap, so only a pixel with taps (a kernel wider than its pixel) looks
  // that up: in a block of its own before the loop, not in the loop's first step, because a SIMD
  // rasteriser that runs every step's body for all its lanes (llvmpipe) would pay for it each step.
  vec3 total = SSS_CDF(SSS_CDF_ENTRIES - 1).rgb;
  vec3 sum = centre * (2.0 * total + SSS_FOOTPRINT.yzw);
  vec3 below = total;
  float p = 0.0;
  // Two positions' sum times this: the fraction of the reach at their midpoint, in profile mm over
  // the reach (sss::math::footprint_midpoint_scale). Not the clamped reach_pixels: the same product.
  float midpoint_scale = 0.5 / (SSS_FOOTPRINT.x * step_pixels);
  if (count > 0) {
    p = tap_position(1, 0.0, dense, reach_pixels);
    below = half_cdf(p * midpoint_scale);
    sum = centre * (2.0 * below + SSS_FOOTPRINT.yzw);
  }
#ifdef SSS_HALF_TAPS
  for (int i = 1; i <= SSS_HALF_TAPS; ++i) {  // a constant bound, so the loop can unroll
    if (i > count) break;
#else
  for (int i = 1; i <= count; ++i) {
#endif
    float next = i < count ? tap_position(i + 1, p, dense, reach_pixels) : 0.0;
    vec3 upto = i < count ? half_cdf((p + next) * midpoint_scale) : total;
    float read = p;
#if SSS_JITTER
    if (i >= jitter_from) read = jittered_position(inner, p, next, i == count, noise);
    inner = p;
#endif
    vec3 pair = vec3(0.0);
    for (int side = 0; side < 2; ++side) {
      float offset = side == 0 ? read : -read;
      vec2 moved;
      vec4 fetched = sss_fetch_tap(site, offset, moved);
      vec3 tap = settled_tap(fetched, centre, sss_off_surface(follow, moved), read * slack);
#if SSS_PROFILE_IDS
      if (sss_tap_foreign) tap = centre;  // another material or object: its weight stays on the centre
#endif
      pair += tap;
    }
    sum += (upto - below) * pair;
    below = upto;
    p = next;
  }
  return sum;
}
