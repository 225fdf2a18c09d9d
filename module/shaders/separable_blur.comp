// One pass of the separable filter as a compute shader (OpenGL 4.3+): the same arithmetic as
// separable_blur.frag, but a work group writes a tile of SSS_LINES rows (horizontal pass) or
// columns (vertical pass) of SSS_SEGMENT pixels, reads each texel of the tile and of an apron
// along the axis on both ends once into shared memory, and its taps (whole pixels) read them there
// instead of each pixel fetching its neighbours from the textures again.
//   - The apron a group fills is as wide as its widest kernel reaches (at most SSS_APRON): each
//     invocation first reads its own pixels and works out their reach from their depth and
//     strength, and the group's largest sets the span. Taps past the cached span (a footprint wider
//     than SSS_APRON, for a close-up at a large scale) read the textures, as the fragment shader
//     does, so any span gives the same image.
//   - A group none of whose pixels is blurred (no translucent pixel, as most of a frame with a
//     small subject) writes what the pass leaves there (SSS_OUTSIDE) and reads no apron and takes
//     no taps. (A rasteriser that runs both sides of every branch, as llvmpipe, saves nothing by
//     this; a GPU, whose work groups take such branches as a whole, does.)
//   - With SSS_LINES > 1 the vertical pass's tiles are that many columns wide and consecutive
//     invocations take neighbouring columns, so a row of the tile is read as neighbouring texels
//     (the module's tiles are one line: module/src/gl/shader_constants.hpp says why).
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp), as in
// separable_blur.frag: SSS_OUTSIDE (0 write the centre, 1 leave the pixel as it is, 2 copy
// u_original), SSS_FOLLOW_SURFACE, SSS_JITTER, SSS_ACCUMULATE (add u_accumulated, the earlier
// terms' sum, on unit 3), SSS_LINEAR_DEPTH, SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS; and
//   SSS_AXIS           0 horizontal, 1 vertical
//   SSS_MARKED         1: the pixel's strength (alpha) is read from the target image, where the
//                      runner marked it under the host's stencil (0 outside it: such pixels are
//                      left as the pass leaves a pixel that is not translucent); horizontal only
//   SSS_THREADS        the work group's invocations
//   SSS_SEGMENT, SSS_LINES  the tile: SSS_LINES lines of SSS_SEGMENT pixels along the axis
//   SSS_APRON          the most pixels cached on each end of a line
//   SSS_IMAGE_FORMAT   the target image's format qualifier (rgba16f, rgba32f, r11f_g11f_b10f)
//   SSS_ALBEDO         the last vertical pass: the sum times A_post (albedo.glsl; 1 or 2, no profiles)
// The header is version_430.glsl. The pieces it includes: nearest_half.glsl (u_round_to_half: set
// for an rgba16f image), depth.glsl, jitter.glsl and footprint_taps.glsl (the taps and their
// weights, shared with separable_blur.frag). The target is written with imageStore. Writing back
// into the host's colour (SSS_OUTSIDE 1), the alpha written is the intermediate's, which holds the
// host's own alpha exactly wherever the pass blurs (the horizontal pass copied it, in the colour's
// precision: RGBA16F into RGBA16F, RGBA32F into RGBA32F; under a host stencil the mark copied it),
// so the host's exact alpha stays without a read of the target (the fragment path masks alpha off
// instead); the marked pass reads each pixel of its target only before it writes it, and every
// other pass reads only textures it does not write.

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "jitter.glsl"
#include "pass_surface.glsl"
#include "albedo.glsl"

layout(local_size_x = SSS_THREADS, local_size_y = 1, local_size_z = 1) in;

layout(binding = 0) uniform sampler2D u_source;  // the pass input (host colour, then the intermediate)
layout(binding = 1) uniform sampler2D u_depth;   // the host's depth
#if SSS_OUTSIDE == 2
layout(binding = 2) uniform sampler2D u_original;  // the host's colour (the target is the separate output)
#endif
#if SSS_ACCUMULATE
layout(binding = 3) uniform sampler2D u_accumulated;  // the earlier terms' vertical sums (the module's own target)
#endif
#if SSS_MARKED
layout(binding = 0, SSS_IMAGE_FORMAT) uniform restrict image2D u_target;
#else
layout(binding = 0, SSS_IMAGE_FORMAT) uniform restrict writeonly image2D u_target;
#endif

