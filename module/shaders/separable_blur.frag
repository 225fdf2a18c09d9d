// One pass of the separable subsurface-scattering filter (Jimenez et al. 2012, §3): the 1D kernel
// along the pass's axis (horizontal: the SSS_PACKED_OUTPUT pass; vertical: the other), its
// footprint scaled per pixel by depth and by the strength, taps blended back to the centre colour
// as their depth leaves the kernel's reach (follow-surface). A kernel of several
// separable terms (sum of Gaussians, SVD rank N) runs this pair of passes once per term; the
// vertical pass of a later term adds the earlier terms' sum (SSS_ACCUMULATE).
//
// Inputs (pass_inputs.frag draws them first): u_source holds per pixel the colour's float bits
// (rgb) and its view distance's (a) in one RGBA32UI texel: the module's copy of the host's colour
// for the horizontal pass, the horizontal pass's result for the vertical one. So a tap is one fetch,
// and no depth is linearised per tap. The strength (the colour's alpha) is read at the centre only.
// Each pass walks the surface by its own pixel's footprint along its line (pass_surface.glsl): the
// horizontal pass along the row, the vertical one up the column sheared so that its steps are
// perpendicular to the row's on the surface; the neighbours' distances give the tangents.
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp):
//   SSS_OUTSIDE   what a pixel that is not blurred writes: 0 its own value (horizontal pass, which
//                 fills the intermediate everywhere), 1 nothing (discard: vertical pass writing back
//                 into the host's colour), 2 the host's original colour (vertical pass into a
//                 separate output texture)
//   SSS_PACKED_OUTPUT  1: the horizontal pass: writes RGBA32UI like its input (the blurred colour's
//                      bits, rounded to half where u_round_to_half says, and the centre's distance
//                      word unchanged); 0: a vertical pass, which writes colour
//   SSS_FOLLOW_SURFACE  0 off; 1 the linear ramp to the kernel's reach; 2 the exact depth correction
//                       of a Gaussian term (supplementary §E): blend by 1 - exp(-dz² / 2v), dz in
//                       profile millimetres
//   SSS_JITTER          1: where the taps are spread out, those from u_jitter_from on read a pixel
//                       of their cell chosen by per-pixel integer-hash noise (supplementary Fig.
//                       S.6-S.7); their weights stay the cells'
//   SSS_ACCUMULATE      1: add the earlier terms' sum (u_accumulated, unit 3) to the result
//   SSS_LINEAR_DEPTH    unused here (pass_inputs.frag linearises); the compute variant reads it
//   SSS_CDF_ENTRIES, SSS_MAX_HALF_TAPS  the sizes of u_cdf and u_spacing
//   SSS_IMAGE_TAPS      1: the taps and the centre read u_source's texture through image unit 0
//                       (imageLoad), where the context has image units (desktop GL 4.3+, GLSL
//                       4.20): on llvmpipe a texelFetch calls a sampling function that works out a
//                       mip level per lane, and the tap loop spills its registers around each call
//                       (the 1080p close-up took 13 % longer); the strength likewise through unit 1
//   SSS_PROFILE_IDS     per-pixel profiles (sss_frame.profile_texture): 0 none; 1 an R8UI index,
//                       which pass_inputs.frag put in the low byte of the blue colour word (the
//                       horizontal pass carries it on); 2 an R16UI one, read per tap from the
//                       host's texture (unit 4). The centre's index
//                       (value & 15) picks its profile's table (a uniform block of SSS_PROFILES)
//                       and u_profile[] entry; an index >= u_profile_count leaves the pixel alone;
//                       taps whose whole value (profile and object) differs count as the centre
//   SSS_DEBUG_VIEW      0: the filter; else an sss_debug_view (sss.h) instead of the blurred colour:
//                       the horizontal pass writes its own footprint (1 / its step: profile mm per
//                       pixel) and tap count into the texel's r and g (b and a, the R8UI index and the
//                       distance the vertical walk reads, kept); the vertical pass writes the view,
//                       (0, 0, 0, 1) for a pixel it leaves alone, and with u_debug_fill set (drawn
//                       over the pixels the culling keeps from the passes) (0, 0, 0, 1) everywhere
// and from the dialect's header (version_*.glsl, module/src/gl/glsl_variant.cpp):
//   SSS_BINDING(unit)        layout(binding = unit) where the dialect has it, else nothing (the
//                            module sets the unit with glUniform1i)
// The pieces it includes (the module expands #include, module/src/gl/shader_source.cpp):
// nearest_half.glsl (sss_nearest_half: the written colour rounded to half float where the target is
// one, u_round_to_half), depth.glsl (clip_w), jitter.glsl and footprint_taps.glsl
// (the taps and their weights: footprint_sum, shared with separable_blur.comp).

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "jitter.glsl"
#include "pass_surface.glsl"

