// The texturing modes (sss.h sss_texturing): the host's colour is irradiance times albedo A; a mode
// other than pre-scatter blurs irradiance times A_pre and multiplies the result by A_post
// (A_pre · A_post = A). colour_copy.frag divides the colour by A_post before the passes; the pass
// that writes the frame's target multiplies by it (separable_blur.frag and .comp, cbf_blur.frag,
// half_upsample.frag). Both read it here, so the two cannot disagree: a pixel the passes leave as
// it is gets colour / A_post · A_post back, and one where A_post is the same everywhere the passes
// reach (uniform light over any albedo, post-scatter) gets its own colour.
//   SSS_ALBEDO  0: pre-scatter (nothing read); 1: A_post = A (post-scatter); 2: A_post = sqrt(A)
//               (pre- and post-scatter); 3: per pixel, the mode of its profile (per-pixel profiles
//               whose modes differ: the caller passes the mode, 0-2)
// A channel of A below kSssAlbedoFloor counts as the floor: the colour is near 0 there too, and a
// smaller divisor would turn its rounding into light (sss.h documents the rule).
//   SSS_ALBEDO_SAMPLES defined: the albedo is multisampled like the colour (the MSAA resolve and
//               write-back, msaa_resolve.frag and msaa_write.frag), read per sample.
#if SSS_ALBEDO
#ifdef SSS_ALBEDO_SAMPLES
SSS_BINDING(6) uniform sampler2DMS u_albedo;  // the host's multisampled albedo
#else
SSS_BINDING(6) uniform sampler2D u_albedo;  // the host's albedo (sRGB decoded by the GL as it is fetched)
#endif

const float kSssAlbedoFloor = 0.00390625;  // 1/256, exact in half and single floats

// A_post at `pixel` (its sample `index` where the albedo is multisampled, else level 0: texelFetch's
// third argument either way) for texturing mode `mode` (1 or 2; 0 gives 1).
vec3 sss_albedo_post_at(ivec2 pixel, int index, int mode) {
  if (mode == 0) return vec3(1.0);
  vec3 a = max(texelFetch(u_albedo, pixel, index).rgb, vec3(kSssAlbedoFloor));
  return mode == 1 ? a : sqrt(a);
}
vec3 sss_albedo_post(ivec2 pixel, int mode) { return sss_albedo_post_at(pixel, 0, mode); }
#endif

// What the pass that writes the target writes at a blurred pixel: its result times A_post for the
// pixel's mode (SSS_ALBEDO 0: the result as it is).
vec3 sss_times_albedo_post(vec3 result, ivec2 pixel, int mode) {
#if SSS_ALBEDO
  return result * sss_albedo_post(pixel, mode);
#else
  return result;
#endif
}
