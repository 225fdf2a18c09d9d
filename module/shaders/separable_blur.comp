// One pass of the separable filter as a compute shader (OpenGL 4.3+): the same arithmetic as
// separable_blur.frag, but a work group first reads its row (or column) segment and an apron on
// both sides into shared memory, once per texel, and the taps (whole pixels) then read it there
// instead of each pixel fetching its neighbours from the textures again. Taps that fall outside the cached
// span (a kernel wider than the apron, for a close-up at a large scale) read the textures, as the
// fragment shader does, so any footprint gives the same image.
//
// Compile-time switches, as in separable_blur.frag: SSS_OUTSIDE (0 write the centre, 1 leave the
// pixel as it is, 2 copy u_original), SSS_FOLLOW_SURFACE, SSS_JITTER, SSS_LINEAR_DEPTH,
// SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS; and
//   SSS_SEGMENT        pixels one work group writes along the pass's axis (its local size)
//   SSS_APRON          pixels cached on each side of the segment
//   SSS_IMAGE_FORMAT   the target image's format qualifier (rgba16f or rgba32f)
// nearest_half.glsl comes first (u_round_to_half: set for an rgba16f image). The target is written
// with imageStore. Writing back into the host's colour (SSS_OUTSIDE 1), the
// pixel's alpha is read from the target itself, so the host's exact alpha stays (the fragment
// path masks alpha off instead); every other pass reads only textures it does not write.

layout(local_size_x = SSS_SEGMENT, local_size_y = 1, local_size_z = 1) in;

layout(binding = 0) uniform sampler2D u_source;  // the pass input (host colour, then the intermediate)
layout(binding = 1) uniform sampler2D u_depth;   // the host's depth
#if SSS_OUTSIDE == 2
layout(binding = 2) uniform sampler2D u_original;  // the host's colour (the target is the separate output)
#endif
#if SSS_OUTSIDE == 1
layout(binding = 0, SSS_IMAGE_FORMAT) uniform restrict image2D u_target;
#else
layout(binding = 0, SSS_IMAGE_FORMAT) uniform restrict writeonly image2D u_target;
#endif

uniform vec4 u_cdf[SSS_CDF_ENTRIES];
uniform vec4 u_footprint;
uniform float u_spacing[SSS_MAX_HALF_TAPS];
uniform int u_half_taps;
#if SSS_JITTER
uniform int u_jitter_from;
#endif
#if SSS_FOLLOW_SURFACE == 2
uniform float u_inv_two_variance;
#endif
uniform ivec2 u_axis;           // (1, 0) or (0, 1)
uniform ivec4 u_rect;           // the pixels this pass writes: x, y, width, height
uniform float u_pixels_per_mm;
uniform float u_follow_surface;
uniform vec2 u_ndc_from_depth;
uniform vec4 u_depth_terms;
uniform vec4 u_clamp;           // tap positions are kept inside (xy min, zw max), in pixels

const int kCached = SSS_SEGMENT + 2 * SSS_APRON;
// rgb: colour; a: raw depth (the pixel's own, as the fragment shader fetches it). One vec4 per
// texel: a tap's two texels are two 128-bit shared loads (a vec3 and a float apart were four).
shared vec4 s_texel[kCached];

float view_distance(float raw_depth) {
#if SSS_LINEAR_DEPTH
  return raw_depth;
#else
  float zn = raw_depth * u_ndc_from_depth.x + u_ndc_from_depth.y;
  return (zn * u_depth_terms.w - u_depth_terms.z) / (zn * u_depth_terms.y - u_depth_terms.x);
#endif
}

#if SSS_JITTER
// Must equal sss::math::jitter_noise bit for bit (and separable_blur.frag's).
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

// As in separable_blur.frag (and sss::math::footprint_half_cdf, footprint_taps).
vec3 half_cdf(float x_mm) {
  float u = sqrt(min(x_mm / u_footprint.x, 1.0)) * float(SSS_CDF_ENTRIES - 1);
  int j = min(int(u), SSS_CDF_ENTRIES - 2);
  float f = u - float(j);
  return u_cdf[j].rgb * (1.0 - f) + u_cdf[j + 1].rgb * f;
}

float tap_position(int i, float previous, bool dense, float reach_pixels) {
  return dense ? float(i) : max(previous + 1.0, floor(reach_pixels * u_spacing[i - 1] + 0.5));
}