SSS_BINDING(0) uniform highp usampler2D u_source;   // colour and distance bits (pass_inputs.frag)
SSS_BINDING(1) uniform highp usampler2D u_strength;  // the colour's alpha bits (pass_inputs.frag)
#if SSS_IMAGE_TAPS
layout(binding = 0, rgba32ui) readonly uniform highp uimage2D u_source_taps;  // u_source's texture
layout(binding = 1, r32ui) readonly uniform highp uimage2D u_strength_image;  // u_strength's texture
#endif
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
#if SSS_ACCUMULATE
SSS_BINDING(3) uniform sampler2D u_accumulated;  // the earlier terms' vertical sums (the module's own target)
#endif
uniform float u_pixels_per_mm;        // along the axis, at clip w = 1 and strength 1
uniform float u_follow_surface;       // 1 / the kernel's reach in world units (SSS_FOLLOW_SURFACE 2: 1 / world units per mm)
uniform vec4 u_clamp;                 // tap positions are kept inside (xy min, zw max), in pixels
#if SSS_DEBUG_VIEW && !SSS_PACKED_OUTPUT
uniform int u_debug_fill;             // 1: every pixel drawn gets (0, 0, 0, 1) (see SSS_DEBUG_VIEW)
#endif

#if SSS_PROFILE_IDS
#if SSS_PROFILE_IDS == 2
SSS_BINDING(4) uniform highp usampler2D u_profile_ids;  // the host's R16UI: profile (bits 0-3), object
#endif
uniform vec4 u_profile[SSS_PROFILES];  // per profile: pixels per mm along the axis, follow-surface factor, 1/(2v)
uniform int u_profile_count;           // the profiles set (sss_set_profiles)
uint sss_centre_id;                    // the centre pixel's whole index
bool sss_tap_foreign;                  // the last tap sss_fetch_tap read has another index
#endif

#if SSS_PACKED_OUTPUT
out uvec4 o_packed;
const int kSssAxis = 0;  // the horizontal pass is the one that writes the packed intermediate
#else
out vec4 o_color;
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

