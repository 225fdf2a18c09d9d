/*
 * sss tools: the research toolbox beside the runtime (C99, no GL): the kernel families of the
 * separable SSS paper and its supplementary, the radial profiles they are built from, their fits,
 * the transmittance terms, and the legacy conversions. Library: sss::tools (CMake) / sss-tools
 * (pkg-config), which links NLopt and Eigen; the runtime library sss::sss links neither. Includes
 * <sss/sss.h> (which never includes this header).
 *
 * The fitted kernels (SVD, pre-integrated, guided, a sum of Gaussians fitted to a profile) and the
 * Gaussians fitted to a measured material are built by this library. sss_tools_init registers them
 * with the runtime, so that sss_settings.kernel and sss_settings.cbf_profile can name them; every
 * function of this header calls it, so a host that fills its kernel with sss_default_kernel_desc
 * need not. Without it sss_set_settings refuses them with SSS_ERROR_UNSUPPORTED.
 *
 * Every kernel is a "plan": a sum of separable terms, each one horizontal and one vertical pass of
 * `taps` taps {weight r, weight g, weight b, offset in profile millimetres}:
 *
 *   out_c(p) = Σ_terms Σ_x Σ_y h_c(x) · v_c(y) · in_c(p + (x, y))
 *
 * Plans redistribute irradiance: each channel sums to 1 (SVD with SSS_KERNEL_SVD_NO_RESCALE aside);
 * the diffuse albedo stays the host's. Profiles are R_c(r) in mm⁻² per RGB channel.
 *
 * Errors: as in sss.h, a specific sss_result and a message naming the argument and its value,
 * readable with sss_last_error(NULL) on the calling thread. Outputs are written only on SSS_OK.
 * Thread-safe: no shared state.
 */
#ifndef SSS_SSS_TOOLS_H
#define SSS_SSS_TOOLS_H

#include "sss.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Kernel families (sss_kernel_desc.family). Passes = 2 × terms. */
typedef enum sss_kernel_family {
  SSS_KERNEL_SEPARABLE = 0,        /**< paper eq. (1) from strength and falloff: 1 term */
  SSS_KERNEL_SUM_OF_GAUSSIANS = 1, /**< d'Eon et al.: `rank` Gaussians, 1 term each (fitted to non-skin profiles) */
  SSS_KERNEL_SVD = 2,              /**< rank-`rank` SVD of the discretised 2D profile (supp. S.2-S.4) */
  SSS_KERNEL_PREINTEGRATED = 3,    /**< a_p(x)a_p(y)/‖R‖₁ (supp. S.5-S.6): exact for E1(x) + E2(y): 1 term; with
                                        rank N > 1, plus N − 1 SVD terms of the residual, which move no light
                                        along either axis (still exact there) and bring the 2D shape closer */
  SSS_KERNEL_GUIDED = 4,           /**< guided rank-1 fit with exponent guide_k (supp. S.7-S.9): 1 term */
  SSS_KERNEL_ARTIST = 5            /**< two Gaussians, near/far variance and weight, depth-corrected (supp. §E): 1 term */
} sss_kernel_family;
#define SSS_KERNEL_FAMILY_COUNT 6
/** The most terms any plan has (sum of Gaussians or SVD at rank 6). */
#define SSS_KERNEL_MAX_TERMS 6

#define SSS_PROFILE_MAX_TABLE 4096

/** Burley's normalized diffusion (SSS_PROFILE_BURLEY; Christensen and Burley 2015), per channel
 *  R(r) = A·(e^{-r/d} + e^{-r/(3d)})/(8π·d·r) with d = ℓ_d/s(A), s(A) = 3.5 + 100·(A − 0.33)⁴ (the
 *  memo's fit for the diffuse mean free path ℓ_d). ∫∫R = A; R is infinite at r = 0 (its 1/r), which
 *  sss_profile_evaluate returns as +inf. The kernels redistribute irradiance (each channel sums to 1),
 *  so there A only shapes the profile through s(A); the diffuse colour stays the host's.
 *  Published materials: sss_profile_burley_from_measured, docs/burley.md. */