#if SSS_JITTER
float jittered_position(float inner, float p, float outer, bool outermost, float noise) {
  float lo = floor(0.5 * (inner + p)) + 1.0;
  float hi = outermost ? p + (p - lo) : floor(0.5 * (p + outer));
  return lo + min(floor(noise * (hi - lo + 1.0)), hi - lo);
}
#endif

void write_untouched(ivec2 pixel, vec4 centre) {
#if SSS_OUTSIDE == 0
  imageStore(u_target, pixel, centre);
#elif SSS_OUTSIDE == 2
  imageStore(u_target, pixel, texelFetch(u_original, pixel, 0));
#endif
}

void main() {
  const int axis_index = u_axis.y;  // 0 horizontal, 1 vertical
  const int along_start = u_rect[axis_index];
  const int along_end = along_start + u_rect[2 + axis_index];  // exclusive
  const int across = u_rect[1 - axis_index] + int(gl_WorkGroupID.y);
  const int segment_start = along_start + int(gl_WorkGroupID.x) * SSS_SEGMENT;
  const int cache_start = segment_start - SSS_APRON;  // pixel coordinate of s_texel[0]
  const ivec2 cross_axis = ivec2(1) - u_axis;

  // Fill the cache: every texel of segment and apron once, clamped into the rectangle (no tap
  // reads past it: positions are clamped to u_clamp first).
  for (int i = int(gl_LocalInvocationID.x); i < kCached; i += SSS_SEGMENT) {
    int along = clamp(cache_start + i, along_start, along_end - 1);
    ivec2 texel = u_axis * along + cross_axis * across;
    s_texel[i] = vec4(texelFetch(u_source, texel, 0).rgb, texelFetch(u_depth, texel, 0).r);
  }
  barrier();

  const int along = segment_start + int(gl_LocalInvocationID.x);
  if (along >= along_end) return;
  const ivec2 pixel = u_axis * along + cross_axis * across;
  const int centre_index = along - cache_start;
  vec4 centre = vec4(s_texel[centre_index].rgb, texelFetch(u_source, pixel, 0).a);
  if (!(centre.a > 0.0) || any(isnan(centre)) || any(isinf(centre))) {
    write_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);
  float centre_distance = view_distance(s_texel[centre_index].a);
  float w = -u_depth_terms.y * centre_distance + u_depth_terms.w;
  if (isnan(w) || !(w > 0.0) || isinf(w)) {  // isnan(): see separable_blur.frag
    write_untouched(pixel, centre);
    return;
  }
  float step_pixels = u_pixels_per_mm * strength / w;
  float follow_surface = u_follow_surface / strength;
  const float centre_coord = float(along) + 0.5;
  const float clamp_min = u_clamp[axis_index], clamp_max = u_clamp[2 + axis_index];
  float reach_pixels = min(u_footprint.x * step_pixels, 1.0e6);
  bool dense = reach_pixels <= float(u_half_taps) + 0.5;
  int count = dense ? max(int(ceil(reach_pixels - 0.5)), 0) : u_half_taps;
#if SSS_JITTER
  int jitter_from = dense ? count + 1 : u_jitter_from;
  float noise = jitter_noise(pixel, axis_index);
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
      // Whole pixels: the cached texel, or the textures' where the tap is past the apron.
      float position = clamp(centre_coord + (side == 0 ? read : -read), clamp_min, clamp_max);
      int along_tap = int(position);
      int index = along_tap - cache_start;
      vec3 tap;
      float tap_depth;
      if (index >= 0 && index < kCached) {
        tap = s_texel[index].rgb;
        tap_depth = s_texel[index].a;
      } else {
        ivec2 texel = u_axis * along_tap + cross_axis * across;
        tap = texelFetch(u_source, texel, 0).rgb;
        tap_depth = texelFetch(u_depth, texel, 0).r;
      }
      if (any(isnan(tap)) || any(isinf(tap))) tap = centre.rgb;
#if SSS_FOLLOW_SURFACE
      float d = follow_surface * abs(centre_distance - view_distance(tap_depth));
#if SSS_FOLLOW_SURFACE == 2
      float s = 1.0 - exp(-d * d * u_inv_two_variance);
#else
      float s = d;
#endif
      if (isnan(s) || !(s < 1.0)) s = 1.0;
      tap = mix(tap, centre.rgb, s);
#endif
      pair += tap;
    }
    sum += (upto - below) * pair;
    below = upto;
    p = next;
  }
#if SSS_OUTSIDE == 2
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a)));
#elif SSS_OUTSIDE == 1
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, imageLoad(u_target, pixel).a)));
#else
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, centre.a)));
#endif
}