// u_rect (the pixels this pass writes: x, y, width, height), u_pixels_per_mm, u_follow_surface,
// u_clamp (tap positions are kept inside: xy min, zw max, in pixels) and the pieces' numbers are
// the blur pass's uniform struct, declared with the variant's #defines (module/src/gl/pass_uniforms.hpp).

const ivec2 kAxis = ivec2(1 - SSS_AXIS, SSS_AXIS);
const ivec2 kAcross = ivec2(SSS_AXIS, 1 - SSS_AXIS);
const int kSpan = SSS_SEGMENT + 2 * SSS_APRON;               // cached texels of one line
const int kPixels = SSS_SEGMENT * SSS_LINES / SSS_THREADS;  // pixels of the tile per invocation
#if SSS_JITTER
const float kReachMargin = 1.5;  // the outermost jittered tap may read past the reach (jitter.glsl)
#else
const float kReachMargin = 1.0;
#endif

// rgb: colour; a: view distance (depth.glsl's view_distance of the host's depth: the taps' depth
// test and the surface's tangent read it). Both are worked out once per texel as it
// is cached rather than once per tap that reads it, as the fragment passes' inputs draw does, and
// as there a colour that is not usable (colour_range.glsl) is held as kSssUnusableColour at
// distance NaN (sss_cached): the taps then need no range test of their own (footprint_taps.glsl),
// which made the compute path 19% faster on an NVIDIA H200 (1080p close-up: 0.085 against 0.105 ms).
// One vec4 per texel: a tap's two texels are two 128-bit shared loads.
shared vec4 s_texel[SSS_LINES * kSpan];
// The group's widest reach in pixels plus one (at most SSS_APRON); 0: no pixel of it is blurred.
shared uint s_extent;

// Where texel i of a line (i = 0 at SSS_APRON pixels before the segment) is cached: the vertical
// pass interleaves its columns, so that invocations reading neighbouring columns at one tap use
// neighbouring words.
int cache_index(int line, int i) {
#if SSS_AXIS == 0
  return line * kSpan + i;
#else
  return i * SSS_LINES + line;
#endif
}

// The tile's pixel `e` (0 <= e < SSS_SEGMENT * SSS_LINES) as (line, position in the segment):
// consecutive e along the row of the image in both passes.
ivec2 tile_pixel(int e) {
#if SSS_AXIS == 0
  return ivec2(e / SSS_SEGMENT, e % SSS_SEGMENT);
#else
  return ivec2(e % SSS_LINES, e / SSS_LINES);
#endif
}

vec4 sss_cached(vec3 colour, float distance) {
  return sss_in_range(colour) ? vec4(colour, distance) : vec4(vec3(kSssUnusableColour), uintBitsToFloat(0x7FC00000u));
}

float tap_distance(ivec2 texel) { return view_distance(texelFetch(u_depth, texel, 0).r); }

// A texel as the cache would hold it, read from the textures.
vec4 sss_texel(ivec2 texel) { return sss_cached(texelFetch(u_source, texel, 0).rgb, tap_distance(texel)); }

// footprint_taps.glsl's tap reads: the work group's cache, or the textures past the cached span
// and, in the vertical pass, off the pixel's own column (its line is sheared: pass_surface.glsl).
struct TapSite {
  float centre;                // the pixel's centre along the axis
  float clamp_min, clamp_max;  // u_clamp along the axis
  int cache_start;             // the pixel coordinate of a line's texel 0
  int first, end;              // the cached texels of the line: [first, end)
  int line;                    // the pixel's line in the tile
  ivec2 row;                   // the texel coordinate across the axis (the other component 0)
  float across;                // the pixel's centre across the axis
  float shear;                 // the vertical pass's columns per row (0 in the horizontal pass)
};

vec4 sss_fetch_tap(TapSite site, float offset, out vec2 moved) {
  float position = clamp(site.centre + offset, site.clamp_min, site.clamp_max);
  int along_tap = int(position);
  int i = along_tap - site.cache_start;
  ivec2 row = site.row;
#if SSS_AXIS == 1
  int column = int(clamp(site.across + site.shear * offset, u_clamp.x, u_clamp.z));
  moved = vec2(float(column) + 0.5 - site.across, float(along_tap) + 0.5 - site.centre);
  if (column == row.x && i >= site.first && i < site.end) return s_texel[cache_index(site.line, i)];
  row.x = column;
#else
  moved = vec2(float(along_tap) + 0.5 - site.centre, 0.0);
  if (i >= site.first && i < site.end) return s_texel[cache_index(site.line, i)];
#endif
  return sss_texel(kAxis * along_tap + row);
}