#define SSS_BURLEY_MIN_DMFP_MM 1e-3f
#define SSS_BURLEY_MAX_DMFP_MM 1e3f

typedef struct sss_profile_desc {
  uint32_t struct_size;         /**< sizeof(sss_profile_desc) (0.1-0.3's, without the burley fields, too) */
  int32_t profile;              /**< sss_profile (sss.h): SSS_PROFILE_SKIN_DEON (default), a measured material
                                     SSS_PROFILE_APPLE..SSS_PROFILE_WHOLEMILK, SSS_PROFILE_TABULATED or
                                     SSS_PROFILE_BURLEY */
  int32_t gaussian_count;       /**< SSS_PROFILE_SKIN_DEON: the first 1..6 Gaussians, renormalised; default 6 */
  int32_t table_size;           /**< SSS_PROFILE_TABULATED: entries, 1..SSS_PROFILE_MAX_TABLE */
  const float *table_radius_mm; /**< table_size radii, finite, >= 0, strictly increasing */
  const float *table_rgb;       /**< 3 × table_size values R_c(r) in mm⁻², finite, >= 0; linear between
                                     radii, constant inside the first, 0 beyond the last */
  float burley_albedo[3];       /**< SSS_PROFILE_BURLEY: surface albedo A (total diffuse reflectance) per
                                     channel, (0, 1]; default: as burley_dmfp_mm */
  float burley_dmfp_mm[3];      /**< SSS_PROFILE_BURLEY: diffuse mean free path ℓ_d = 1/σtr per channel, mm,
                                     [SSS_BURLEY_MIN_DMFP_MM, SSS_BURLEY_MAX_DMFP_MM]; default Jensen et al.
                                     2001's skin1 (sss_profile_burley_from_measured; docs/burley.md) */
} sss_profile_desc;

/** SSS_KERNEL_SVD: keep the plain rank-N truncation (no rescaling to the profile's energy). */
#define SSS_KERNEL_SVD_NO_RESCALE 0x1u
#define SSS_KERNEL_ALL_FLAGS 0x1u

typedef struct sss_kernel_desc {
  uint32_t struct_size;        /**< sizeof(sss_kernel_desc) (0.1-0.3's, profile without burley fields, too) */
  int32_t family;              /**< sss_kernel_family; default SSS_KERNEL_SEPARABLE */
  int32_t taps;                /**< taps per pass, odd, [SSS_MIN_TAPS, SSS_MAX_TAPS]; default 17 */
  int32_t rank;                /**< SUM_OF_GAUSSIANS: Gaussians, SVD: rank, PREINTEGRATED: terms (1: the
                                    supplementary's); 1..6 (default 1); others ignore it */
  uint32_t flags;              /**< SSS_KERNEL_* flags; default 0 */
  float guide_k;               /**< GUIDED: guide exponent, [0, 4]; default 1.55 */
  float radius_mm;             /**< SVD, PREINTEGRATED, GUIDED: grid half-width in mm, 0 (default: the
                                    profile's 1e-4 extent; guided: its 90% radius) or in (0, 1e4] */
  float strength[3];           /**< SEPARABLE: [0, 1] each; default the paper's Table 1 (.78 .70 .75) */
  float falloff[3];            /**< SEPARABLE: [0, 1] each; default (.57 .13 .08) */
  float near_variance_mm2[3];  /**< ARTIST: (0, 1e4] each; default: the model's fit to d'Eon's skin
                                    (docs/kernel-fits.md), as far_variance_mm2 and near_weight */
  float far_variance_mm2[3];   /**< ARTIST: (0, 1e4] each */
  float near_weight[3];        /**< ARTIST: [0, 1] each */
  sss_profile_desc profile;    /**< SUM_OF_GAUSSIANS, SVD, PREINTEGRATED, GUIDED: the profile */
} sss_kernel_desc;

/** Fills *p with the defaults above (d'Eon skin, six Gaussians). NULL is ignored. */
SSS_API void sss_default_profile_desc(sss_profile_desc *p);

/** Fills *d with the defaults above (eq. (1) kernel, Table 1 parameters, 17 taps). NULL is ignored. */
SSS_API void sss_default_kernel_desc(sss_kernel_desc *d);

