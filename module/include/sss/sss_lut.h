/*
 * sss_lut: pre-integrated skin shading lookup tables (Penner and Borshukov 2011), C99.
 *
 * A tools header: include it (it includes <sss/sss.h> for sss_result, sss_context, sss_profile and
 * SSS_API; sss.h does not include it). Implemented in the runtime library (sss::sss): the LUTs need
 * neither NLopt nor Eigen, and sss_lut_create_texture draws with the context's GL objects. The fill
 * functions need no GL context; sss_lut_create_texture needs the one an sss_context was created in.
 *
 *   Diffuse LUT D(N·L, curvature), eq. (1.1): the light a sphere of radius r = 1/curvature lit
 *   from one direction shows at the angle θ = acos(N·L), the diffusion profile integrated around
 *   the ring. Column x (of width W) holds N·L = -1 + 2x/(W-1); row y (of height H) holds curvature
 *   curvature_min + (curvature_max - curvature_min)·y/(H-1) in 1/mm of profile. Both ends are
 *   texels: sample at uv = (0.5 + u·(W-1))/W (integration/sss_preintegrated.glsl does).
 *
 *   Shadow LUT P_S(s, w), §1.6: the shadow value s of the host's filtered shadow map (column x
 *   holds s = x/(W-1)) remapped, for a penumbra w world units wide (row y holds penumbra_min +
 *   (penumbra_max - penumbra_min)·y/(H-1)), to a sharper penumbra (new_penumbra of the filter's
 *   width, centred) plus the light the profile scatters across it; s = 0 stays 0 and s = 1 stays 1.
 *
 * Texels are RGBA: red, green, blue = the three channels of the profile, alpha = 1. Every value
 * lies in [0, 1].
 */
#ifndef SSS_SSS_LUT_H
#define SSS_SSS_LUT_H

#include "sss.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Diffusion profiles for sss_lut_desc.profile: the sss_profile values of sss.h from
 * SSS_PROFILE_SKIN_DEON (all six Gaussians) to SSS_PROFILE_WHOLEMILK (the dipoles of the 11 measured
 * materials). SSS_PROFILE_TABULATED has no place here (a table needs the arrays of sss_profile_desc),
 * nor SSS_PROFILE_MIKKELSEN_2010 (its spike is no radial profile) or SSS_PROFILE_KERNEL. */

/** Shadow filters for sss_lut_desc.shadow_filter: the filter the host's shadow map uses. */
typedef enum sss_lut_shadow_filter {
  SSS_LUT_SHADOW_BOX = 0,     /**< box PCF: the penumbra is a linear ramp (the default) */
  SSS_LUT_SHADOW_GAUSSIAN = 1 /**< Gaussian-weighted PCF, its penumbra spanning ±2σ */
} sss_lut_shadow_filter;

/** Texture formats for sss_lut_desc.format (sss_lut_create_texture). */
typedef enum sss_lut_format {
  SSS_LUT_FORMAT_RGBA16F = 0, /**< half floats (the default): 2^-11 relative error */
  SSS_LUT_FORMAT_RGBA32F = 1, /**< floats, exactly the fill functions' values */
  SSS_LUT_FORMAT_RGBA8 = 2    /**< unsigned normalised bytes, linear (no sRGB): value = byte/255;
                                   |error| <= 1/510 with SSS_LUT_CPU (rounded to nearest on the host),
                                   <= 1/255 from the GPU generator (the driver's float-to-unorm rounding) */
} sss_lut_format;

/** Which LUT sss_lut_create_texture makes. */
typedef enum sss_lut_kind { SSS_LUT_DIFFUSE = 0, SSS_LUT_SHADOW = 1 } sss_lut_kind;

/* Flags for sss_lut_desc.flags. */
/** sss_lut_create_texture: generate on the CPU and upload, instead of the fragment-shader generator. */
#define SSS_LUT_CPU 0x1u
#define SSS_LUT_ALL_FLAGS 0x1u

#define SSS_LUT_MIN_SIZE 2
#define SSS_LUT_MAX_SIZE 4096

/** What to generate. Fill with sss_lut_default_desc, then change fields. */
typedef struct sss_lut_desc {
  uint32_t struct_size;      /**< sizeof(sss_lut_desc) */
  int32_t width;             /**< [2, 4096] columns (N·L or shadow value). Default 256 */
  int32_t height;            /**< [2, 4096] rows (curvature or penumbra width). Default 256 */
  int32_t profile;           /**< sss_profile in [SSS_PROFILE_SKIN_DEON, SSS_PROFILE_WHOLEMILK] (0..11).
                                  Default SSS_PROFILE_SKIN_DEON */
  float curvature_min;       /**< diffuse: 1/mm, finite, [0, 1000], < curvature_max. Default 0 (flat) */
  float curvature_max;       /**< diffuse: 1/mm, finite, (curvature_min, 1000]. Default 1 (r = 1 mm) */
  float penumbra_min;        /**< shadow: world units, finite, > 0, < penumbra_max. Default 0.001 */
  float penumbra_max;        /**< shadow: world units, finite, <= 1e6. Default 0.032 */
  float world_units_per_mm;  /**< shadow: the scene's scale, finite, (0, 1e6]. Default 0.001 (metres) */
  float new_penumbra;        /**< shadow: width of the sharp penumbra as a fraction of the filter's, (0, 1].
                                  Default 0.25 */
  int32_t shadow_filter;     /**< sss_lut_shadow_filter. Default SSS_LUT_SHADOW_BOX */
  int32_t format;            /**< sss_lut_format (textures only; the fill functions write floats). Default RGBA16F */
  int32_t threads;           /**< CPU generation: [0, 256] std::threads, 0 = as many as the hardware has. Default 0 */
  uint32_t flags;            /**< SSS_LUT_* flags. Default 0 */
} sss_lut_desc;