// The view distance of the neighbour `step` (-1 or +1) pixels from `pixel` along `axis` and whether
// it may serve the surface's tangent (separable_blur.frag's sss_neighbour_distance): from the cache
// along the pass's axis, from the textures across it.
float sss_neighbour_distance(ivec2 pixel, int axis, int step, int line, int cache_i, out bool usable) {
  float along = float(pixel[axis]) + 0.5 + float(step);
  bool inside = along >= u_clamp[axis] && along <= u_clamp[2 + axis];
  float d;
  if (axis == SSS_AXIS) {
    d = s_texel[cache_index(line, inside ? cache_i + step : cache_i)].a;
  } else {
    ivec2 texel = pixel;
    texel[axis] += inside ? step : 0;
    d = sss_texel(texel).a;
  }
  usable = inside && sss_usable_distance(d);
  return d;
}

// The tangent along `axis` from the pixel's two neighbours on it.
vec3 sss_tangent(ivec2 pixel, vec2 g, int axis, float d0, int line, int cache_i) {
  bool um, up;
  float dm = sss_neighbour_distance(pixel, axis, -1, line, cache_i, um);
  float dp = sss_neighbour_distance(pixel, axis, 1, line, cache_i, up);
  return sss_surface_tangent(g, axis, d0, dm, um, dp, up);
}

// The pass's walk over the surface at `pixel` (separable_blur.frag's sss_walk), `cache_i` its texel
// in its line's cache.
SssWalk sss_walk(ivec2 pixel, float d0, int line, int cache_i) {
  vec2 g = sss_ray_slope(vec2(pixel) + 0.5);
  vec3 tx = sss_tangent(pixel, g, 0, d0, line, cache_i);
#if SSS_AXIS == 0
  return sss_horizontal_walk(g, d0, tx);
#else
  return sss_vertical_walk(g, d0, tx, sss_tangent(pixel, g, 1, d0, line, cache_i));
#endif
}

#include "footprint_taps.glsl"

void write_untouched(ivec2 pixel, vec4 centre) {
#if SSS_OUTSIDE == 0
  imageStore(u_target, pixel, centre);
#elif SSS_OUTSIDE == 2
  imageStore(u_target, pixel, texelFetch(u_original, pixel, 0));
#endif
}

void write_blurred(ivec2 pixel, vec3 sum, float alpha) {
#if SSS_ACCUMULATE
  sum += texelFetch(u_accumulated, pixel, 0).rgb;
#endif
  sum = sss_times_albedo_post(sum, pixel, SSS_ALBEDO);  // the last vertical pass's (SSS_ALBEDO 1 or 2)
#if SSS_OUTSIDE == 2
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a)));
#else
  // Written back (SSS_OUTSIDE 1), `alpha` is the host's own (the file's comment).
  imageStore(u_target, pixel, sss_nearest_half(vec4(sum, alpha)));
#endif
}

