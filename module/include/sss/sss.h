/*
 * sss: screen-space separable subsurface scattering for OpenGL hosts.
 *
 * Public C API (C99). This header includes no GL header: GL object names are uint32_t and
 * GL enums are never needed by the caller.
 *
 * Typical frame:
 *
 *     sss_create_desc desc = { sizeof desc, my_get_proc_address, NULL };
 *     sss_context *sss; sss_create(&desc, &sss);           // GL context current
 *     sss_settings s; sss_default_settings(&s); s.world_units_per_mm = 0.001f; sss_set_settings(sss, &s);
 *     ...every frame:
 *     sss_set_camera(sss, projection);                     // column-major, as glUniformMatrix4fv
 *     sss_apply(sss, diffuse_rgba16f, depth24_stencil8, NULL);  // blurs diffuse in place
 *
 * Threading: a context is used from the thread on which its GL context is current; separate
 * sss contexts share nothing and may be used from separate threads. There is no global state.
 *
 * GL state: every entry point that calls GL restores, before it returns, each state in the list
 * below that it changed (unless SSS_CREATE_NO_STATE_RESTORE is given), and leaves no GL error
 * behind. A call that reads the GL error flag first clears the errors the host left pending and
 * reports them through the log callback (GL has no way to re-raise them): sss_create, the other
 * entry points that call GL, and every sss_apply_frame that is not steady (see "GL queries" on
 * sss_frame); a steady frame reads no error flag and leaves the host's pending errors to the host,
 * unless SSS_CREATE_DEBUG_CHECKS is given.
 *
 *   Saved and restored (SSS_STATE_LIST):
 *   - GL_CURRENT_PROGRAM, GL_VERTEX_ARRAY_BINDING
 *   - GL_DRAW_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER_BINDING, GL_RENDERBUFFER_BINDING
 *   - GL_ACTIVE_TEXTURE; on texture units 0, 1, 2 and 3: GL_TEXTURE_BINDING_2D, GL_SAMPLER_BINDING,
 *     and GL_TEXTURE_BINDING_2D_MULTISAMPLE where the API has it (GL 3.2+, ES 3.1+)
 *   - GL_PIXEL_UNPACK_BUFFER_BINDING
 *   - image unit 0 (desktop GL 4.3+: the compute path's target): GL_IMAGE_BINDING_NAME, _LEVEL,
 *     _LAYERED, _LAYER, _ACCESS, _FORMAT (a texture the host deleted in between restores as 0)
 *   - GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS (set only
 *     by sss_lut_create_texture's CPU upload, and always put back, even with SSS_CREATE_NO_STATE_RESTORE)
 *   - GL_VIEWPORT, GL_SAMPLE_MASK_VALUE (word 0)
 *   - enables: GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE,
 *     GL_FRAMEBUFFER_SRGB, GL_RASTERIZER_DISCARD, GL_SAMPLE_ALPHA_TO_COVERAGE,
 *     GL_SAMPLE_COVERAGE, GL_SAMPLE_MASK, GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP,
 *     GL_COLOR_LOGIC_OP, GL_CLIP_DISTANCE0..7, GL_MULTISAMPLE (the MSAA write-back switches it on: a
 *     host that disabled it would have the write-back's sample mask ignored and every sample overwritten)
 *   - GL_COLOR_WRITEMASK (draw buffer 0), GL_POLYGON_MODE
 *   - front and back: stencil func, ref, value mask, fail, depth-fail and pass ops, write mask
 *   - KHR_debug groups are pushed and popped in pairs.
 *   - Queries (SSS_CREATE_STATS): the module begins and ends its own inside the call, so no query
 *     is left active; a target the host has a query active on is not used (GL_CURRENT_QUERY of
 *     GL_TIME_ELAPSED and GL_SAMPLES_PASSED stays the host's).
 *   On OpenGL ES the list is what exists there: the same, without GL_FRAMEBUFFER_SRGB,
 *   GL_DEPTH_CLAMP, GL_COLOR_LOGIC_OP, GL_CLIP_DISTANCE0..7, GL_MULTISAMPLE and GL_POLYGON_MODE (none
 *   of them exist in ES; the module's float targets are never sRGB-converted), without GL_SAMPLE_MASK_VALUE
 *   (only the desktop MSAA path sets it), and without GL_SAMPLE_MASK and
 *   GL_TEXTURE_BINDING_2D_MULTISAMPLE before ES 3.1 (ES 3.0 has neither).
 *   - Host texture parameters: GL_DEPTH_STENCIL_TEXTURE_MODE of the frame's depth texture, switched
 *     to GL_DEPTH_COMPONENT for the passes when the host left it on GL_STENCIL_INDEX and always put
 *     back, even with SSS_CREATE_NO_STATE_RESTORE (see sss_frame.depth_stencil_mode).
 *   Not touched: blend functions and equations, depth function and mask, scissor box, clear
 *   values, pixel pack parameters and the other unpack ones, buffer bindings other than the unpack buffer, other texture
 *   parameters of host textures (the module samples through its own sampler objects).
 *   The host must not call sss_apply with transform feedback active or conditional rendering on.
 */
#ifndef SSS_SSS_H
#define SSS_SSS_H

#include "sss_common.h"
#include "sss_kernels.h" /* the kernel families and profiles (GL-free): sss_kernel_desc, ... */