/** The profile's short name ("apple"; "skin" for SSS_PROFILE_SKIN_DEON, "tabulated", "mikkelsen-2010",
 *  "kernel", "burley"), or NULL when profile is outside [0, SSS_PROFILE_COUNT). */
SSS_API const char *sss_profile_name(int32_t profile);

/** Burley's parameters for a measured material: *out becomes the default desc with profile
 *  SSS_PROFILE_BURLEY, burley_albedo the material dipole's total diffuse reflectance R_d and
 *  burley_dmfp_mm 1/σtr, from Jensen et al. 2001's σa, σs' and η (the table: docs/burley.md).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT out NULL, or material outside [SSS_PROFILE_APPLE, SSS_PROFILE_WHOLEMILK] */
SSS_API sss_result sss_profile_burley_from_measured(int32_t material, sss_profile_desc *out);

/** R_c(r) of the profile at `count` radii into out_rgb (3 floats per radius, mm⁻²).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT profile, radius_mm or out_rgb NULL; count outside [1, 1e8]; a radius
 *                                     negative or not finite; or the profile invalid (struct_size, profile,
 *                                     gaussian_count, table_size, a table pointer NULL, a table value out of range,
 *                                     a burley field out of range) */
SSS_API sss_result sss_profile_evaluate(const sss_profile_desc *profile, int32_t count, const float *radius_mm,
                                        float *out_rgb);

/** The profile's integral over the plane per channel (its total diffuse reflectance) into out_rgb[3].
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT profile or out_rgb NULL, or the profile invalid (as for sss_profile_evaluate) */
SSS_API sss_result sss_profile_integral(const sss_profile_desc *profile, float out_rgb[3]);

/** Builds the kernel `desc` describes. Writes *out_terms (1..SSS_KERNEL_MAX_TERMS) terms of
 *  2 passes × desc->taps taps: out_taps[((term · 2 + pass) · taps + tap) · 4 + k], pass 0 horizontal,
 *  1 vertical, k = {weight r, weight g, weight b, offset mm}; taps of a pass in increasing offset
 *  (the eq. (1) kernel keeps its own layout: centre first; its offsets are its own kernel
 *  millimetres, which sss_settings.separable_scale converts to the surface's). The passes do not
 *  read these taps: they read each pass's kernel at every pixel's footprint (docs/kernels.md); the
 *  taps are the kernel's discrete form for your own use. SVD weights may be negative.
 *  out_taps must hold max_terms · 2 · taps · 4 floats. Optional (may be NULL): out_depth_variance_mm2
 *  (max_terms floats: > 0 where a term's taps are depth-corrected by exp(-dz²/2v), supp. §E; else 0)
 *  and out_reach_mm (the largest |offset|). The fitted families (GUIDED, SUM_OF_GAUSSIANS on a
 *  non-skin profile) run an optimiser: milliseconds to a few hundred; build plans once, not per frame.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT desc, out_taps or out_terms NULL; struct_size; family, taps, rank, flags,
 *                                     guide_k, radius_mm, strength, falloff, the artist fields or the profile out of
 *                                     range; or max_terms below the plan's term count (*out_terms then says how
 *                                     many are needed, nothing else is written) */
SSS_API sss_result sss_kernel_plan(const sss_kernel_desc *desc, int32_t max_terms, float *out_taps,
                                   float *out_depth_variance_mm2, int32_t *out_terms, float *out_reach_mm);

/** Gaussians fitted to a measured material's dipole for the cross-bilateral mode and the
 *  transmittance terms (sss_kernel_plan's SSS_KERNEL_SUM_OF_GAUSSIANS fit with rank 4). */
#define SSS_PROFILE_FIT_GAUSSIANS 4
/** The most terms sss_profile_transmittance_terms writes. */
#define SSS_PROFILE_MAX_TERMS 8

