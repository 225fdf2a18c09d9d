// The half-resolution path's upsample (sss.h SSS_PATH_HALF_RESOLUTION; the method and its reasons:
// module/src/math/half_resolution.hpp): at each translucent full-size pixel whose kernel reaches
// at least u_min_reach pixels on both axes,
//   out = B + Σ_q W_q · x_q − (Σ_q W_q) · X, kept within the range of the B texels and x_q it combined
// B and X the half-size result and input from the four nearest half-size texels (bilinear weights
// times 1 − the follow-surface blend of their distance off the pixel's tangent plane, on texels of
// the pixel's own index only); q the pixel, its two neighbours along the row and the nearest pixels
// of the rows above and below on the vertical pass's sheared line, x_q as the full-size passes take
// it, W_q the product of the two full-size passes' weights at offsets 0 and ±1 (the near field at
// full size; why: module/src/math/half_resolution.hpp). The steps and lines are the full-size
// passes' walk over the surface (pass_surface.glsl), from the four neighbours' distances.
// Every other pixel is discarded here, leaving the culling depth at 0, and the full-size passes
// that follow (drawn nearer) take exactly those; the written ones get depth 0.5 from this draw.
// This must compute what sss::math::cpu_half_resolution_filter does (cpu_half_resolution.cpp).
//
// Switches: SSS_PROFILE_IDS 0 or 1 (as half_inputs.frag), SSS_CDF_ENTRIES (a table's entries),
// SSS_ALBEDO (albedo.glsl: the result times A_post, one mode for the frame). It
// writes alpha as the colour's own (the strength's bits); writing back, the runner masks it off.
#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "pass_surface.glsl"
#include "albedo.glsl"

SSS_BINDING(0) uniform highp usampler2D u_source;    // pass_inputs.frag's colour and distance bits
SSS_BINDING(1) uniform highp usampler2D u_strength;  // pass_inputs.frag's strength bits (the colour's alpha)
SSS_BINDING(2) uniform highp usampler2D u_half_source;  // half_inputs.frag's texels
SSS_BINDING(3) uniform highp sampler2D u_half_result;   // the half-size passes' result (alpha: strength)
// Each profile's two pass tables (row 2·profile + axis): SSS_CDF_ENTRIES cumulative entries (rgb),
// then the table's reach in profile mm (r) and centre delta (gba): the passes' u_cdf and u_footprint.
SSS_BINDING(4) uniform highp sampler2D u_tables;
uniform vec4 u_looks[16];     // per profile: pixels per mm on x and y (clip w = 1, strength 1), depth factor
// u_profile_count, u_half_rect (the half-size texels the passes covered: first and last, x0, y0,
// x1, y1), u_rect (the drawn rectangle's first and last pixel), u_half_taps (the kernel's most taps
// per side), u_spacing (its sparse layout's first two taps, as shares of the reach), u_min_reach
// (math::kHalfResolutionMinReachPixels), u_min_weight (math::kHalfResolutionMinWeight) and the
// pieces' numbers are the upsample's uniform struct, declared with the variant's #defines
// (module/src/gl/pass_uniforms.hpp).

out vec4 o_color;

float sss_distance(uint word) { return uintBitsToFloat(word); }
// A texel's colour: with R8UI indices the blue word's low byte is the index (pass_inputs.frag).
vec3 sss_colour(uvec3 bits) {
#if SSS_PROFILE_IDS == 1
  bits.b &= 0xFFFFFF00u;
#endif
  return uintBitsToFloat(bits);
}

vec4 table(int entry, int row) { return texelFetch(u_tables, ivec2(entry, row), 0); }

// The weights the pass of table row `row` (its reach and delta: `footprint`) gives, at `step`
// pixels per profile mm, to the centre (returned) and to each pixel beside it (*beside; 0 where its
// first tap is farther out): footprint_taps.glsl's, as math::footprint_near_weights.
vec3 half_cdf_at(int row, float fraction) {  // fraction: of the row's reach
  float u = sqrt(min(fraction, 1.0)) * float(SSS_CDF_ENTRIES - 1);
  int j = min(int(u), SSS_CDF_ENTRIES - 2);
  float f = u - float(j);
  return table(j, row).rgb * (1.0 - f) + table(j + 1, row).rgb * f;
}
vec3 near_weights(int row, vec4 footprint, float step, out vec3 beside) {
  float reach = min(footprint.x * step, 1.0e6);
  bool dense = reach <= float(u_half_taps) + 0.5;
  int count = dense ? max(int(ceil(reach - 0.5)), 0) : u_half_taps;
  beside = vec3(0.0);
  // Only a pixel whose kernel fits in it has no taps, and the upsample never serves one (its reach
  // is at least u_min_reach pixels): the table's total is not read per pixel.
  if (count == 0) return 2.0 * table(SSS_CDF_ENTRIES - 1, row).rgb + footprint.yzw;
  float first = dense ? 1.0 : max(1.0, floor(reach * u_spacing.x + 0.5));
  float midpoint_scale = 0.5 / (footprint.x * step);  // as footprint_taps.glsl's
  vec3 below = half_cdf_at(row, first * midpoint_scale);
  if (first == 1.0) {
    float second = dense ? 2.0 : max(2.0, floor(reach * u_spacing.y + 0.5));
    vec3 upto = count > 1 ? half_cdf_at(row, (first + second) * midpoint_scale)
                          : table(SSS_CDF_ENTRIES - 1, row).rgb;
    beside = upto - below;
  }
  return 2.0 * below + footprint.yzw;
}