/** Fills *desc with the defaults listed on sss_lut_desc (struct_size set). NULL is a no-op. */
SSS_API void sss_lut_default_desc(sss_lut_desc *desc);

/** Writes the diffuse LUT, width·height RGBA floats row by row (row 0 = curvature_min), into
 *  out_rgba. Uses width, height, profile, curvature_min/max and threads. No GL. Cached: the fill
 *  functions keep the 8 most recently requested LUTs of the process (keyed by every input that
 *  changes a value; thread-safe), so asking again with the same description copies instead of
 *  generating (sss_lut_fill_generation_count counts the generations).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT desc or out_rgba NULL, bad struct_size, a field outside its range
 *                                     on sss_lut_desc (named in sss_last_error(NULL)), or out_floats below
 *                                     4·width·height; out_rgba is untouched
 *  @retval SSS_ERROR_OUT_OF_MEMORY    a thread could not be started */
SSS_API sss_result sss_lut_diffuse_fill(const sss_lut_desc *desc, float *out_rgba, size_t out_floats);

/** Writes the shadow LUT like sss_lut_diffuse_fill (row 0 = penumbra_min). Uses width, height,
 *  profile, penumbra_min/max, world_units_per_mm, new_penumbra, shadow_filter and threads. No GL.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT as sss_lut_diffuse_fill
 *  @retval SSS_ERROR_OUT_OF_MEMORY    a thread could not be started */
SSS_API sss_result sss_lut_shadow_fill(const sss_lut_desc *desc, float *out_rgba, size_t out_floats);

/** A GL_TEXTURE_2D holding the LUT `which` (SSS_LUT_DIFFUSE or SSS_LUT_SHADOW) in desc->format,
 *  linear filtering, clamped to edge, one level. Generated by a fragment shader on the GPU (or on
 *  the CPU with SSS_LUT_CPU; always on the CPU for a profile that is not a sum of at most 8
 *  Gaussians, i.e. the measured materials' dipoles, and on OpenGL ES for SSS_LUT_FORMAT_RGBA32F
 *  without GL_EXT_color_buffer_float). On OpenGL ES, SSS_LUT_FORMAT_RGBA32F needs
 *  GL_OES_texture_float_linear (the texture is filtered linearly). The texture belongs to the context: the same inputs (the fields that LUT uses, format
 *  and SSS_LUT_CPU; not threads)
 *  give the same texture again without generating anything; the context keeps the 8 most recently
 *  requested LUTs and deletes the least recently requested one when a ninth is made (ask again for
 *  a LUT you use each frame, or keep at most 8 in use); sss_destroy deletes them all. The host must
 *  not delete or modify it. GL state is restored as sss.h lists (the unpack buffer binding and the
 *  four unpack parameters included); a GPU generation compiles its shader each time (llvmpipe:
 *  hundreds of ms for 256², see docs/benchmarks/preintegrated.md), a cached LUT costs nothing.
 *  @retval SSS_OK                       *out_texture holds the name
 *  @retval SSS_ERROR_INVALID_ARGUMENT   ctx, desc or out_texture NULL, `which` unknown, or a field as
 *                                       for the fill functions, format or flags unknown
 *  @retval SSS_ERROR_NO_CONTEXT         no GL context current, or not the context's
 *  @retval SSS_ERROR_UNSUPPORTED        OpenGL ES, SSS_LUT_FORMAT_RGBA32F and no GL_OES_texture_float_linear
 *  @retval SSS_ERROR_SHADER_COMPILE     the generator shader failed (driver log in the message)
 *  @retval SSS_ERROR_FRAMEBUFFER        the generator's framebuffer is incomplete for this format
 *  @retval SSS_ERROR_OUT_OF_MEMORY      host or GL allocation failed
 *  @retval SSS_ERROR_GL                 the GL raised an error
 *  On failure *out_texture is 0 and nothing is left in the GL. */
SSS_API sss_result sss_lut_create_texture(sss_context *ctx, int32_t which, const sss_lut_desc *desc,
                                          uint32_t *out_texture);

/** How many LUTs sss_lut_diffuse_fill and sss_lut_shadow_fill have generated in this process: a
 *  fill that found its LUT cached leaves it unchanged. */
SSS_API uint64_t sss_lut_fill_generation_count(void);

/** How many LUTs the context has generated (CPU or GPU) since it was created: a call that found its
 *  LUT cached leaves it unchanged. 0 for NULL. */
SSS_API uint64_t sss_lut_generation_count(const sss_context *ctx);

#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_LUT_H */
