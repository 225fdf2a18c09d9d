// One pass of the separable subsurface-scattering filter (Jimenez et al. 2012, §3): the 1D kernel
// along `u_axis`, its footprint scaled per pixel by depth and by the strength in alpha, taps blended
// back to the centre colour as their depth leaves the kernel's reach (follow-surface). A kernel of
// several separable terms (sum of Gaussians, SVD rank N) runs this pair of passes once per term; the
// vertical pass of a later term adds the earlier terms' sum (SSS_ACCUMULATE).
//
// Compile-time switches (prepended by the module):
//   SSS_OUTSIDE   what a pixel that is not blurred writes: 0 its own value (horizontal pass, which
//                 fills the intermediate everywhere), 1 nothing (discard: vertical pass writing back
//                 into the host's colour), 2 the host's original colour (vertical pass into a
//                 separate output texture)
//   SSS_FOLLOW_SURFACE  0 off; 1 the linear ramp to the kernel's reach; 2 the exact depth correction
//                       of a Gaussian term (supplementary §E): blend by 1 - exp(-dz² / 2v), dz in
//                       profile millimetres
//   SSS_JITTER          1: where the taps are spread out, those from u_jitter_from on read a pixel
//                       of their cell chosen by per-pixel integer-hash noise (supplementary Fig.
//                       S.6-S.7); their weights stay the cells'
//   SSS_ACCUMULATE      1: add the earlier terms' sum (u_accumulated, unit 3) to the result
//   SSS_LINEAR_DEPTH    0: hardware depth, linearised with the projection; 1: view distance
//   SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS  the sizes of u_cdf and u_spacing
// and from the dialect's header (module/src/gl/glsl_variant.cpp):
//   SSS_BINDING(unit)        layout(binding = unit) where the dialect has it, else nothing (the
//                            module sets the unit with glUniform1i)
// and nearest_half.glsl (sss_nearest_half: the written colour rounded to half float where the target
// is one, u_round_to_half).
//
// Every pass runs footprint-aware taps: they sit on whole pixels chosen from this pixel's footprint
// (no bilinear read blends a neighbour into a tap) and each weighs the pass's kernel integrated over
// the pixels it stands for, from its cumulative table u_cdf. This must compute exactly what
// sss::math::footprint_taps does (module/src/math/footprint_kernel.cpp).

SSS_BINDING(0) uniform sampler2D u_source;    // the pass input (host colour, then the intermediate)
SSS_BINDING(1) uniform sampler2D u_depth;     // the host's depth
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
#if SSS_ACCUMULATE
SSS_BINDING(3) uniform sampler2D u_accumulated;  // the earlier terms' vertical sums (the module's own target)
#endif
uniform vec4 u_cdf[SSS_CDF_ENTRIES];          // rgb: ∫_0^x kernel at x = reach·(j/(N-1))²; the last: up to ∞
uniform vec4 u_footprint;                     // x: the table's reach in profile mm, yzw: the centre delta
uniform float u_spacing[SSS_MAX_HALF_TAPS];   // sparse layout: tap i at reach·u_spacing[i-1] (pixels)
uniform int u_half_taps;                      // the most taps on either side
#if SSS_JITTER
uniform int u_jitter_from;                    // the first sparse tap (1 = next to the centre) that jitters
#endif
#if SSS_FOLLOW_SURFACE == 2
uniform float u_inv_two_variance;      // 1 / (2v) of the term's depth Gaussian, v in mm²
#endif
uniform vec2 u_axis;                  // (1, 0) or (0, 1)
uniform float u_pixels_per_mm;        // along u_axis, at clip w = 1 and strength 1
uniform float u_follow_surface;       // 1 / the kernel's reach in world units (SSS_FOLLOW_SURFACE 2: 1 / world units per mm)
uniform vec2 u_ndc_from_depth;        // z_ndc = depth · x + y
uniform vec4 u_depth_terms;           // projection m10, m11, m14, m15
uniform vec4 u_clamp;                 // tap positions are kept inside (xy min, zw max), in pixels

out vec4 o_color;

float view_distance(float raw_depth) {
#if SSS_LINEAR_DEPTH
  return raw_depth;
#else
  float zn = raw_depth * u_ndc_from_depth.x + u_ndc_from_depth.y;
  return (zn * u_depth_terms.w - u_depth_terms.z) / (zn * u_depth_terms.y - u_depth_terms.x);
#endif
}

#if SSS_JITTER
// The jitter noise in [0, 1): must equal sss::math::jitter_noise (module/src/math/pass_kernel.cpp)
// bit for bit, which 32-bit uint arithmetic guarantees.
float jitter_noise(ivec2 pixel, int axis) {
  uint h = uint(pixel.x) * 0x8da6b343u ^ uint(pixel.y) * 0xd8163841u ^ uint(axis + 1) * 0xcb1ab31fu;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return float(h >> 8u) * (1.0 / 16777216.0);
}
#endif

// The pass's kernel integrated from 0 to x_mm, as sss::math::footprint_half_cdf.
vec3 half_cdf(float x_mm) {
  float u = sqrt(min(x_mm / u_footprint.x, 1.0)) * float(SSS_CDF_ENTRIES - 1);
  int j = min(int(u), SSS_CDF_ENTRIES - 2);
  float f = u - float(j);
  return u_cdf[j].rgb * (1.0 - f) + u_cdf[j + 1].rgb * f;
}