void main() {
  const int along_start = u_rect[SSS_AXIS];
  const int along_end = along_start + u_rect[2 + SSS_AXIS];  // exclusive
  const int across_end = u_rect[1 - SSS_AXIS] + u_rect[3 - SSS_AXIS];
  const int segment_start = along_start + int(gl_WorkGroupID.x) * SSS_SEGMENT;
  const int line_start = u_rect[1 - SSS_AXIS] + int(gl_WorkGroupID.y) * SSS_LINES;
  const int cache_start = segment_start - SSS_APRON;
  const int thread = int(gl_LocalInvocationIndex);
  if (thread == 0) s_extent = 0u;
  barrier();

  // This invocation's pixels: colour into the cache, and, where the pixel is blurred, its depth,
  // its step in pixels per profile mm and its reach (as separable_blur.frag's main()).
  float alpha[kPixels], distance[kPixels], step_pixels[kPixels];
  vec3 own[kPixels];  // the pixel's colour as it is (the cache holds it sanitised)
  bool blurred[kPixels];
  // (No `continue` in these loops: they unroll, and the arrays stay in registers.)
  uint reach_of_mine = 0u;  // the widest of this invocation's pixels (one shared atomic, not kPixels)
  for (int k = 0; k < kPixels; ++k) {
    ivec2 tile = tile_pixel(thread + k * SSS_THREADS);
    int along = segment_start + tile.y, across = line_start + tile.x;
    alpha[k] = 0.0;
    own[k] = vec3(0.0);
    distance[k] = 0.0;
    step_pixels[k] = 0.0;
    blurred[k] = false;
    if (along < along_end && across < across_end) {  // no tap reads outside the rectangle
      ivec2 pixel = kAxis * along + kAcross * across;
      vec4 colour = texelFetch(u_source, pixel, 0);
#if SSS_MARKED
      colour.a = imageLoad(u_target, pixel).a;
#endif
      alpha[k] = colour.a;
      float raw = texelFetch(u_depth, pixel, 0).r;
      float centre_distance = view_distance(raw);
      float w = clip_w(centre_distance);
      // Not translucent, not finite, or behind the camera: as separable_blur.frag (isnan(): see there).
      if (colour.a > 0.0 && sss_in_range(colour) && !(isnan(w) || !(w > 0.0) || isinf(w))) {
        distance[k] = centre_distance;
        // The step of a surface facing the camera: the walk (below, once the cache holds the
        // neighbours) multiplies it by its ratio, which is at most about 1, so the apron this sizes
        // holds the taps; a tap past it reads the textures.
        step_pixels[k] = u_pixels_per_mm * min(colour.a, 1.0) / w;
        blurred[k] = true;
        float reach = min(SSS_FOOTPRINT.x * step_pixels[k], 1.0e6) * kReachMargin;
        reach_of_mine = max(reach_of_mine, uint(min(ceil(reach) + 1.0, float(SSS_APRON))));
      }
      s_texel[cache_index(tile.x, SSS_APRON + tile.y)] = sss_cached(colour.rgb, centre_distance);
      own[k] = colour.rgb;
    }
  }
  if (reach_of_mine > 0u) atomicMax(s_extent, reach_of_mine);
  barrier();
  const int extent = int(s_extent);  // the same in every invocation: the branch below is uniform

  if (extent > 0) {
    // The apron, as far as it is reached.
    for (int e = thread; e < 2 * extent * SSS_LINES; e += SSS_THREADS) {
#if SSS_LINES == 1
      int line = 0, j = e;
#elif SSS_AXIS == 0
      int line = e / (2 * extent), j = e % (2 * extent);
#else
      int line = e % SSS_LINES, j = e / SSS_LINES;
#endif
      int i = j < extent ? SSS_APRON - extent + j : SSS_APRON + SSS_SEGMENT + (j - extent);
      int along = cache_start + i, across = line_start + line;
      if (along >= along_start && along < along_end && across < across_end) {
        s_texel[cache_index(line, i)] = sss_texel(kAxis * along + kAcross * across);
      }
    }
    barrier();
  }

  for (int k = 0; k < kPixels; ++k) {
    ivec2 tile = tile_pixel(thread + k * SSS_THREADS);
    int along = segment_start + tile.y, across = line_start + tile.x;
    if (along < along_end && across < across_end) {
      ivec2 pixel = kAxis * along + kAcross * across;
      vec4 centre = vec4(own[k], alpha[k]);
      if (blurred[k]) {
        float follow_surface = u_follow_surface / min(centre.a, 1.0);
        SssWalk walk = sss_walk(pixel, distance[k], tile.x, SSS_APRON + tile.y);
        TapSite site = TapSite(float(along) + 0.5, u_clamp[SSS_AXIS], u_clamp[2 + SSS_AXIS], cache_start,
                               SSS_APRON - extent, SSS_APRON + SSS_SEGMENT + extent, tile.x, kAcross * across,
                               float(across) + 0.5, walk.shear);
        vec3 sum = footprint_sum(site, centre.rgb, step_pixels[k] * walk.ratio, sss_follow(walk, follow_surface, distance[k]),
                                 sss_follow_slack(walk, follow_surface), pixel, SSS_AXIS);
        write_blurred(pixel, sum, centre.a);
      } else {
        write_untouched(pixel, centre);
      }
    }
  }
}
