// What one pass of the separable filter reads at its pixel, shared by the filter
// (separable_blur.frag) and its debug views (blur_debug_view.frag): the inputs pass_inputs.frag
// drew (colour and view distance in one RGBA32UI texel, the strength apart), the pass's line of taps
// (the horizontal pass along its row, the vertical one up its column sheared along the surface:
// pass_surface.glsl), the surface's walk from the neighbours' distances, and the centre.
// Switches: SSS_PACKED_OUTPUT (1: the horizontal pass), SSS_IMAGE_TAPS (the texels through image
// units 0 and 1 instead of samplers), SSS_PROFILE_IDS (per-pixel profiles: 1 the R8UI index in the
// blue word's low byte, 2 an R16UI index read per tap), and footprint_taps.glsl's.

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "jitter.glsl"
#include "pass_surface.glsl"
#include "albedo.glsl"

SSS_BINDING(0) uniform highp usampler2D u_source;   // colour and distance bits (pass_inputs.frag)
SSS_BINDING(1) uniform highp usampler2D u_strength;  // the colour's alpha bits (pass_inputs.frag)
#if SSS_IMAGE_TAPS
layout(binding = 0, rgba32ui) readonly uniform highp uimage2D u_source_taps;  // u_source's texture
layout(binding = 1, r32ui) readonly uniform highp uimage2D u_strength_image;  // u_strength's texture
#endif
// The pass's own numbers (u_pixels_per_mm, u_follow_surface, u_clamp, u_profile_count and the
// pieces' u_ndc_from_depth, u_depth_terms, u_pixel_span, u_ray_slope, u_round_to_half,
// u_noise_index) are the blur pass's uniform struct, declared with the variant's #defines
// (module/src/gl/pass_uniforms.hpp).

#if SSS_PROFILE_IDS
#if SSS_PROFILE_IDS == 2
SSS_BINDING(4) uniform highp usampler2D u_profile_ids;  // the host's R16UI: profile (bits 0-3), object
#endif
uniform vec4 u_profile[SSS_PROFILES];  // per profile: pixels per mm along the axis, follow-surface factor, 1/(2v)
uint sss_centre_id;                    // the centre pixel's whole index
bool sss_tap_foreign;                  // the last tap sss_fetch_tap read has another index
#endif

#if SSS_PACKED_OUTPUT
const int kSssAxis = 0;  // the horizontal pass is the one that writes the packed intermediate
#else
const int kSssAxis = 1;
#endif

// One texel of u_source's texture: through the image unit where the variant has it (u_source itself
// is then unused), else the sampler.
uvec4 sss_tap_texel(ivec2 texel) {
#if SSS_IMAGE_TAPS
  return imageLoad(u_source_taps, texel);
#else
  return texelFetch(u_source, texel, 0);
#endif
}

// The pixel's strength (pass_inputs.frag's copy of the colour's alpha): through image unit 1 where
// the taps are read through unit 0 (on llvmpipe a texelFetch from the R32UI texture is a call to a
// sampling function; the imageLoad is inlined: 2.3e7 instructions of the 1080p close-up's 1.3e9).
float sss_strength(ivec2 pixel) {
#if SSS_IMAGE_TAPS
  return uintBitsToFloat(imageLoad(u_strength_image, pixel).r);
#else
  return uintBitsToFloat(texelFetch(u_strength, pixel, 0).r);
#endif
}

// A texel's colour: with R8UI indices the blue word's low byte is the index (pass_inputs.frag).
vec3 sss_colour(uvec3 bits) {
#if SSS_PROFILE_IDS == 1
  bits.b &= 0xFFFFFF00u;
#endif
  return uintBitsToFloat(bits);
}
// A texel's view distance.
float sss_distance(uint word) { return uintBitsToFloat(word); }
// A texel's profile and object index.
uint sss_index(uvec4 t, ivec2 texel) {
#if SSS_PROFILE_IDS == 2
  return texelFetch(u_profile_ids, texel, 0).r;
#else
  return t.b & 0xFFu;
#endif
}

// footprint_taps.glsl's tap reads: straight from the textures, along the axis from the fragment.
// u_clamp is read once per pixel, into the site, and only its bounds along the axis reach the taps:
// llvmpipe loaded all four of its components again for every tap (a per-lane load each, since the
// loop's texel fetches may write memory as far as LLVM knows), a tenth of the tap loop's work.
// The vertical pass steps along its sheared line (pass_surface.glsl): the column of tap `offset`
// is floor(x + shear · offset), x the centre's window position, kept in u_clamp.
struct TapSite {
  float along;                 // gl_FragCoord along the axis
  float clamp_min, clamp_max;  // u_clamp along the axis
#if SSS_PACKED_OUTPUT
  int across;                  // the taps' row (the centre's, clamped)
#else
  float across;                // the centre's window x
  float shear;                 // columns per row
  float across_min, across_max;  // u_clamp across the axis
#endif
};

TapSite sss_tap_site(float shear) {
  vec4 box = u_clamp;
#if SSS_PACKED_OUTPUT
  return TapSite(gl_FragCoord.x, box.x, box.z, int(clamp(gl_FragCoord.y, box.y, box.w)));
#else
  return TapSite(gl_FragCoord.y, box.y, box.w, gl_FragCoord.x, shear, box.x, box.z);
#endif
}