/** The transmittance terms of a profile, for the host's lighting pass
 *  (integration/glsl/sss_transmittance.glsl): out_terms receives up to `capacity` quadruples
 *  {variance in mm², weight r, weight g, weight b} of the same Gaussians the cross-bilateral mode
 *  blurs with; *count the number written. The include evaluates Σ w · exp(-s² / v) at the scaled
 *  thickness s. `profile`, an sss_profile as sss_settings.cbf_profile takes it:
 *  - SSS_PROFILE_MIKKELSEN_2010: its three broad Gaussians (the spike has no width and transmits nothing);
 *  - SSS_PROFILE_SKIN_DEON: d'Eon–Luebke's six Gaussians (the 0.0064 mm² one is the blur's spike);
 *  - SSS_PROFILE_APPLE .. SSS_PROFILE_WHOLEMILK: SSS_PROFILE_FIT_GAUSSIANS Gaussians fitted to the
 *    material's dipole (an NLopt fit: milliseconds to ~0.1 s; no spike). SSS_PROFILE_TABULATED,
 *    SSS_PROFILE_KERNEL and SSS_PROFILE_BURLEY are not accepted (they need an sss_profile_desc).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT profile neither SSS_PROFILE_MIKKELSEN_2010 nor in [SSS_PROFILE_SKIN_DEON,
 *                                     SSS_PROFILE_WHOLEMILK], out_terms or count NULL, or capacity smaller
 *                                     than the profile's term count (SSS_PROFILE_MAX_TERMS always suffices;
 *                                     *count then tells the size needed)
 *  @retval SSS_ERROR_OUT_OF_MEMORY    the fit of a measured material could not allocate */
SSS_API sss_result sss_profile_transmittance_terms(uint32_t profile, float *out_terms, int32_t capacity,
                                                   int32_t *count);

/** The transmittance terms of any sss_profile_desc, written like sss_profile_transmittance_terms:
 *  the Gaussians the cross-bilateral mode blurs with when sss_settings.cbf_profile is
 *  SSS_PROFILE_KERNEL and sss_settings.kernel->profile is *profile (a sum of Gaussians as it is, any
 *  other profile fitted with SSS_PROFILE_FIT_GAUSSIANS Gaussians).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT profile, out_terms or count NULL, a field of *profile outside its range
 *                                     (named in sss_last_error(NULL)), or capacity below the term count
 *                                     (*count then tells the size needed)
 *  @retval SSS_ERROR_OUT_OF_MEMORY    the fit could not allocate */
SSS_API sss_result sss_profile_desc_transmittance_terms(const sss_profile_desc *profile, float *out_terms,
                                                        int32_t capacity, int32_t *count);

/** Fills `taps` taps of the separable kernel of the paper's eq. (1) into out_rgba as
 *  {weight r, weight g, weight b, offset in profile millimetres}: the centre tap first, then the
 *  others from the most negative offset to the most positive. Offsets span [-R, R] with R = 2 mm at
 *  every tap count (3 mm above 20 taps before issue 49, docs/migration.md), quadratically denser at
 *  the centre; each weight is the profile integrated exactly over the tap's interval, normalised per channel, then strength applied
 *  (centre: 1 - s + s·w0; others: s·w). Each channel sums to 1.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT taps even or outside [3, 65], a NULL pointer, strength or falloff
 *                                     outside [0, 1] or not finite */
SSS_API sss_result sss_kernel_separable(int32_t taps, const float strength[3], const float falloff[3],
                                        float *out_rgba);

/** The legacy conversion: sss_settings.world_units_per_mm for the paper's (and sss 0.1's) `width`,
 *  with which one millimetre of the profile spanned (2/3)·width world units: returns (2/3)·width.
 *  sss_set_settings applies it itself to a 0.1-sized sss_settings. */
SSS_API float sss_world_units_per_mm_from_legacy_width(float width);

/** Sets the eq. (1) kernel of *s to the paper's Table 1 (strength .78 .70 .75, falloff .57 .13 .08)
 *  with the separable_scale fitted for it against d'Eon's skin (docs/kernel-fits.md), so that Table 1
 *  too is physical skin size at scale 1. Other fields are kept. NULL is a no-op. */
SSS_API void sss_settings_separable_table1(sss_settings *s);

/** Registers this library's fitters with the runtime (see the top of this header). Idempotent and
 *  thread-safe; every other function of this header calls it. */
SSS_API void sss_tools_init(void);

#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_TOOLS_H */