// The full-size pixel `pixel`'s neighbour `o` for the surface's tangent, as the passes take it
// (separable_blur.frag's sss_neighbour_distance: inside the drawn rectangle, a usable distance, the
// pixel's index where there are R8UI indices).
float neighbour_distance(ivec2 pixel, ivec2 o, uint index, out bool usable) {
  ivec2 texel = pixel + o;
  bool inside = all(greaterThanEqual(texel, u_rect.xy)) && all(lessThanEqual(texel, u_rect.zw));
  uvec4 t = texelFetch(u_source, inside ? texel : pixel, 0);
  float d = sss_distance(t.a);
  usable = inside && sss_usable_distance(d);
#if SSS_PROFILE_IDS == 1
  usable = usable && (t.b & 0xFFu) == index;
#endif
  return d;
}

vec3 tangent(ivec2 pixel, vec2 g, int axis, float d0, uint index) {
  ivec2 o = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
  bool um, up;
  float dm = neighbour_distance(pixel, -o, index, um);
  float dp = neighbour_distance(pixel, o, index, up);
  return sss_surface_tangent(g, axis, d0, dm, um, dp, up);
}

// One pixel of the near field: its colour as the full-size passes take it (blended towards the
// centre's by the follow-surface rule: its distance off the pixel's surface along `walk`'s line,
// less the ramp's slack for `steps` steps; the centre's where its index differs), times `w`.
struct NearSite {
  ivec2 pixel;
  uint index;     // the centre's R8UI index (the low byte of its blue colour word)
  vec3 colour;
  float distance;
  float factor;   // the follow-surface factor at the centre's strength
};
// `lowest` and `highest`: the range of the values the upsample combines, which bounds its result.
void near_tap(NearSite site, ivec2 offset, SssWalk walk, float steps, vec3 w, inout vec3 near, inout vec3 mass,
              inout vec3 lowest, inout vec3 highest) {
  ivec2 texel = clamp(site.pixel + offset, u_rect.xy, u_rect.zw);
  uvec4 q = texelFetch(u_source, texel, 0);
  vec2 line = sss_off_surface(sss_follow(walk, site.factor, site.distance), vec2(texel - site.pixel));
  float h = abs(sss_distance(q.a) * line.x + line.y);
  float s = max(h - steps * sss_follow_slack(walk, site.factor), 0.0);
  // Also an unusable texel (its distance NaN, so h is), tested on h: max() may drop a NaN, as may a
  // compiler that rewrites a select into max() (Mesa's NIR does). isnan() spelt out: NVIDIA's
  // compiler takes !(s < 1.0) for s >= 1.0, which NaN fails. So the inputs' unusable colours
  // (pass_inputs.frag) never enter.
  if (isnan(h) || !(s < 1.0)) s = 1.0;
#if SSS_PROFILE_IDS == 1
  if ((q.b & 0xFFu) != site.index) s = 1.0;
#endif
  vec3 taken = s < 1.0 ? sss_colour(q.rgb) * (1.0 - s) + site.colour * s : site.colour;
  near += w * taken;
  mass += w;
  lowest = min(lowest, taken);
  highest = max(highest, taken);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uvec4 texel = texelFetch(u_source, pixel, 0);
  vec4 centre = vec4(sss_colour(texel.rgb), uintBitsToFloat(texelFetch(u_strength, pixel, 0).r));
  // What the passes leave alone goes to them (and they leave it alone).
  if (!(centre.a > 0.0) || !sss_in_range(centre)) discard;
  float d = sss_distance(texel.a);
  float w = clip_w(d);
  if (isnan(w) || !(w > 0.0) || isinf(w)) discard;
  int profile = 0;
#if SSS_PROFILE_IDS == 1
  profile = int(texel.b & 15u);
  if (profile >= u_profile_count) discard;
#endif
  vec4 look = u_looks[profile];
  float a = min(centre.a, 1.0);
  // The full-size passes' walks at this pixel: along the row, and up the sheared column.
  vec2 g = sss_ray_slope(gl_FragCoord.xy);
  vec3 tx = tangent(pixel, g, 0, d, texel.b & 0xFFu);
  SssWalk across = sss_horizontal_walk(g, d, tx);
  SssWalk up = sss_vertical_walk(g, d, tx, tangent(pixel, g, 1, d, texel.b & 0xFFu));
  float step_x = look.x * a / w * across.ratio, step_y = look.y * a / w * up.ratio;
  vec4 footprint_x = table(SSS_CDF_ENTRIES, 2 * profile), footprint_y = table(SSS_CDF_ENTRIES, 2 * profile + 1);
  float reach_x = min(footprint_x.x * step_x, 1.0e6);
  float reach_y = min(footprint_y.x * step_y, 1.0e6);
  float reach = min(reach_x, reach_y);
  if (isnan(reach) || !(reach >= u_min_reach)) discard;  // narrow: the full-size passes

  float factor = look.z / a;
  vec4 plane = sss_follow(up, factor, d);  // the tangent plane's distance (the vertical walk's)
  ivec2 base = (pixel - 1) >> 1;  // the lower-left of the four nearest half-size texels
  vec2 f = vec2((pixel.x & 1) != 0 ? 0.25 : 0.75, (pixel.y & 1) != 0 ? 0.25 : 0.75);
  float weight = 0.0;
  vec3 blurred = vec3(0.0), reduced = vec3(0.0);
  vec3 lowest = vec3(3.4e38), highest = vec3(-3.4e38);  // nothing yet (finite: ES may not make infinities)
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      ivec2 q = clamp(base + ivec2(dx, dy), u_half_rect.xy, u_half_rect.zw);
      uvec4 h = texelFetch(u_half_source, q, 0);
      vec4 result = texelFetch(u_half_result, q, 0);
      if (isnan(result.a) || !(result.a > 0.0)) continue;  // not translucent (or left alone by the passes)
#if SSS_PROFILE_IDS == 1
      if ((h.b & 0xFFu) != (texel.b & 0xFFu)) continue;
#endif
      // Off the pixel's tangent plane, at the centre of the 2x2 block the texel stands for.
      vec2 line = sss_off_surface(plane, vec2(2 * q - pixel) + 0.5);
      float s = abs(sss_distance(h.a) * line.x + line.y);
      if (isnan(s) || !(s < 1.0)) s = 1.0;
      float wq = (dx == 0 ? 1.0 - f.x : f.x) * (dy == 0 ? 1.0 - f.y : f.y) * (1.0 - s);
      weight += wq;
      blurred += wq * result.rgb;
      reduced += wq * sss_colour(h.rgb);
      if (wq > 0.0) {
        lowest = min(lowest, result.rgb);
        highest = max(highest, result.rgb);
      }
    }
  }
  if (isnan(weight) || !(weight >= u_min_weight)) discard;  // no neighbour on this surface: the full-size passes
  // The near field at full size: the pixel and its four neighbours along the axes as the passes
  // take them (not the diagonals: module/src/math/half_resolution.hpp).
  vec3 beside_x, beside_y;
  vec3 centre_x = near_weights(2 * profile, footprint_x, step_x, beside_x);
  vec3 centre_y = near_weights(2 * profile + 1, footprint_y, step_y, beside_y);
  // In the CPU model's order (dy, then dx, from -1), written out: no loop for a SIMD rasteriser to
  // run with masked lanes.
  vec3 near = vec3(0.0), mass = vec3(0.0);
  NearSite site = NearSite(pixel, texel.b & 0xFFu, centre.rgb, d, factor);
  // The vertical pass's taps one row down and up read the column nearest its sheared line.
  int below_column = int(gl_FragCoord.x - up.shear) - pixel.x, above_column = int(gl_FragCoord.x + up.shear) - pixel.x;
  near_tap(site, ivec2(below_column, -1), up, 1.0, centre_x * beside_y, near, mass, lowest, highest);
  near_tap(site, ivec2(-1, 0), across, 1.0, beside_x * centre_y, near, mass, lowest, highest);
  near_tap(site, ivec2(0, 0), across, 0.0, centre_x * centre_y, near, mass, lowest, highest);
  near_tap(site, ivec2(1, 0), across, 1.0, beside_x * centre_y, near, mass, lowest, highest);
  near_tap(site, ivec2(above_column, 1), up, 1.0, centre_x * beside_y, near, mass, lowest, highest);
  // Not a convex sum (the near field minus its half-size stand-in): at a strong edge it could leave
  // the range of what it combined, which the result never should (it is a blur of those values).
  vec3 result = clamp(blurred / weight + near - mass * (reduced / weight), lowest, highest);
  result = sss_times_albedo_post(result, pixel, SSS_ALBEDO);  // SSS_ALBEDO 1 or 2 (one mode per frame here)
  o_color = sss_nearest_half(vec4(result, centre.a));
}