vec4 sss_fetch_tap(TapSite site, float offset, out vec2 moved) {
  int along = int(clamp(site.along + offset, site.clamp_min, site.clamp_max));
#if SSS_PACKED_OUTPUT
  ivec2 texel = ivec2(along, site.across);
#else
  ivec2 texel = ivec2(int(clamp(site.across + site.shear * offset, site.across_min, site.across_max)), along);
#endif
  moved = vec2(texel) + 0.5 - gl_FragCoord.xy;
  uvec4 t = sss_tap_texel(texel);
#if SSS_PROFILE_IDS
  sss_tap_foreign = sss_index(t, texel) != sss_centre_id;
#endif
  return vec4(sss_colour(t.rgb), sss_distance(t.a));
}

#include "footprint_taps.glsl"

// The view distance of the neighbour `step` (-1 or +1) pixels from `pixel` along `axis`, and whether
// it may serve the surface's tangent (inside u_clamp, a finite distance in front of the camera, and
// with per-pixel profiles the centre's profile and object: another object is another surface). A
// neighbour outside u_clamp reads the pixel itself (a texel inside the texture) and does not serve.
float sss_neighbour_distance(ivec2 pixel, int axis, float step, out bool usable) {
  float along = gl_FragCoord[axis] + step;
  bool inside = along >= u_clamp[axis] && along <= u_clamp[2 + axis];
  ivec2 texel = pixel;
  texel[axis] = int(inside ? along : gl_FragCoord[axis]);
  uvec4 t = sss_tap_texel(texel);
  float d = sss_distance(t.a);
  usable = inside && sss_usable_distance(d);
#if SSS_PROFILE_IDS
  usable = usable && sss_index(t, texel) == sss_centre_id;
#endif
  return d;
}

// The tangent along `axis` from this pixel's two neighbours on it.
vec3 sss_tangent(ivec2 pixel, vec2 g, int axis, float d0) {
  bool um, up;
  float dm = sss_neighbour_distance(pixel, axis, -1.0, um);
  float dp = sss_neighbour_distance(pixel, axis, 1.0, up);
  return sss_surface_tangent(g, axis, d0, dm, um, dp, up);
}

// The pass's walk over the surface at this pixel (pass_surface.glsl): the horizontal pass needs T_x,
// the vertical one T_x and T_y.
SssWalk sss_walk(ivec2 pixel, float d0) {
  vec2 g = sss_ray_slope(gl_FragCoord.xy);
  vec3 tx = sss_tangent(pixel, g, 0, d0);
#if SSS_PACKED_OUTPUT
  return sss_horizontal_walk(g, d0, tx);
#else
  return sss_vertical_walk(g, d0, tx, sss_tangent(pixel, g, 1, d0));
#endif
}

// What the pass knows of its pixel before the taps.
struct SssCentre {
  uvec4 texel;           // its own input texel
  vec4 colour;           // rgb, and a: the strength as the host gave it
  float strength;        // the strength, at most 1
  float distance;        // the view distance
  float w;               // its clip w
  float pixels_per_mm;   // of its profile, along the axis
  float follow_surface;  // of its profile, over the strength (the reach scales with alpha like the taps)
};

// False where the pass leaves the pixel as it is (c.texel is read all the same): not translucent,
// a non-finite colour or strength (or one past colour_range.glsl's bound), behind the camera, on an
// infinite far plane or NaN, or an index without a profile (documented as left alone). With
// per-pixel profiles it picks the centre's table (sss_table_base, sss_inv_two_variance).
bool sss_read_centre(ivec2 pixel, out SssCentre c) {
  c.texel = sss_tap_texel(pixel);
  c.colour = vec4(sss_colour(c.texel.rgb), sss_strength(pixel));
  if (!(c.colour.a > 0.0) || !sss_in_range(c.colour)) return false;
  c.strength = min(c.colour.a, 1.0);  // alpha is documented as 0..1; more must not widen the kernel
  c.distance = sss_distance(c.texel.a);
  c.w = clip_w(c.distance);
  // isnan() and not only !(w > 0.0): on NVIDIA's driver (580) the negated comparison behaved as
  // the opposite one, which a NaN passes.
  if (isnan(c.w) || !(c.w > 0.0) || isinf(c.w)) return false;
#if SSS_PROFILE_IDS
  sss_centre_id = sss_index(c.texel, pixel);
  int profile = int(sss_centre_id & 15u);
  if (profile >= u_profile_count) return false;
  sss_table_base = profile * (SSS_CDF_ENTRIES + 1);
  vec4 look = u_profile[profile];
  sss_inv_two_variance = look.z;
  c.pixels_per_mm = look.x;
  c.follow_surface = look.y / c.strength;
#else
  c.pixels_per_mm = u_pixels_per_mm;
  c.follow_surface = u_follow_surface / c.strength;
#endif
  return true;
}

// The centre's texturing mode for albedo.glsl (SSS_ALBEDO 3: its profile's, in u_profile's w).
int sss_centre_texturing() {
#if SSS_ALBEDO == 3
  return int(u_profile[int(sss_centre_id & 15u)].w);
#else
  return SSS_ALBEDO;
#endif
}

// This pass's step in pixels per profile mm at the pixel, on its walk over the surface.
float sss_step_pixels(SssCentre c, SssWalk walk) { return c.pixels_per_mm * c.strength / c.w * walk.ratio; }