// `texel`: the pixel's own input texel.
void leave_untouched(ivec2 pixel, uvec4 texel) {
#if SSS_DEBUG_VIEW && !SSS_PACKED_OUTPUT
  o_color = vec4(0.0, 0.0, 0.0, 1.0);  // a view: a pixel the passes leave alone
#elif SSS_OUTSIDE == 0 && SSS_PACKED_OUTPUT
  o_packed = texel;
#elif SSS_OUTSIDE == 0
  o_color = vec4(sss_colour(texel.rgb), 0.0);
#elif SSS_OUTSIDE == 1
  discard;
#else
  o_color = texelFetch(u_original, pixel, 0);
#endif
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#if SSS_DEBUG_VIEW && !SSS_PACKED_OUTPUT
  if (u_debug_fill != 0) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
#endif
  uvec4 texel = sss_tap_texel(pixel);
  vec4 centre = vec4(sss_colour(texel.rgb), sss_strength(pixel));
  // Not translucent, or a non-finite colour or strength (or past colour_range.glsl's bound): the
  // pixel keeps its own value.
  if (!(centre.a > 0.0) || !sss_in_range(centre)) {
    leave_untouched(pixel, texel);
    return;
  }
  float strength = min(centre.a, 1.0);  // alpha is documented as 0..1; more must not widen the kernel
  float centre_distance = sss_distance(texel.a);
  float w = clip_w(centre_distance);
  // Behind the camera, on an infinite far plane, or NaN. isnan() and not only !(w > 0.0): on
  // NVIDIA's driver (580) the negated comparison behaved as the opposite one, which a NaN passes.
  if (isnan(w) || !(w > 0.0) || isinf(w)) {
    leave_untouched(pixel, texel);
    return;
  }

#if SSS_PROFILE_IDS
  sss_centre_id = sss_index(texel, pixel);
  int profile = int(sss_centre_id & 15u);
  if (profile >= u_profile_count) {  // no profile set for this index: documented as left alone
    leave_untouched(pixel, texel);
    return;
  }
  sss_table_base = profile * (SSS_CDF_ENTRIES + 1);
  vec4 look = u_profile[profile];
  sss_inv_two_variance = look.z;
  float pixels_per_mm = look.x;
  float follow_surface = look.y / strength;
#else
  float pixels_per_mm = u_pixels_per_mm;
  float follow_surface = u_follow_surface / strength;  // the reach scales with alpha like the taps
#endif
  SssWalk walk = sss_walk(pixel, centre_distance);
  float step_pixels = pixels_per_mm * strength / w * walk.ratio;
#if SSS_DEBUG_VIEW
  // This pass's footprint and taps (footprint_taps.glsl's count), as the filter would run them.
  float footprint = 1.0 / step_pixels;
  float taps = float(1 + 2 * sss_tap_count(sss_reach_pixels(step_pixels)));
#if SSS_PACKED_OUTPUT
  o_packed = uvec4(floatBitsToUint(footprint), floatBitsToUint(taps), texel.b, texel.a);
#else
  // The horizontal pass's numbers for this pixel are in its texel's r and g.
  vec2 across = vec2(uintBitsToFloat(texel.r), uintBitsToFloat(texel.g));
#if SSS_DEBUG_VIEW == 1
  vec3 view = vec3(1.0);
#elif SSS_DEBUG_VIEW == 2
  vec3 view = vec3(centre_distance);
#elif SSS_DEBUG_VIEW == 3
  vec3 view = vec3(across.x, footprint, 0.0);
#elif SSS_DEBUG_VIEW == 4
  vec3 view = vec3(across.y, taps, 0.0);
#elif SSS_PROFILE_IDS
  vec3 view = vec3(float(sss_centre_id & 15u), float(sss_centre_id >> 4u), 1.0);
#else
  vec3 view = vec3(0.0, 0.0, 1.0);  // b 1: profile 0 and object 0 told apart from a pixel left alone
#endif
  o_color = sss_nearest_half(vec4(view, 1.0));
#endif
  return;
#endif
  vec3 sum = footprint_sum(sss_tap_site(walk.shear), centre.rgb, step_pixels, sss_follow(walk, follow_surface, centre_distance),
                           sss_follow_slack(walk, follow_surface), pixel, kSssAxis);
#if SSS_ACCUMULATE
  sum += texelFetch(u_accumulated, pixel, 0).rgb;
#endif
#if SSS_PACKED_OUTPUT
  uvec3 bits = floatBitsToUint(sss_nearest_half(vec4(sum, 0.0)).rgb);
#if SSS_PROFILE_IDS == 1
  bits.b = (bits.b & 0xFFFFFF00u) | (texel.b & 0xFFu);  // the index rides on for the vertical taps
#endif
  o_packed = uvec4(bits, texel.a);
#elif SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(sum, centre.a));
#endif
}