#ifdef __cplusplus
extern "C" {
#endif

/** Loader callback: return the address of the GL function `name` ("glDrawArrays"), or NULL.
 *  OSMesaGetProcAddress, eglGetProcAddress and glfwGetProcAddress all fit (wrap them to add
 *  the user pointer). */
typedef void *(*sss_get_proc_address_fn)(const char *name, void *user);

/** Log levels for sss_log_fn. */
#define SSS_LOG_ERROR 0
#define SSS_LOG_WARNING 1
#define SSS_LOG_INFO 2
#define SSS_LOG_DEBUG 3
typedef void (*sss_log_fn)(int level, const char *message, void *user);

typedef struct sss_context sss_context;

/* SSS_CREATE_* flags for sss_create_desc.flags. */
/** The host saves and restores GL state itself: the module leaves the state it set (list in the
 *  file comment) as it is after each call, which saves the queries. */
#define SSS_CREATE_NO_STATE_RESTORE 0x1u
/** Skip KHR_debug groups and object labels even when the extension is present. */
#define SSS_CREATE_NO_DEBUG_LABELS 0x2u
/** Measure the passes on the GPU for sss_get_stats (pixels touched, GPU time per pass). Without it
 *  no query object exists and no query runs; sss_get_stats then gives the counters only. */
#define SSS_CREATE_STATS 0x4u
/** Check everything on every frame, steady ones included (see "GL queries" on sss_frame): that a
 *  context is current and holds the module's objects, the textures' targets, formats and sizes
 *  against the GL, every framebuffer's completeness, and the GL error flag: the host's pending errors
 *  are cleared and logged at SSS_LOG_WARNING on entry, and an error the passes raised fails the call
 *  with SSS_ERROR_GL. Off by default: a steady frame then makes no GL query at all (each is a round
 *  trip that stalls a threaded driver). For development builds and bug reports. */
#define SSS_CREATE_DEBUG_CHECKS 0x8u
#define SSS_CREATE_ALL_FLAGS 0xFu

typedef struct sss_create_desc {
  uint32_t struct_size;                     /**< sizeof(sss_create_desc) */
  sss_get_proc_address_fn get_proc_address; /**< required */
  void *get_proc_address_user;              /**< passed back to get_proc_address */
  sss_log_fn log;                           /**< optional: NULL for silence */
  void *log_user;                           /**< passed back to log */
  uint32_t flags;                           /**< SSS_CREATE_* */
} sss_create_desc;

/* Flags for sss_settings.flags. */
/** Follow-surface test (paper §3.2): a tap is blended back towards the centre colour in proportion
 *  to its depth difference from the centre, fully once that difference reaches the kernel's reach
 *  (its largest tap offset in profile millimetres, scaled like the taps by the scene scale and the pixel's
 *  alpha). The artist family (SSS_KERNEL_ARTIST) blends by its exact depth correction instead:
 *  1 - exp(-dz²/2τ_max), dz in profile millimetres (supplementary §E). */
#define SSS_FOLLOW_SURFACE 0x1u
/** Accepted for source compatibility and ignored since 0.2: every kernel now runs
 *  footprint-aware taps (see sss_settings.samples), which choose each pixel's taps from its footprint,
 *  pass a pixel whose kernel fits inside it through and never read more taps than its footprint
 *  needs; what this flag used to switch on is the default behaviour. sss_get_settings does not
 *  report it back. */
#define SSS_ADAPTIVE_TAPS 0x2u
#define SSS_SETTINGS_ALL_FLAGS 0x3u

/* How the separable passes run, for sss_settings.path. */
/** Two full-screen fragment passes (the paper's; every feature, every API). The default. */
#define SSS_PATH_FRAGMENT 0u
/** Two compute dispatches (desktop OpenGL 4.3+): each work group reads its row, then column, segment
 *  of 128 pixels and 64 on either side into shared memory once, and the taps read it there
 *  instead of sampling the textures again; taps farther out than the cached span sample the
 *  textures, so any kernel width gives the same image as the fragment path. Writes the target
 *  through image unit 0 (saved and restored with the rest of the state list). A frame the compute
 *  path cannot run takes the fragment path: OpenGL ES or a context before 4.3, the cross-bilateral
 *  mode, a stencil mask, multisampled colour or a kernel of several terms (sss_stats.last_frame_path
 *  says which path ran). Written back in place, the host's alpha is read back from the colour and
 *  stored unchanged. sss_stats.pixels_touched is not measured for
 *  compute frames (SSS_STATS_PIXELS stays clear: there are no samples to count). */
#define SSS_PATH_COMPUTE 1u
/** Whichever path is fastest here, among those that can run the frame: SSS_PATH_FRAGMENT,
 *  SSS_PATH_FRAGMENT_MASKED and SSS_PATH_COMPUTE. Where timer queries are trustworthy (desktop GL,
 *  GL_QUERY_COUNTER_BITS > 0, not a software rasteriser), the first frames of a configuration
 *  cycle through the candidates, timing each frame with GL_TIME_ELAPSED read back without stalling
 *  (three per path), and the lowest median wins until the size, the settings, the formats or the
 *  frame's flags change. Elsewhere (Mesa's software rasterisers, OpenGL ES) it takes what the
 *  benchmark measured fastest on llvmpipe (docs/benchmarks.md; the compute path runs about 2x slower
 *  there): the masked fragment path, or the plain one when the frame has SSS_FRAME_REGION (the
 *  region already leaves out what is not translucent) or the mask cannot be used. The choice is
 *  logged at SSS_LOG_INFO. While it times a frame, SSS_CREATE_STATS has no GPU time for that frame
 *  (GL_TIME_ELAPSED queries cannot nest), and a frame with the host's own GL_TIME_ELAPSED query
 *  active is not timed. The default: with state restore it also saves what the masked and compute
 *  paths change (the stencil state, image unit 0), and the masked path's stencil is a renderbuffer
 *  the size of the frame; SSS_PATH_FRAGMENT avoids both where the plain passes are what you want. */
#define SSS_PATH_AUTO 2u
/** The fragment passes behind a stencil mask the module marks from the colour's alpha (one
 *  full-screen draw that writes only stencil: alpha > 0 and a finite colour), the paper's stencil
 *  culling without a host stencil: the blur is shaded on translucent pixels alone, the rest are
 *  copied (horizontal pass; and into a separate output) or left alone. The same image as
 *  SSS_PATH_FRAGMENT, bit for bit; it costs the mark and a copy draw, and saves shading every
 *  pixel that is not translucent, which on llvmpipe (whose shaders pay for their masked-off code)
 *  cuts frames with few translucent pixels to a fraction (docs/benchmarks.md, "Skipping what a
 *  frame does not need"). Frames with a host stencil (already culled),
 *  the cross-bilateral mode or multisampled colour (whose path marks the stencil from alpha
 *  anyway) take their usual path. */
#define SSS_PATH_FRAGMENT_MASKED 3u

/* Filter modes for sss_settings.mode. */
/** Jimenez et al. 2012: the two-pass separable kernel of eq. (1), follow-surface blend (the default). */
#define SSS_MODE_SEPARABLE 0u
/** Mikkelsen 2010: a pseudo-separable normalised cross-bilateral filter (two 1D passes). The
 *  footprint is the projected sphere of radius cbf_r_max_mm, shrunk per axis by the cosine between
 *  the surface (normal reconstructed from depth) and the view ray in the XZ and YZ planes; taps are
 *  placed by the inverse CDF of the red channel's profile (cbf_taps of them), green and blue reuse
 *  them with their own weights; a range Gaussian on the depth difference and zero weight for
 *  neighbours that are not translucent (alpha 0 or outside the stencil) keep light from crossing
 *  silhouettes. Uses world_units_per_mm and scale (and alpha scaling them) like the separable mode;
 *  ignores strength, falloff, samples and flags: the profile (cbf_profile) sets the unscattered
 *  share and the radii. */
#define SSS_MODE_CROSS_BILATERAL 1u

/* The profile of the cross-bilateral mode (sss_settings.cbf_profile) is named like every profile of
 * the module: an sss_material value of sss_kernels.h (SSS_MATERIAL_SKIN to SSS_MATERIAL_WHOLEMILK),
 * or SSS_PROFILE_MIKKELSEN_2010 (also in sss_kernels.h), Mikkelsen's own profile, which is no material,
 * or SSS_PROFILE_KERNEL: whatever sss_settings.kernel.profile holds (d'Eon with 1..6 Gaussians, a
 * material, a tabulated table). */

#define SSS_CBF_DEFAULT_TAPS 13     /**< Mikkelsen's N */
#define SSS_CBF_DEFAULT_R_MAX_MM 4.5f /**< Mikkelsen's r_max for skin */
#define SSS_CBF_MAX_R_MAX_MM 50.0f

/** Filter settings.
 *
 *  Units (changed in 0.2; see docs/migration.md): the scene scale and the look are apart.
 *  world_units_per_mm says how long one millimetre of the surface is in the host's world units
 *  (0.001 for a scene in metres, 0.1 for centimetres, 1 for millimetres, 1/25.4 for inches);
 *  `scale` multiplies every scattering distance, 1 being the material at its physical
 *  size. With the defaults a scene in metres gets d'Eon's skin profile at its measured size. The
 *  per-pixel alpha of the colour texture (0..1) scales the distances further, as in the paper.
 *  The paper's `width` (one kernel millimetre spans (2/3)·width world units) converts with
 *  sss_world_units_per_mm_from_legacy_width; for 0.1's eq. (1) kernel size, also select
 *  sss_settings_separable_table1 and set separable_scale to 1 (the taps differ: see
 *  docs/migration.md). */
typedef struct sss_settings {
  uint32_t struct_size; /**< sizeof(sss_settings) */
  float world_units_per_mm; /**< [0, 1e6], finite: world units per millimetre of surface; 0 leaves the image
                                 unchanged. Default 0.001 (metres) */
  float scale;          /**< [0, 1e3], finite: multiplies the scattering distances; 1 = physical, 0 leaves the
                             image unchanged. Default 1 */
  float strength[3];    /**< [0, 1] per channel, eq. (1): share of light that scatters. Default: the calibrated fit
                             (sss_default_settings; the values and the fit: docs/kernel-fits.md) */
  float falloff[3];     /**< [0, 1] per channel, eq. (1): profile radius scale. Default: the calibrated fit */
  float separable_scale; /**< (0, 100], finite, eq. (1): kernel millimetres (the unit of its 2 or 3 mm range and of
                              falloff) per millimetre of surface. Default: the calibrated fit. The paper's Table 1
                              with its own derived scale: sss_settings_separable_table1 */
  int32_t samples;      /**< odd, [3, 65]; the most taps per pass (each pixel reads as many as its footprint
                             needs, up to this: every pixel out to the kernel's reach where it spans fewer
                             pixels, else spread cubically denser at the centre). Default 17 */
  uint32_t flags;       /**< SSS_FOLLOW_SURFACE (default on); SSS_ADAPTIVE_TAPS is accepted and ignored */
  /* Appended in 0.1 for the cross-bilateral mode. */
  uint32_t mode;        /**< SSS_MODE_SEPARABLE (default) or SSS_MODE_CROSS_BILATERAL */
  int32_t cbf_taps;     /**< odd, [3, 65]: taps per pass of the cross-bilateral mode. Default 13 */
  float cbf_r_max_mm;   /**< (0, 50] profile millimetres, finite: radius of the footprint sphere (world units:
                             r_max · world_units_per_mm · scale, times alpha). Default 4.5 */
  uint32_t cbf_profile; /**< SSS_PROFILE_MIKKELSEN_2010 (default), an sss_material in [SSS_MATERIAL_SKIN,
                             SSS_MATERIAL_WHOLEMILK] (see sss_profile_transmittance_terms for how each is
                             expressed; a measured material costs a fit, up to ~0.1 s, when first selected), or
                             SSS_PROFILE_KERNEL: the profile of kernel.profile below, read in this mode too (see
                             sss_profile_desc_transmittance_terms; a table is fitted when selected or changed) */
  /* Appended in 0.1 for the kernel families of sss_kernels.h (read by SSS_MODE_SEPARABLE only). */
  sss_kernel_desc kernel; /**< the kernel the passes run, one horizontal and one vertical pass per term
                               (sss_kernel_plan). Default SSS_KERNEL_SEPARABLE: the paper's eq. (1) from
                               strength and falloff above. kernel.taps, .strength and .falloff are never read:
                               samples, strength and falloff above are the filter's, for every family (strength
                               applies to eq. (1) alone; the other families scatter all light their profile
                               does). Every other field is checked against its range on sss_kernel_desc, whatever
                               the family. A tabulated profile's table is copied (the pointers need not outlive the
                               call; sss_get_settings returns pointers to the context's copy, valid until the
                               next sss_set_settings). The fitted families (guided; sum of Gaussians of a
                               measured material) run an optimiser when first selected (see sss_set_settings):
                               tens of ms at 17 taps, up to ~0.7 s for the guided family at 65 */
  float jitter;           /**< [0, 1], finite: the share of each pass's taps, the outermost, that read a pixel of
                               the cell they stand for chosen per pixel by deterministic noise (supplementary
                               Fig. S.6-S.7 use 0.33), where a pixel's kernel spans more pixels than `samples`
                               taps (where it spans fewer, every pixel has a tap and nothing moves): turns the
                               banding of few taps into fine noise, with no temporal filter; the weights stay
                               the cells'. Default 0 */
  /* Appended in 0.1 for the choice of how the passes run. */
  uint32_t path;          /**< SSS_PATH_AUTO (default since 0.2; 0.1: SSS_PATH_FRAGMENT), SSS_PATH_FRAGMENT,
                               SSS_PATH_COMPUTE or SSS_PATH_FRAGMENT_MASKED: how the separable mode's two passes
                               run (see SSS_PATH_*). Every path gives the same image within fp16 rounding */
} sss_settings;

/** The host's stencil marks translucent pixels: translucent where (stencil & mask) == (ref & mask).
 *  The module copies the stencil into its own renderbuffer (never samples or attaches the host's
 *  texture while drawing to it). */
typedef struct sss_stencil {
  uint32_t depth_stencil_texture; /**< GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8, same size, target and sample count
                                       as colour (multisampled: see sss_frame on MSAA) */
  uint32_t ref;                   /**< [0, 255] */
  uint32_t mask;                  /**< [0, 255]; 0 makes every pixel pass */
} sss_stencil;

/* SSS_FRAME_* flags for sss_frame.flags. */
/** Hardware depth was written with glClipControl(..., GL_ZERO_TO_ONE): window depth equals NDC z.
 *  Without it depth = (z_ndc + 1) / 2 (the GL default). glDepthRange is assumed [0, 1]. */
#define SSS_FRAME_DEPTH_ZERO_TO_ONE 0x1u
/** sss_frame.region holds the host's bounding rectangle of the translucent pixels: see there. */
#define SSS_FRAME_REGION 0x2u
/** The host's promise that the texture the passes write (color_texture written back, or
 *  output_texture) is complete: its GL_TEXTURE_MIN_FILTER is GL_NEAREST or GL_LINEAR, or it has every
 *  mip level its filter and GL_TEXTURE_MAX_LEVEL ask for. The compute path (SSS_PATH_COMPUTE, and
 *  SSS_PATH_AUTO's candidate) writes that texture through an image unit, and image stores to an
 *  incomplete texture are undefined (a silent no-op on some drivers). A new texture's default
 *  filter, GL_NEAREST_MIPMAP_LINEAR, makes a texture with level 0 alone incomplete. Without the flag
 *  the module asks the GL (GL_TEXTURE_MIN_FILTER, _BASE_LEVEL, _MAX_LEVEL, _IMMUTABLE_FORMAT) when the
 *  frame does not describe its textures, and takes the default when it does; a texture that may be
 *  incomplete (a mipmap filter, more than one level allowed, mutable storage) sends the frame down
 *  the fragment path: sss_stats.last_frame_path says SSS_PATH_FRAGMENT and the log (INFO) says why.
 *  A wrong promise gives undefined results, never an error. */
#define SSS_FRAME_TARGET_COMPLETE 0x4u
#define SSS_FRAME_ALL_FLAGS 0x7u

/* Values of sss_frame.msaa_depth_resolve: how the MSAA path turns a pixel's sample depths into one
 * depth. Each sample's depth is first converted to linear view distance with the camera. */
#define SSS_MSAA_DEPTH_AVERAGE 0u /**< mean of the samples' linear depths (the paper's choice; default) */
#define SSS_MSAA_DEPTH_SAMPLE0 1u /**< sample 0 alone */
#define SSS_MSAA_DEPTH_MIN 2u     /**< the nearest sample */
#define SSS_MSAA_DEPTH_MAX 3u     /**< the farthest sample */

/** The full form of one application of the filter.
 *
 *  Multisampling (MSAA): color_texture and depth_texture may both be GL_TEXTURE_2D_MULTISAMPLE
 *  with the same sample count (any count up to 32 that the context made; not one multisampled and
 *  the other not). A first pass then resolves them: colour by the box average of the samples,
 *  depth by msaa_depth_resolve of the samples' linear depths. Without a stencil the module marks
 *  its own stencil from the resolved alpha (> 0 exactly when some sample's alpha is > 0), so both
 *  blur passes touch only translucent pixels (the paper's multisampling path); a stencil, if given,
 *  must be multisampled with the same count and is resolved by glBlitFramebuffer (the driver picks
 *  one sample's stencil per pixel). With output_texture 0 the result is written back into the
 *  host's samples: each translucent sample (alpha > 0) of a pixel that changed gets that pixel's
 *  change times samples / translucent samples (so the box resolve equals the blurred pixel),
 *  clamped at 0; every other sample, and alpha everywhere, keeps its exact value. With an output
 *  texture (single-sample) the blurred resolve goes there and untouched pixels get the resolved
 *  colour.
 *  The MSAA path is desktop OpenGL only (it needs GLSL sampler2DMS and glSampleMaski). OpenGL ES 3.0
 *  has no multisampled textures at all (the module never asks for GL_TEXTURE_2D_MULTISAMPLE there);
 *  on OpenGL ES 3.1+ a multisampled input fails with SSS_ERROR_UNSUPPORTED: resolve it to
 *  GL_TEXTURE_2D first there (colour by glBlitFramebuffer, depth as linear view distance). */
typedef struct sss_frame {
  uint32_t struct_size;      /**< sizeof(sss_frame) */
  uint32_t color_texture;    /**< GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA16F or GL_RGBA32F: linear
                                  diffuse irradiance, alpha = strength 0..1 */
  uint32_t depth_texture;    /**< same target, size and sample count as colour: hardware depth (DEPTH_COMPONENT16/24/32/32F,
                                  DEPTH24_STENCIL8, DEPTH32F_STENCIL8) or linear view distance (R16F, R32F) */
  uint32_t output_texture;   /**< 0: write back into color_texture; else GL_TEXTURE_2D (single-sample) RGBA16F/RGBA32F
                                  of the same size, not the colour texture: every pixel is written (untouched ones copied) */
  const sss_stencil *stencil;/**< NULL: the mask is alpha > 0 alone */
  int32_t viewport[4];       /**< x, y, width, height in texels; all 0: the whole texture. Taps never read outside it */
  uint32_t flags;            /**< SSS_FRAME_* */
  /* Texture description (optional on desktop GL and OpenGL ES 3.1+, required on OpenGL ES 3.0).
   * The module asks the GL for each texture's internal format and size (glGetTexLevelParameteriv);
   * OpenGL ES 3.0 has no such query, so there the frame must say what the host allocated: every
   * format of a texture the frame names, and the size. Where the GL can be asked, a value that is
   * given (not 0) is checked against the GL's answer (SSS_ERROR_INVALID_ARGUMENT when they differ)
   * whenever the module asks (not in a steady frame, below).
   * Formats are the GL internal-format values the textures were allocated with; 0 = not given.
   * A frame that gives the size and the format of every texture it names is described: the module
   * then asks the GL nothing about the host texture parameters its passes depend on either
   * (depth_stencil_mode, SSS_FRAME_TARGET_COMPLETE) and takes what the frame does not state at the
   * GL's default for a new texture.
   *
   * GL queries. A frame is steady when it is described and has the same texture names, description,
   * flags and msaa_depth_resolve as the last frame that succeeded, with settings that pick the same
   * kernel, path, mode and follow-surface test, and draws (or, with identity settings or an empty
   * region, does not) as that frame did.
   * A steady frame makes no GL query at all with SSS_CREATE_NO_STATE_RESTORE (no glGet*, glIs*,
   * glGetError or glCheckFramebufferStatus: each is a round trip that stalls a threaded driver
   * such as Mesa's glthread or NVIDIA's threaded optimisation), and with state restore only reads
   * the part of the state list its path can change (docs/integration.md, "Threaded drivers"). It
   * trusts what the last successful frame checked: that a GL context is current and is the same
   * one (after a loss, a re-creation or a switch, call sss_gl_context_changed first), that the
   * textures are what the description says (a texture re-created under the same name and
   * description but with another target or sample count also needs sss_gl_context_changed), that
   * the framebuffers on them are complete; and it reads no GL error flag. Every other frame checks
   * all of it, and with SSS_CREATE_DEBUG_CHECKS every frame does. */
  uint32_t color_format;     /**< 0, 0x881A GL_RGBA16F or 0x8814 GL_RGBA32F */
  uint32_t depth_format;     /**< 0, 0x81A5 GL_DEPTH_COMPONENT16, 0x81A6 _24, 0x81A7 _32, 0x8CAC _32F,
                                  0x88F0 GL_DEPTH24_STENCIL8, 0x8CAD GL_DEPTH32F_STENCIL8, 0x822D GL_R16F, 0x822E GL_R32F */
  uint32_t output_format;    /**< 0, 0x881A GL_RGBA16F or 0x8814 GL_RGBA32F; ignored when output_texture is 0 */
  uint32_t stencil_format;   /**< 0, 0x88F0 GL_DEPTH24_STENCIL8 or 0x8CAD GL_DEPTH32F_STENCIL8; ignored when stencil is NULL */
  int32_t texture_width;     /**< 0 (with texture_height 0), or the width all the textures share, [1, GL_MAX_TEXTURE_SIZE] */
  int32_t texture_height;    /**< 0 (with texture_width 0), or their height, [1, GL_MAX_TEXTURE_SIZE] */
  /* Appended in 0.1 for the cross-bilateral mode (ignored by the separable mode). */
  uint32_t normal_texture;   /**< 0: normals are reconstructed from depth; else GL_TEXTURE_2D, GL_RGBA16F or
                                  GL_RGBA32F, same size: the view-space unit normal in xyz, each in [-1, 1]
                                  (facing the camera: z > 0), w unused. Used only for the footprint's cosine
                                  correction; a zero or non-finite normal means no correction */
  uint32_t normal_format;    /**< 0, 0x881A GL_RGBA16F or 0x8814 GL_RGBA32F: normal_texture's format, like the formats
                                  above (required on OpenGL ES 3.0 when normal_texture is given); ignored when it is 0 */
  uint32_t msaa_depth_resolve; /**< SSS_MSAA_DEPTH_* (multisampled inputs only; default 0 = average) */
  /* Appended in 0.1 to skip what a frame does not need. */
  int32_t region[4];         /**< read only with SSS_FRAME_REGION: x, y, width, height in texels, inside the
                                  viewport, width and height >= 0. The host's promise that no pixel outside
                                  it is translucent (e.g. the projected bounds of its skin meshes). The
                                  passes are drawn over the region alone and their taps never read outside it
                                  (like the viewport's edge: pad the region by the kernel's reach in pixels for
                                  the result of the whole viewport). Width or height 0: nothing is translucent,
                                  and in place nothing is drawn at all (a separate output gets the colour
                                  copied). With a separate output, the viewport outside the region gets the
                                  colour copied (one more draw): writing back costs less */
  /* Appended after 0.2 (docs/migration.md) for the host texture parameters the passes depend on. */
  uint32_t depth_stencil_mode; /**< 0, 0x1902 GL_DEPTH_COMPONENT or 0x1901 GL_STENCIL_INDEX: the
                                  GL_DEPTH_STENCIL_TEXTURE_MODE of depth_texture (read only when it is
                                  GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8). A host that samples its
                                  depth-stencil texture's stencil (GL 4.3+, ES 3.1+) leaves it on
                                  GL_STENCIL_INDEX, and depth fetches then return stencil indices: the
                                  module switches it to GL_DEPTH_COMPONENT for its passes and puts
                                  GL_STENCIL_INDEX back before it returns, on failure too and whatever
                                  SSS_CREATE_NO_STATE_RESTORE says (host texture state). 0: not given; the
                                  module asks the GL (glGetTexParameteriv) when the frame does not describe
                                  its textures, and takes GL_DEPTH_COMPONENT (the default) when it does or
                                  the GL has no such parameter. A given value is taken as it is (not checked
                                  against the GL). Another value: SSS_ERROR_INVALID_ARGUMENT, and so is
                                  GL_STENCIL_INDEX on a GL before 4.3 (ES 3.1) */
} sss_frame;

/* GLSL dialects, negotiated by sss_create (sss_stats.glsl_variant). */
#define SSS_GLSL_330_CORE 0 /**< OpenGL 3.3 to 4.1 */
#define SSS_GLSL_420_CORE 1 /**< OpenGL 4.2+: sampler units bound in the shader (layout(binding)) */
#define SSS_GLSL_300_ES 2   /**< OpenGL ES 3.x: precision qualifiers, depth filtered in the shader */

/* SSS_STATS_* bits of sss_stats.measured: which measurements the numbers below them hold. */
#define SSS_STATS_PIXELS 0x1u   /**< pixels_touched is valid */
#define SSS_STATS_GPU_TIME 0x2u /**< gpu_time_ms is valid */

/** What the context did, for a host's profiler overlay (sss_get_stats). */
typedef struct sss_stats {
  uint32_t struct_size;          /**< sizeof(sss_stats), set by the caller */
  uint32_t glsl_variant;         /**< SSS_GLSL_*: the dialect the shaders were compiled in */
  uint64_t frames;               /**< sss_apply / sss_apply_frame calls that returned SSS_OK */
  uint64_t passes;               /**< full-screen draws over all those frames (blur passes, two per kernel term, and the copies of
                                      stencil-rejected pixels, and for multisampled input the resolve, the stencil
                                      mark and one write per sample; SSS_PATH_FRAGMENT_MASKED adds its stencil mark,
                                      the compute path counts its two dispatches; 0 for an in-place frame with scale
                                      or strength 0) */
  uint32_t last_frame_passes;    /**< full-screen draws of the last successful frame */
  /* GPU measurements (SSS_CREATE_STATS only). Read back without stalling: they come from the
   * latest frame whose queries the GPU had finished when a later sss_apply_frame looked, so they
   * lag the current frame by one or more frames (measured_frame says which). */
  uint32_t measured;             /**< SSS_STATS_* bits: what the measurements below hold; 0 without SSS_CREATE_STATS,
                                      before the first result, or where the GL cannot measure (see below) */
  uint64_t measured_frame;       /**< the frame (1 = the first successful one) the measurements come from; 0: none */
  uint64_t pixels_touched;       /**< pixels the vertical blur pass wrote (GL_SAMPLES_PASSED): in place, exactly the
                                      blurred ones (in the stencil mask, alpha > 0, usable depth); into a separate
                                      output, every pixel of the viewport in the mask. Desktop GL only (OpenGL ES
                                      has no sample count) */
  double gpu_time_ms[2];         /**< GPU time of the horizontal and the vertical pass, each with its copies
                                      (GL_TIME_ELAPSED), >= 0. A kernel of several terms (sss_settings.kernel):
                                      [0] is every pass before the last vertical one, [1] that last pass. Only where timer queries are trustworthy:
                                      GL_QUERY_COUNTER_BITS > 0, on OpenGL ES through GL_EXT_disjoint_timer_query
                                      (a disjoint event voids the results it spans), and not on Mesa's software
                                      rasterisers (llvmpipe, softpipe: their GL_TIME_ELAPSED covers one tile) */
  uint32_t last_frame_path;      /**< SSS_PATH_FRAGMENT, _FRAGMENT_MASKED or _COMPUTE: how the last successful frame's passes ran
                                      (what sss_settings.path asked for, SSS_PATH_AUTO's choice, or SSS_PATH_FRAGMENT
                                      where the path asked for cannot run that frame) */
} sss_stats;

/** Short English name of a status code ("SSS_ERROR_INVALID_TEXTURE"); never NULL. */
SSS_API const char *sss_result_string(sss_result r);

/** The message of the last failure of a call on `ctx` (owned by the context, valid until the next
 *  call on it); with ctx NULL, the last failure on this thread of a call that had no context
 *  (sss_create, or any call given a NULL context). "" when there was none. Never NULL. */
SSS_API const char *sss_last_error(const sss_context *ctx);

/** Creates a context. Needs a current GL context: OpenGL 3.3 or newer (core or compatibility) or
 *  OpenGL ES 3.0 or newer; compiles the shaders and builds the GL objects the module owns in it.
 *  The GLSL dialect is chosen from GL_VERSION ("OpenGL ES 3.x ..." is ES) and logged at INFO with
 *  the renderer (sss_stats.glsl_variant gives it too):
 *    OpenGL 3.3..4.1  GLSL 330 core;
 *    OpenGL 4.2+      GLSL 420 core, sampler units bound in the shader (no glUniform1i per sampler);
 *    OpenGL ES 3.x    GLSL ES 300 with highp precision; depth is filtered in the shader (ES cannot
 *                     filter depth textures). ES needs GL_EXT_color_buffer_float or
 *                     GL_EXT_color_buffer_half_float (the RGBA16F intermediate is rendered to);
 *                     RGBA32F colour or output textures need GL_EXT_color_buffer_float, and RGBA32F
 *                     colour also GL_OES_texture_float_linear (checked by sss_apply_frame). On ES 3.0
 *                     the frame must describe its textures (sss_frame's format and size fields).
 *  @retval SSS_OK                        *out holds the new context
 *  @retval SSS_ERROR_INVALID_ARGUMENT    desc or out NULL, bad struct_size, NULL get_proc_address, unknown flags
 *  @retval SSS_ERROR_NO_CONTEXT          no GL context is current (glGetString(GL_VERSION) gave NULL)
 *  @retval SSS_ERROR_UNSUPPORTED         the GL version is below 3.3 (ES: below 3.0), or OpenGL ES without
 *                                        GL_EXT_color_buffer_float / _half_float (named in the message)
 *  @retval SSS_ERROR_GL_FUNCTION_MISSING a needed GL function could not be loaded (named in the message)
 *  @retval SSS_ERROR_SHADER_COMPILE      an embedded shader failed (driver log in the message)
 *  @retval SSS_ERROR_OUT_OF_MEMORY       allocation failed
 *  On failure *out is set to NULL (when out is not NULL) and nothing is left in the GL. */
SSS_API sss_result sss_create(const sss_create_desc *desc, sss_context **out);

/** Deletes the context's GL objects (its GL context must be current) and frees it. NULL is a no-op.
 *  When the GL context the module was created in is gone (lost or destroyed) and another is current,
 *  nothing is deleted there (the names could be the host's objects): the module's objects went with
 *  their context. */
SSS_API void sss_destroy(sss_context *ctx);

/** Fills *s with the defaults documented on sss_settings (struct_size set). NULL is a no-op. */
SSS_API void sss_default_settings(sss_settings *s);

/** The legacy conversion: world_units_per_mm for the paper's (and sss 0.1's) `width`, with which one
 *  millimetre of the profile spanned (2/3)·width world units: returns (2/3)·width. (0.1's
 *  sss_width_for_world_units_per_mm, 1.5 × world units per mm, is gone: world_units_per_mm is set
 *  directly now.) */
SSS_API float sss_world_units_per_mm_from_legacy_width(float width);

/** Sets the eq. (1) kernel of *s to the paper's Table 1 (strength .78 .70 .75, falloff .57 .13 .08)
 *  with the separable_scale fitted for it against d'Eon's skin (docs/kernel-fits.md), so that Table 1 too is physical skin size at scale 1. Other fields are kept.
 *  NULL is a no-op. */
SSS_API void sss_settings_separable_table1(sss_settings *s);

/** Validates and takes the settings; a kernel is rebuilt only when its inputs change. Does not call GL.
 *  The fitted kernels (the guided family; a sum of Gaussians, a cross-bilateral profile or a table
 *  of a measured material) run an optimiser here and in no other call of this header: from a
 *  millisecond to ~0.7 s (the guided family at 65 taps; logged at SSS_LOG_DEBUG with the time), so
 *  set them at load time. The
 *  last four kernels that cost a fit are kept: settings that go back to one take it without fitting.
 *  Then sss_prepare gets the programs and targets of the new settings ready before the next frame.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or s NULL, struct_size, world_units_per_mm, scale, strength, falloff,
 *                                     separable_scale, samples, flags,
 *                                     mode, cbf_taps, cbf_r_max_mm, cbf_profile, jitter, path (0..3) or a field of kernel
 *                                     (any but taps, strength and falloff, which are not read) outside
 *                                     its range (every field is checked, whatever the mode and family); a
 *                                     profile that integrates to 0 in a channel for a family that needs its
 *                                     energy; the old settings stay
 *  @retval SSS_ERROR_OUT_OF_MEMORY    building a kernel (a measured material's fit, the cross-bilateral kernel)
 *                                     could not allocate; the old settings stay */
SSS_API sss_result sss_set_settings(sss_context *ctx, const sss_settings *s);

/** Current settings into *s (struct_size must be set by the caller).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or s NULL, or s->struct_size too small */
SSS_API sss_result sss_get_settings(const sss_context *ctx, sss_settings *s);

/** The camera's projection matrix, column-major as glUniformMatrix4fv takes it (m[12..14] is the
 *  translation column). Perspective (finite or infinite far plane, off-centre, reversed-Z) and
 *  orthographic matrices are accepted. Does not call GL.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or projection NULL, a non-finite element, or a singular matrix
 *                                     (depth cannot be linearised, or a zero x/y scale); the old camera stays
 *  @retval SSS_ERROR_UNSUPPORTED      w depends on x or y (m[3], m[7] not 0) or x/y are sheared (m[1], m[4] not 0) */
SSS_API sss_result sss_set_camera(sss_context *ctx, const float projection[16]);

/** Blurs `color_texture` in place: sss_apply_frame with output 0, the whole texture, default depth.
 *  Same return codes as sss_apply_frame. On OpenGL ES 3.0 it always fails with
 *  SSS_ERROR_INVALID_ARGUMENT (the textures cannot be described): use sss_apply_frame there. */
SSS_API sss_result sss_apply(sss_context *ctx, uint32_t color_texture, uint32_t depth_texture,
                             const sss_stencil *stencil);

/** Runs the two passes: horizontal from the colour texture into the module's RGBA16F target,
 *  vertical into the output (or back into the colour texture); multisampled inputs get a resolve
 *  pass first and, written back, a per-sample write last (see sss_frame). Pixels outside the stencil or with
 *  alpha 0 keep their exact input value. Needs the GL context current that the module was created in.
 *  Non-finite input never spreads: a pixel whose colour or alpha is NaN or infinite keeps its value,
 *  and a neighbour that is counts as the centre's colour (its weight goes to the centre). Alpha
 *  above 1 counts as 1.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT   ctx or frame NULL, bad struct_size, flags, viewport, stencil ref/mask,
 *                                       with SSS_FRAME_REGION a region field negative or the region reaching
 *                                       outside the viewport,
 *                                       msaa_depth_resolve above SSS_MSAA_DEPTH_MAX, depth_stencil_mode outside its
 *                                       list (or GL_STENCIL_INDEX on a GL without that mode), or output_texture equal to
 *                                       color_texture; a texture description field outside its list, a size
 *                                       given alone, above GL_MAX_TEXTURE_SIZE, or one that differs from the
 *                                       GL's answer; on OpenGL ES 3.0 a description missing
 *  @retval SSS_ERROR_UNSUPPORTED        OpenGL ES: an RGBA32F colour or output texture without the extension it
 *                                       needs (named in the message; see sss_create), or a multisampled input
 *                                       (ES 3.1+; the MSAA path is desktop GL only, see sss_frame)
 *  @retval SSS_ERROR_INVALID_OPERATION  no camera set yet
 *  @retval SSS_ERROR_NO_CONTEXT         no GL context current; or the current one does not hold the module's GL
 *                                       objects: the context the module was created in was lost or destroyed
 *                                       (or another one is current). Nothing is drawn or changed; the objects
 *                                       are forgotten (not deleted: their names may be the host's now) and the
 *                                       next call rebuilds them in the context current then, so a host that
 *                                       recreates its context after a loss just carries on. A steady frame
 *                                       does not look (see sss_frame): call sss_gl_context_changed first
 *  @retval SSS_ERROR_INVALID_TEXTURE    a name that is 0 or not a texture, neither GL_TEXTURE_2D nor
 *                                       GL_TEXTURE_2D_MULTISAMPLE (or a multisampled output or normal texture), a
 *                                       texture without storage, a format outside the lists on sss_frame, sizes that
 *                                       differ (normal_texture included, whatever the mode), or colour, depth and
 *                                       stencil that differ in target or sample count
 *  @retval SSS_ERROR_UNSUPPORTED        a sample count above 32 or above the context's GL_MAX_COLOR_TEXTURE_SAMPLES /
 *                                       GL_MAX_DEPTH_TEXTURE_SAMPLES
 *  @retval SSS_ERROR_FRAMEBUFFER        the driver rejected a framebuffer built on the given textures (checked
 *                                       when a frame is not steady, or with SSS_CREATE_DEBUG_CHECKS)
 *  @retval SSS_ERROR_OUT_OF_MEMORY      the intermediate target could not be allocated
 *  @retval SSS_ERROR_GL                 the GL raised an error during the passes (named in the message; read
 *                                       when a frame is not steady, or with SSS_CREATE_DEBUG_CHECKS): found
 *                                       after the draws began, so the target (colour written back, or the output)
 *                                       may be partly written and its content is undefined until a frame succeeds
 *                                       (the message says so); GL state and the depth texture's mode are restored
 *  @retval SSS_ERROR_SHADER_COMPILE    a shader variant first needed by this frame did not compile (retried by
 *                                       the next call that needs it)
 *  Every check, shader build and allocation that can fail runs before the first draw into a host texture, so
 *  on any failure but SSS_ERROR_GL raised by the passes the host's textures are unchanged. On any failure the
 *  GL state is restored and no GL error is left pending; the next call starts afresh (nothing the failed call
 *  did has to be undone by the host). */
SSS_API sss_result sss_apply_frame(sss_context *ctx, const sss_frame *frame);

/** Tells the module that the GL context current for its next call may not be the one of its last
 *  call: the host re-created it after a loss, or made another one current. The next sss_apply_frame
 *  then checks, even when the frame is steady (see "GL queries" on sss_frame), that a context is
 *  current and holds the module's objects (SSS_ERROR_NO_CONTEXT and a rebuild when it does not, as
 *  documented there). Only a steady frame needs this: every other frame checks by itself. Does not
 *  call GL.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx is NULL */
SSS_API sss_result sss_gl_context_changed(sss_context *ctx);

/** Counters and the latest GPU measurements of the context (see sss_stats). Does not call GL. A
 *  measurement is skipped for a frame when the host has a query of the same target active around
 *  sss_apply (GL allows one per target), or when every slot of the module's small ring of query
 *  objects is still waiting for the GPU.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or stats NULL, or stats->struct_size is not sizeof(sss_stats) */
SSS_API sss_result sss_get_stats(const sss_context *ctx, sss_stats *stats);

/* SSS_PREPARE_* flags for sss_prepare_desc.flags. */
/** The frames will give sss_frame.normal_texture (the cross-bilateral mode's normals variant). */
#define SSS_PREPARE_NORMALS 0x1u
/** The frames will set SSS_FRAME_REGION (accepted for completeness: a region needs no program or
 *  target of its own, so this changes nothing prepared today). */
#define SSS_PREPARE_REGION 0x2u
/** Multisampled colour made with fixedsamplelocations GL_FALSE (the MSAA path's copy of the samples
 *  is made like the host's texture); read only when samples > 1. */
#define SSS_PREPARE_UNFIXED_SAMPLE_LOCATIONS 0x4u
#define SSS_PREPARE_ALL_FLAGS 0x7u

/** The frames sss_prepare gets ready for: what sss_apply_frame would learn from the textures.
 *  Formats are the GL internal-format values, as in sss_frame's description fields. */
typedef struct sss_prepare_desc {
  uint32_t struct_size;    /**< sizeof(sss_prepare_desc) */
  int32_t width, height;   /**< the colour texture's size, each in [1, GL_MAX_TEXTURE_SIZE] */
  uint32_t color_format;   /**< 0x881A GL_RGBA16F or 0x8814 GL_RGBA32F (required) */
  uint32_t output_format;  /**< 0: written back in place (output_texture 0); else the separate output's format,
                                0x881A GL_RGBA16F or 0x8814 GL_RGBA32F */
  uint32_t depth_format;   /**< required, one of sss_frame.depth_format's list: hardware depth (0x81A5, 0x81A6,
                                0x81A7, 0x8CAC, 0x88F0, 0x8CAD) or linear view distance (0x822D GL_R16F,
                                0x822E GL_R32F) */
  int32_t samples;         /**< 0 or 1: single-sample textures; [2, 32]: multisampled colour and depth (desktop GL,
                                at most GL_MAX_COLOR_TEXTURE_SAMPLES) with exactly the count the GL gave them
                                (GL_TEXTURE_SAMPLES: a driver may round a count up) */
  uint32_t stencil_format; /**< 0: no host stencil (sss_frame.stencil NULL); else the host's depth-stencil
                                format, 0x88F0 GL_DEPTH24_STENCIL8 or 0x8CAD GL_DEPTH32F_STENCIL8 */
  uint32_t flags;          /**< SSS_PREPARE_* */
} sss_prepare_desc;

/** Gets the context ready for frames like `desc` with the current settings, so that the first
 *  sss_apply_frame of such a frame compiles no shader and allocates no GL object ("no hitch").
 *  Builds every program variant those frames can need with the settings as they are now (each path
 *  sss_settings.path lets a frame take: the plain fragment passes, the masked ones, the compute
 *  dispatches where the GL has them (4.3+ desktop), all three for SSS_PATH_AUTO; the
 *  cross-bilateral variants in that mode; the MSAA resolve, stencil mark and per-sample write for
 *  samples > 1; the variants of every kernel term), and allocates the render targets for that
 *  size (the intermediate, the sum of several kernel terms, the stencil copy or mask, the masked
 *  colour copy, the MSAA targets). Call it at load time after sss_set_settings, again after each
 *  sss_set_settings that changes the mode, the path, the kernel or follow-surface, and after a
 *  resize (a frame of another size or format reallocates then, as without this call). Calling it
 *  again with nothing changed does nothing. Kernel fits never run here or in any per-frame call:
 *  sss_set_settings runs them (see there). Needs the GL context current that the module was created
 *  in; saves and restores the GL state like sss_apply_frame. Needs no camera.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or desc NULL, bad struct_size, width or height outside [1,
 *                                     GL_MAX_TEXTURE_SIZE], color_format, output_format, depth_format or
 *                                     stencil_format outside its list, samples negative or above 32, unknown
 *                                     flags; nothing is built or allocated
 *  @retval SSS_ERROR_UNSUPPORTED      samples > 1 on OpenGL ES (the MSAA path is desktop GL only) or above
 *                                     GL_MAX_COLOR_TEXTURE_SAMPLES / GL_MAX_DEPTH_TEXTURE_SAMPLES; OpenGL ES: an
 *                                     RGBA32F colour or output format without the extension it needs (as
 *                                     sss_apply_frame); nothing is built or allocated
 *  @retval SSS_ERROR_NO_CONTEXT       as sss_apply_frame
 *  @retval SSS_ERROR_SHADER_COMPILE   a variant did not compile (driver log in the message)
 *  @retval SSS_ERROR_OUT_OF_MEMORY    a target could not be allocated
 *  @retval SSS_ERROR_GL               the GL raised an error (named in the message)
 *  After a failure what was built stays built and the frames still work: each builds what it lacks. */
SSS_API sss_result sss_prepare(sss_context *ctx, const sss_prepare_desc *desc);

/* ---- GL-free kernel API (math layer): usable without any GL context. ----
 * The pre-integrated skin LUTs (sss_lut_*) are declared in <sss/sss_lut.h>, which includes this header. */

/** Fills `samples` taps of the separable kernel of the paper's eq. (1) into out_rgba as
 *  {weight r, weight g, weight b, offset in profile millimetres}: the centre tap first, then the
 *  others from the most negative offset to the most positive. Offsets span [-R, R] with R = 2 mm for
 *  samples <= 20 and 3 mm above, quadratically denser at the centre; each weight is the profile
 *  integrated exactly over the tap's interval, normalised per channel, then strength applied
 *  (centre: 1 - s + s·w0; others: s·w). Each channel sums to 1.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT samples even or outside [3, 65], a NULL pointer, strength or falloff
 *                                     outside [0, 1] or not finite */
SSS_API sss_result sss_kernel_separable(int32_t samples, const float strength[3], const float falloff[3],
                                        float *out_rgba);


#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_H */
