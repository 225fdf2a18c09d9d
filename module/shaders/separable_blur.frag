// One pass of the separable subsurface-scattering filter (Jimenez et al. 2012, §3): the 1D kernel
// along `u_axis`, its footprint scaled per pixel by depth and by the strength in alpha, taps blended
// back to the centre colour as their depth leaves the kernel's reach (follow-surface). A kernel of
// several separable terms (sum of Gaussians, SVD rank N) runs this pair of passes once per term; the
// vertical pass of a later term adds the earlier terms' sum (SSS_ACCUMULATE).
//
// Compile-time switches (the variant's #defines, module/src/gl/shader_variants.cpp):
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
//   SSS_PROFILE_IDS     1: per-pixel profiles (sss_frame.profile_texture): depth and index come from
//                       the module's RG32UI copy (profile_depth.frag, unit 4) in one fetch, the
//                       depth as a view distance already (SSS_TAP_DISTANCE is then the identity); the
//                       centre's index (value & 15) picks its profile's table (a uniform block of
//                       SSS_PROFILES) and u_profile[] entry; an index >= u_profile_count leaves the
//                       pixel alone; taps whose whole value (profile and object) differs count as
//                       the centre
// and from the dialect's header (version_*.glsl, module/src/gl/glsl_variant.cpp):
//   SSS_BINDING(unit)        layout(binding = unit) where the dialect has it, else nothing (the
//                            module sets the unit with glUniform1i)
// The pieces it includes (the module expands #include, module/src/gl/shader_source.cpp):
// nearest_half.glsl (sss_nearest_half: the written colour rounded to half float where the target is
// one, u_round_to_half), depth.glsl (view_distance, clip_w), jitter.glsl and footprint_taps.glsl
// (the taps and their weights: footprint_sum, shared with separable_blur.comp).

#include "nearest_half.glsl"
#include "colour_range.glsl"
#include "depth.glsl"
#include "jitter.glsl"

SSS_BINDING(0) uniform sampler2D u_source;    // the pass input (host colour, then the intermediate)
SSS_BINDING(1) uniform sampler2D u_depth;     // the host's depth
#if SSS_OUTSIDE == 2
SSS_BINDING(2) uniform sampler2D u_original;  // the host's colour, never attached to the target of this pass
#endif
#if SSS_ACCUMULATE
SSS_BINDING(3) uniform sampler2D u_accumulated;  // the earlier terms' vertical sums (the module's own target)
#endif
uniform vec2 u_axis;                  // (1, 0) or (0, 1)
uniform float u_pixels_per_mm;        // along u_axis, at clip w = 1 and strength 1
uniform float u_follow_surface;       // 1 / the kernel's reach in world units (SSS_FOLLOW_SURFACE 2: 1 / world units per mm)
uniform vec4 u_clamp;                 // tap positions are kept inside (xy min, zw max), in pixels

#if SSS_PROFILE_IDS
SSS_BINDING(4) uniform highp usampler2D u_depth_ids;  // per pixel: view distance bits, profile (bits 0-3), object
uniform vec4 u_profile[SSS_PROFILES];  // per profile: pixels per mm along u_axis, follow-surface factor, 1/(2v)
uniform int u_profile_count;           // the profiles set (sss_set_profiles)
uint sss_centre_id;                    // the centre pixel's whole index
bool sss_tap_foreign;                  // the last tap sss_fetch_tap read has another index
#endif

out vec4 o_color;

// footprint_taps.glsl's tap reads: straight from the textures, around the fragment.
struct TapSite {
  vec2 centre;  // gl_FragCoord.xy
};

vec4 sss_fetch_tap(TapSite site, float offset) {
  vec2 position = clamp(site.centre + u_axis * offset, u_clamp.xy, u_clamp.zw);
  ivec2 texel = ivec2(position);
#if SSS_PROFILE_IDS
  uvec2 depth_id = texelFetch(u_depth_ids, texel, 0).rg;
  sss_tap_foreign = depth_id.y != sss_centre_id;
  return vec4(texelFetch(u_source, texel, 0).rgb, uintBitsToFloat(depth_id.x));  // a view distance already
#elif SSS_FOLLOW_SURFACE
  return vec4(texelFetch(u_source, texel, 0).rgb, texelFetch(u_depth, texel, 0).r);
#else
  return vec4(texelFetch(u_source, texel, 0).rgb, 0.0);
#endif
}

#include "footprint_taps.glsl"

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
  // Not translucent, or a non-finite colour or strength (or past colour_range.glsl's bound): the
  // pixel keeps its own value.
  if (!(centre.a > 0.0) || !sss_in_range(centre)) {
    leave_untouched(pixel, centre);
    return;
  }
  float strength = min(centre.a, 1.0);  // alpha is documented as 0..1; more must not widen the kernel
#if SSS_PROFILE_IDS
  uvec2 centre_depth_id = texelFetch(u_depth_ids, pixel, 0).rg;
  float centre_distance = uintBitsToFloat(centre_depth_id.x);
#else
  float centre_distance = view_distance(texelFetch(u_depth, pixel, 0).r);
#endif
  float w = clip_w(centre_distance);
  // Behind the camera, on an infinite far plane, or NaN. isnan() and not only !(w > 0.0): on
  // NVIDIA's driver (580) the negated comparison behaved as the opposite one, which a NaN passes.
  if (isnan(w) || !(w > 0.0) || isinf(w)) {
    leave_untouched(pixel, centre);
    return;
  }

#if SSS_PROFILE_IDS
  sss_centre_id = centre_depth_id.y;
  int profile = int(sss_centre_id & 15u);
  if (profile >= u_profile_count) {  // no profile set for this index: documented as left alone
    leave_untouched(pixel, centre);
    return;
  }
  sss_table_base = profile * (SSS_CDF_ENTRIES + 1);
  vec4 look = u_profile[profile];
  sss_inv_two_variance = look.z;
  float step_pixels = look.x * strength / w;
  float follow_surface = look.y / strength;
#else
  float step_pixels = u_pixels_per_mm * strength / w;
  float follow_surface = u_follow_surface / strength;  // the reach scales with alpha like the taps
#endif
  vec3 sum = footprint_sum(TapSite(gl_FragCoord.xy), centre.rgb, step_pixels, centre_distance, follow_surface,
                           pixel, u_axis.y > 0.5 ? 1 : 0);
#if SSS_ACCUMULATE
  sum += texelFetch(u_accumulated, pixel, 0).rgb;
#endif
#if SSS_OUTSIDE == 2
  o_color = sss_nearest_half(vec4(sum, texelFetch(u_original, pixel, 0).a));
#else
  o_color = sss_nearest_half(vec4(sum, centre.a));
#endif
}