// The i-th tap's distance from the centre in pixels (i >= 1), after the previous one's.
float tap_position(int i, float previous, bool dense, float reach_pixels) {
  return dense ? float(i) : max(previous + 1.0, floor(reach_pixels * u_spacing[i - 1] + 0.5));
}

#if SSS_JITTER
// The pixel a jittered tap reads in its cell (tap at p, inner neighbour at `inner`, outer one at
// `outer`; the outermost tap's cell is its inner half mirrored), as sss::math::footprint_taps.
float jittered_position(float inner, float p, float outer, bool outermost, float noise) {
  float lo = floor(0.5 * (inner + p)) + 1.0;
  float hi = outermost ? p + (p - lo) : floor(0.5 * (p + outer));
  return lo + min(floor(noise * (hi - lo + 1.0)), hi - lo);
}
#endif

void leave_untouched(ivec2 pixel, vec4 centre) {
#if SSS_OUTSIDE == 0
  o_color = centre;
#elif SSS_OUTSIDE == 1
  discard;
#else
  o_color = texelFetch(u_original, pixel, 0);
#endif
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_source, pixel, 0);
  // Not translucent, or a non-finite colour or strength: the pixel keeps its own value.
  if (!(centre.a > 0.0) || any(isnan(centre)) || any(isinf(centre))) {
    leave_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);  // alpha is documented as 0..1; more must not widen the kernel
  float centre_distance = view_distance(texelFetch(u_depth, pixel, 0).r);
  float w = -u_depth_terms.y * centre_distance + u_depth_terms.w;
  // Behind the camera, on an infinite far plane, or NaN. isnan() and not only !(w > 0.0): on
  // NVIDIA's driver (580) the negated comparison behaved as the opposite one, which a NaN passes.
  if (isnan(w) || !(w > 0.0) || isinf(w)) {
    leave_untouched(pixel, centre);
    return;
  }

  float step_pixels = u_pixels_per_mm * strength / w;
  float follow_surface = u_follow_surface / strength;  // the reach scales with alpha like the taps
  // Taps on whole pixels: every pixel out to the reach where the kernel spans at most u_half_taps
  // on a side, else u_half_taps spread denser at the centre (never two on one pixel). A tap's weight is the
  // kernel over the pixels between the midpoints to its neighbours; the last one takes the tail.
  float reach_pixels = min(u_footprint.x * step_pixels, 1.0e6);
  bool dense = reach_pixels <= float(u_half_taps) + 0.5;
  int count = dense ? max(int(ceil(reach_pixels - 0.5)), 0) : u_half_taps;
#if SSS_JITTER
  int jitter_from = dense ? count + 1 : u_jitter_from;
  float noise = jitter_noise(pixel, u_axis.y > 0.5 ? 1 : 0);
  float inner = 0.0;
#endif
  // Without taps the whole kernel stays on the centre. With taps the centre keeps the kernel out to
  // the midpoint to the first tap, set in the loop's first step, so a pixel with no tap (a kernel
  // inside its pixel) looks nothing up.
  vec3 total = u_cdf[SSS_CDF_ENTRIES - 1].rgb;
  vec3 sum = centre.rgb * (2.0 * total + u_footprint.yzw);
  vec3 below = total;
  float p = 0.0;
  for (int i = 1; i <= count; ++i) {
    if (i == 1) {
      p = tap_position(1, 0.0, dense, reach_pixels);
      below = half_cdf(0.5 * p / step_pixels);
      sum = centre.rgb * (2.0 * below + u_footprint.yzw);
    }
    float next = i < count ? tap_position(i + 1, p, dense, reach_pixels) : 0.0;
    vec3 upto = i < count ? half_cdf(0.5 * (p + next) / step_pixels) : total;
    float read = p;
#if SSS_JITTER
    if (i >= jitter_from) read = jittered_position(inner, p, next, i == count, noise);
    inner = p;
#endif
    vec3 pair = vec3(0.0);
    for (int side = 0; side < 2; ++side) {
      vec2 position = clamp(gl_FragCoord.xy + u_axis * (side == 0 ? read : -read), u_clamp.xy, u_clamp.zw);
      ivec2 texel = ivec2(position);
      vec3 tap = texelFetch(u_source, texel, 0).rgb;
      // A non-finite neighbour must not spread: it counts as the centre's colour (its weight goes
      // to the centre), like a tap across a depth step.
      if (any(isnan(tap)) || any(isinf(tap))) tap = centre.rgb;
#if SSS_FOLLOW_SURFACE
      float d = follow_surface * abs(centre_distance - view_distance(texelFetch(u_depth, texel, 0).r));
#if SSS_FOLLOW_SURFACE == 2
      float s = 1.0 - exp(-d * d * u_inv_two_variance);
#else
      float s = d;
#endif
      if (isnan(s) || !(s < 1.0)) s = 1.0;  // also when the tap's distance is not finite
      tap = mix(tap, centre.rgb, s);
#endif
      pair += tap;
    }
    sum += (upto - below) * pair;
    below = upto;
    p = next;
  }
#if SSS_ACCUMULATE
  sum += texelFetch(u_accumulated, pixel, 0).rgb;
#endif
#if SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(sum, centre.a));
#endif
}
