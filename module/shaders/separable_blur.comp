// One pass of the separable filter as a compute shader (OpenGL 4.3+): the same arithmetic as
// separable_blur.frag, but a work group first reads its row (or column) segment and an apron on
// both sides into shared memory, once per texel, and the taps (whole pixels) then read it there
// instead of each pixel fetching its neighbours from the textures again. Taps that fall outside the cached
// span (a kernel wider than the apron, for a close-up at a large scale) read the textures, as the
// fragment shader does, so any footprint gives the same image.
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp), as in
// separable_blur.frag: SSS_OUTSIDE (0 write the centre, 1 leave the pixel as it is, 2 copy
// u_original), SSS_FOLLOW_SURFACE, SSS_JITTER, SSS_LINEAR_DEPTH, SSS_CDF_ENTRIES,
// SSS_MAX_HALF_TAPS (SSS_ACCUMULATE is always 0: the path runs single-term kernels); and
//   SSS_SEGMENT        pixels one work group writes along the pass's axis (its local size)
//   SSS_APRON          pixels cached on each side of the segment
//   SSS_IMAGE_FORMAT   the target image's format qualifier (rgba16f or rgba32f)
// The header is version_430.glsl. The pieces it includes: nearest_half.glsl (u_round_to_half: set
// for an rgba16f image), depth.glsl, jitter.glsl and footprint_taps.glsl (the taps and their
// weights, shared with separable_blur.frag). The target is written with imageStore. Writing back
// into the host's colour (SSS_OUTSIDE 1), the pixel's alpha is read from the target itself, so the
// host's exact alpha stays (the fragment path masks alpha off instead); every other pass reads only
// textures it does not write.

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "jitter.glsl"

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

uniform ivec2 u_axis;           // (1, 0) or (0, 1)
uniform ivec4 u_rect;           // the pixels this pass writes: x, y, width, height
uniform float u_pixels_per_mm;
uniform float u_follow_surface;
uniform vec4 u_clamp;           // tap positions are kept inside (xy min, zw max), in pixels

const int kCached = SSS_SEGMENT + 2 * SSS_APRON;
// rgb: colour; a: raw depth (the pixel's own, as the fragment shader fetches it). One vec4 per
// texel: a tap's two texels are two 128-bit shared loads (a vec3 and a float apart were four).
shared vec4 s_texel[kCached];

// footprint_taps.glsl's tap reads: the work group's cache, or the textures past the apron.
struct TapSite {
  float centre;                // the pixel's centre along the axis
  float clamp_min, clamp_max;  // u_clamp along the axis
  int cache_start;             // the pixel coordinate of s_texel[0]
  ivec2 row;                   // the texel coordinate across the axis (the other component 0)
};

vec4 sss_fetch_tap(TapSite site, float offset) {
  // Whole pixels: the cached texel, or the textures' where the tap is past the apron.
  float position = clamp(site.centre + offset, site.clamp_min, site.clamp_max);
  int along_tap = int(position);
  int index = along_tap - site.cache_start;
  if (index >= 0 && index < kCached) return s_texel[index];
  ivec2 texel = u_axis * along_tap + site.row;
  return vec4(texelFetch(u_source, texel, 0).rgb, texelFetch(u_depth, texel, 0).r);
}

#define SSS_TAP_DISTANCE(a) view_distance(a)  // the cache holds the host's raw depth
#define SSS_TAPS_SANITISED 0                   // and the host's colour as it is
#include "footprint_taps.glsl"

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
  if (!(centre.a > 0.0) || !sss_in_range(centre)) {
    write_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);
  float centre_distance = view_distance(s_texel[centre_index].a);
  float w = clip_w(centre_distance);
  if (isnan(w) || !(w > 0.0) || isinf(w)) {  // isnan(): see separable_blur.frag
    write_untouched(pixel, centre);
    return;
  }
  float step_pixels = u_pixels_per_mm * strength / w;
  float follow_surface = u_follow_surface / strength;
  TapSite site = TapSite(float(along) + 0.5, u_clamp[axis_index], u_clamp[2 + axis_index], cache_start,
                         cross_axis * across);
  vec3 sum = footprint_sum(site, centre.rgb, step_pixels, centre_distance, follow_surface, pixel, axis_index);
#if SSS_OUTSIDE == 2
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a)));
#elif SSS_OUTSIDE == 1
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, imageLoad(u_target, pixel).a)));
#else
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, centre.a)));
#endif
}
