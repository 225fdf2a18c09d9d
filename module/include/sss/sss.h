/*
 * sss: screen-space subsurface scattering for OpenGL hosts. The runtime API (C99, no GL header:
 * GL names are uint32_t, formats the GL enum values). The research tools (kernel families,
 * profiles, fits, transmittance terms) are in <sss/sss_tools.h>, the skin LUTs in <sss/sss_lut.h>;
 * this header includes neither. Reference and host guide: docs/integration.md.
 *
 * sss-h-example: begin
 *   #include <sss/sss.h>
 *   // Load time, GL context (3.3+ or ES 3.0+) current:
 *   sss_context *engine_sss_init(sss_get_proc_address_fn load, void *load_user, int w, int h) {
 *     sss_create_desc desc = {0};
 *     sss_settings settings;
 *     sss_prepare_desc prepare = {0};
 *     sss_context *sss = NULL;
 *     desc.struct_size = sizeof desc;
 *     desc.get_proc_address = load; desc.get_proc_address_user = load_user;
 *     if (sss_create(&desc, &sss) != SSS_OK) return NULL; // sss_last_error(NULL) says why
 *     sss_default_settings(&settings);      // d'Eon's skin at its measured size
 *     settings.world_units_per_mm = 0.001f; // scene in metres
 *     if (sss_set_settings(sss, &settings) != SSS_OK) { sss_destroy(sss); return NULL; }
 *     prepare.struct_size = sizeof prepare;
 *     prepare.width = w; prepare.height = h;
 *     prepare.color_format = 0x881A; // GL_RGBA16F
 *     prepare.depth_format = 0x88F0; // GL_DEPTH24_STENCIL8
 *     sss_prepare(sss, &prepare);     // compile and allocate now, not in the first frame
 *     return sss;
 *   }
 *   // Every frame, after diffuse lighting, before specular and tone mapping:
 *   int engine_sss_frame(sss_context *sss, const float projection[16], uint32_t diffuse,
 *                        uint32_t depth, int w, int h) {
 *     sss_frame frame = {0};
 *     sss_stats stats;
 *     frame.struct_size = sizeof frame;
 *     frame.color_texture = diffuse; // linear diffuse light x albedo, alpha = SSS strength
 *     frame.depth_texture = depth;
 *     frame.color_format = 0x881A;   // described textures: a steady frame asks the GL nothing
 *     frame.depth_format = 0x88F0; frame.texture_width = w; frame.texture_height = h;
 *     if (sss_set_camera(sss, projection) != SSS_OK) return 0; // column-major
 *     if (sss_apply_frame(sss, &frame) != SSS_OK) return 0;    // blurred in place
 *     stats.struct_size = sizeof stats; sss_get_stats(sss, &stats); // e.g. stats.last_frame_path
 *     return 1;
 *   }
 *   void engine_sss_shutdown(sss_context *sss) { sss_destroy(sss); } // same GL context current
 * sss-h-example: end
 *
 * Threads: a context lives on its GL context's thread; contexts share nothing. Errors: an sss_result and
 * sss_last_error naming the bad argument. struct_size: this release's sizeof or a 0.1/0.2 size (missing
 * fields take defaults; old sss_settings are converted); others fail naming the struct and size.
 *
 * GL state (SSS_STATE_LIST; docs/integration.md details it): a call that draws restores what it changed
 * (unless SSS_CREATE_NO_STATE_RESTORE) and leaves no GL error: program, vertex array, draw and read
 * framebuffers, renderbuffer, active texture; on units 0-5 the 2D and 2D-multisample texture and sampler;
 * uniform buffer binding 0 and the generic one; the unpack buffer and alignment/row length/skips (pack
 * state too under SSS_CREATE_DEBUG_CHECKS); image units 0 and 1; viewport; sample mask word 0; the enables
 * SCISSOR, DEPTH, STENCIL, BLEND, CULL_FACE, FRAMEBUFFER_SRGB, RASTERIZER_DISCARD, SAMPLE_ALPHA_TO_COVERAGE,
 * SAMPLE_COVERAGE, SAMPLE_MASK, POLYGON_OFFSET_FILL, DEPTH_CLAMP, COLOR_LOGIC_OP, CLIP_DISTANCE0-7,
 * MULTISAMPLE; colour mask (buffer 0); blend func/equation (buffer 0; MSAA); polygon mode; front/back stencil;
 * depth func, write mask and range; the depth texture's DEPTH_STENCIL_TEXTURE_MODE. On ES what exists there.
 * Untouched: scissor box, clear values, other bindings, texture parameters. No transform feedback/conditional render.
 */
#ifndef SSS_SSS_H
#define SSS_SSS_H

#include "sss_common.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sss_context sss_context;
typedef void *(*sss_get_proc_address_fn)(const char *name, void *user); /**< GL loader: eglGetProcAddress... */
typedef enum sss_log_level { SSS_LOG_ERROR, SSS_LOG_WARNING, SSS_LOG_INFO, SSS_LOG_DEBUG } sss_log_level;
typedef void (*sss_log_fn)(int level, const char *message, void *user); /**< level: an sss_log_level */

typedef enum sss_create_flag { /* sss_create_desc.flags */
  SSS_CREATE_NO_STATE_RESTORE = 0x1, /**< the host restores GL state itself: no state queries */
  SSS_CREATE_NO_DEBUG_LABELS = 0x2, SSS_CREATE_STATS = 0x4, /**< no KHR_debug; GPU measurements in sss_stats */
  SSS_CREATE_DEBUG_CHECKS = 0x8 /**< check textures, framebuffers, profile indices, glGetError every frame */ } sss_create_flag;
#define SSS_CREATE_ALL_FLAGS 0xFu

typedef struct sss_create_desc {
  uint32_t struct_size;                     /**< sizeof(sss_create_desc) */
  sss_get_proc_address_fn get_proc_address; void *get_proc_address_user; /**< required; its user pointer */
  sss_log_fn log; void *log_user; uint32_t flags; /**< optional; sss_create_flag bits */ } sss_create_desc;

/** One profile-ID space for every profile the module knows (settings, LUTs, tools, per-pixel ids). */
typedef enum sss_profile {
  SSS_PROFILE_SKIN_DEON = 0, /**< d'Eon-Luebke six-Gaussian skin */
  SSS_PROFILE_APPLE = 1, SSS_PROFILE_CHICKEN1, SSS_PROFILE_CHICKEN2, SSS_PROFILE_CREAM, SSS_PROFILE_KETCHUP,
  SSS_PROFILE_MARBLE, SSS_PROFILE_POTATO, SSS_PROFILE_SKIMMILK, SSS_PROFILE_SKIN1, SSS_PROFILE_SKIN2,
  SSS_PROFILE_WHOLEMILK = 11,      /**< 1..11: Jensen et al. 2001's measured dipoles */
  SSS_PROFILE_TABULATED = 12,      /**< the caller's table (sss_tools.h sss_profile_desc only) */
  SSS_PROFILE_MIKKELSEN_2010 = 13, /**< spike + one Gaussian per channel (cross-bilateral default) */
  SSS_PROFILE_KERNEL = 14, SSS_PROFILE_BURLEY = 15 /**< 14: cbf_profile only (settings.kernel's); 15: Burley, as 12 */
} sss_profile;
#define SSS_PROFILE_COUNT 16

typedef enum sss_mode { SSS_MODE_SEPARABLE = 0, SSS_MODE_CROSS_BILATERAL = 1 } sss_mode; /**< paper; Mikkelsen 2010 */
/** How the separable passes run; 0-3 give the same image within fp16 rounding. */
typedef enum sss_path {
  SSS_PATH_FRAGMENT = 0, SSS_PATH_COMPUTE = 1, /**< two full-screen fragment passes; compute (GL 4.3+) else fragment */
  SSS_PATH_AUTO = 2,           /**< the fastest that can run the frame (timed where timers are trustworthy); default */
  SSS_PATH_FRAGMENT_MASKED = 3, /**< fragment, its draws kept to 16x16 tiles holding alpha > 0 (cheap on sparse) */
  SSS_PATH_HALF_RESOLUTION = 4 /**< 0.4: half size where kernels are wide; not the same image (guide §18) */
} sss_path;
#define SSS_FOLLOW_SURFACE 0x1u /**< sss_settings.flags: fade taps across depth steps (§3.2). Default on */
#define SSS_AUTO_HALF_RESOLUTION 0x4u /**< flags: SSS_PATH_AUTO may pick SSS_PATH_HALF_RESOLUTION (timed). Off */
#define SSS_SETTINGS_ALL_FLAGS 0x5u

struct sss_kernel_desc; /* sss_tools.h */
/** Filter settings; fill with sss_default_settings. Scene scale: world units per millimetre. */
typedef struct sss_settings {
  uint32_t struct_size;     /**< sizeof(sss_settings) (or an earlier release's size, converted) */
  float world_units_per_mm; /**< [0, 1e6]: 0.001 metres (default), 0.1 cm, 1 mm; 0 = no blur */
  float scale;              /**< [0, 1e3]: scattering distance multiplier; 1 = physical (default) */
  float strength[3];        /**< [0, 1]: scattered share per channel. Default: the calibrated fit */
  float falloff[3];         /**< [0, 1]: profile radius per channel. Default: the calibrated fit */
  float separable_scale;    /**< (0, 100]: kernel mm per surface mm of eq. (1). Default: calibrated */
  int32_t taps;             /**< odd, [SSS_MIN_TAPS, SSS_MAX_TAPS]: most taps per pass. Default 17 */
  uint32_t flags;           /**< SSS_FOLLOW_SURFACE, SSS_AUTO_HALF_RESOLUTION */
  uint32_t mode;            /**< sss_mode. Default SSS_MODE_SEPARABLE */
  int32_t cbf_taps;         /**< odd, [3, 65]: most taps per pass of the cross-bilateral mode. Default 13 */
  float cbf_r_max_mm;       /**< (0, 50]: cross-bilateral footprint radius in profile mm. Default 4.5 */
  uint32_t cbf_profile;     /**< cross-bilateral sss_profile (measured/KERNEL need sss_tools_init). Default MIKKELSEN_2010 */
  const struct sss_kernel_desc *kernel; /**< NULL: eq. (1) from the above (default); else a sss_tools.h kernel (copied) */
  float jitter;             /**< [0, 1]: share of the outer taps jittered per pixel. Default 0 */
  uint32_t path;            /**< sss_path. Default SSS_PATH_AUTO (before 0.3: SSS_PATH_FRAGMENT) */
} sss_settings;

typedef struct sss_stencil { /* host stencil: translucent where (stencil & mask) == (ref & mask) */
  uint32_t depth_stencil_texture; /**< GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8, like colour */
  uint32_t ref, mask; /**< [0, 255] */ } sss_stencil;

typedef enum sss_frame_flag /* sss_frame.flags */ {
  SSS_FRAME_DEPTH_ZERO_TO_ONE = 0x1, SSS_FRAME_REGION = 0x2, /**< glClipControl 0..1 depth; frame.region is set */
  SSS_FRAME_TARGET_COMPLETE = 0x4 /**< written texture is complete (no mipmap filter): GL 4.3+ binds it as an image */ } sss_frame_flag;
#define SSS_FRAME_ALL_FLAGS 0x7u
/** How MSAA sample depths become one (linear) depth: mean (default), sample 0, nearest, farthest. */
typedef enum sss_msaa_depth { SSS_MSAA_DEPTH_AVERAGE, SSS_MSAA_DEPTH_SAMPLE0, SSS_MSAA_DEPTH_MIN,
                              SSS_MSAA_DEPTH_MAX } sss_msaa_depth;

/** One application. A frame giving its size and every named texture's format is described; one equal
 *  to the last successful frame is steady and makes no GL query without state restore (after a
 *  context loss or texture re-creation call sss_gl_context_changed). MSAA inputs: desktop GL. */
typedef struct sss_frame {
  uint32_t struct_size;       /**< sizeof(sss_frame) */
  uint32_t color_texture;     /**< 2D or 2D-multisample RGBA16F/RGBA32F (32F stays float): diffuse, alpha = strength */
  uint32_t depth_texture;     /**< same size/target: hardware depth or linear view distance (R16F/R32F) */
  uint32_t output_texture;    /**< 0: in place; else a single-sample RGBA16F/RGBA32F of the same size */
  const sss_stencil *stencil; /**< NULL: translucent where alpha > 0 */
  int32_t viewport[4];        /**< x, y, w, h in texels; all 0 = whole texture */
  uint32_t flags;             /**< sss_frame_flag bits */
  uint32_t color_format;      /**< 0, 0x881A RGBA16F, 0x8814 RGBA32F, 0x8C3A R11F_G11F_B10F (only with a
                                   strength_texture); required on ES 3.0, as all these formats */
  uint32_t depth_format;      /**< 0, 0x81A5/0x81A6/0x81A7/0x8CAC DEPTH16/24/32/32F, 0x88F0, 0x8CAD, 0x822D, 0x822E */
  uint32_t output_format;     /**< 0, 0x881A, 0x8814 */
  uint32_t stencil_format;    /**< 0, 0x88F0, 0x8CAD */
  int32_t texture_width, texture_height; /**< 0 or the textures' shared size */
  uint32_t normal_texture;    /**< cross-bilateral: 0 or view-space normals (RGBA16F/32F) */
  uint32_t normal_format;     /**< 0, 0x881A, 0x8814 */
  uint32_t msaa_depth_resolve; /**< sss_msaa_depth. Default average */
  int32_t region[4];          /**< with SSS_FRAME_REGION: x, y, w, h inside the viewport */
  uint32_t depth_stencil_mode; /**< 0, 0x1902 GL_DEPTH_COMPONENT or 0x1901 GL_STENCIL_INDEX (the host's) */
  uint32_t strength_texture;  /**< 0: alpha is strength; else 2D R8/R16F/R32F: red = strength, alpha unused */
  uint32_t strength_format;   /**< 0, 0x8229 R8, 0x822D R16F, 0x822E R32F */
  uint32_t profile_texture, profile_format; /**< 0, or 2D R8UI (0x8232)/R16UI (0x8234): value & 15 the profile
                                   (sss_set_profiles), value >> 4 an object; taps of another value are not taken */
} sss_frame;

typedef enum sss_prepare_flag { /* frames give normal_texture; SSS_FRAME_REGION; MSAA without fixed locations */
  SSS_PREPARE_NORMALS = 0x1, SSS_PREPARE_REGION = 0x2, SSS_PREPARE_UNFIXED_SAMPLE_LOCATIONS = 0x4 } sss_prepare_flag;
#define SSS_PREPARE_ALL_FLAGS 0x7u
/** The frames sss_prepare gets ready for (formats as in sss_frame). */
typedef struct sss_prepare_desc {
  uint32_t struct_size;  /**< sizeof(sss_prepare_desc) */
  int32_t width, height; /**< [1, GL_MAX_TEXTURE_SIZE] */
  uint32_t color_format, output_format, depth_format; /**< colour and depth required; output 0 = in place */
  int32_t samples;         /**< MSAA sample count: 0 or 1 single-sample, [2, 32] multisampled */
  uint32_t stencil_format, flags; /**< 0: no host stencil; sss_prepare_flag bits */
  uint32_t strength_format; /**< 0: no strength texture; else as sss_frame (then samples 0 or 1) */
  uint32_t profile_format;  /**< 0: no profile texture; else as sss_frame (then samples 0 or 1) */
} sss_prepare_desc;

typedef enum sss_glsl { SSS_GLSL_330_CORE = 0, SSS_GLSL_420_CORE = 1, SSS_GLSL_300_ES = 2 } sss_glsl;
typedef enum sss_stats_flag { SSS_STATS_PIXELS = 0x1, SSS_STATS_GPU_TIME = 0x2 } sss_stats_flag; /**< valid fields */
/** Counters, and with SSS_CREATE_STATS GPU measurements read back without stalling (a frame or more old). */
typedef struct sss_stats {
  uint32_t struct_size;       /**< set by the caller */
  uint32_t glsl_variant;      /**< sss_glsl */
  uint64_t frames, passes;    /**< successful frames; draws and dispatches over them */
  uint32_t last_frame_passes, measured; /**< draws of the last frame; sss_stats_flag bits */
  uint64_t measured_frame;    /**< the frame the measurements come from (1 = first); 0 none */
  uint64_t pixels_touched;    /**< pixels the vertical pass wrote (desktop GL) */
  double gpu_time_ms[2];      /**< horizontal, vertical pass */
  uint32_t last_frame_path;   /**< sss_path that ran */
} sss_stats;

SSS_API const char *sss_result_string(sss_result r); /**< "SSS_ERROR_INVALID_TEXTURE"; never NULL */
/** The last failure's message on ctx (NULL: on this thread, for calls without a context). Never NULL. */
SSS_API const char *sss_last_error(const sss_context *ctx);

/** Compiles the shaders in the current GL context. @return OK; INVALID_ARGUMENT (desc, out, struct_size,
 *  get_proc_address, flags); NO_CONTEXT; UNSUPPORTED (GL < 3.3, ES < 3.0 or without float render targets);
 *  GL_FUNCTION_MISSING; SHADER_COMPILE; OUT_OF_MEMORY. On failure *out is NULL and nothing is left in the GL. */
SSS_API sss_result sss_create(const sss_create_desc *desc, sss_context **out);
SSS_API void sss_destroy(sss_context *ctx); /**< deletes its GL objects (same context current); NULL: no-op */
SSS_API void sss_default_settings(sss_settings *s); /**< the defaults, struct_size = sizeof; NULL: no-op */
/** Validates and takes *s (one profile); no GL. Kernels are built here, never per frame (a fit up to ~0.7 s).
 *  @return OK; INVALID_ARGUMENT (a field out of range, named); UNSUPPORTED (needs the tools library:
 *  sss_tools_init not called); OUT_OF_MEMORY. On failure the old settings stay. */
SSS_API sss_result sss_set_settings(sss_context *ctx, const sss_settings *s);
#define SSS_MAX_PROFILES 16
/** Per-pixel profiles: profiles[i] for pixels of sss_frame.profile_texture index i, all in one pass pair.
 *  Each may differ in world_units_per_mm, scale, strength, falloff, separable_scale and kernel (one term
 *  when count > 1); the other fields must equal profiles[0]'s, which becomes the settings (sss_set_settings
 *  is count 1). Indices >= count are left alone (refused under SSS_CREATE_DEBUG_CHECKS). No GL.
 *  @return OK; INVALID_ARGUMENT (count outside [1, SSS_MAX_PROFILES], profiles[i].field named); UNSUPPORTED
 *  (several terms or cross-bilateral with count > 1; count over the GL's uniform block). Else all kept. */
SSS_API sss_result sss_set_profiles(sss_context *ctx, const sss_settings *profiles, uint32_t count);
/** The current settings into *s; s->struct_size selects the layout written (this or an earlier release's).
 *  settings.kernel points at the context's copy until the next sss_set_settings. @return OK; INVALID_ARGUMENT */
SSS_API sss_result sss_get_settings(const sss_context *ctx, sss_settings *s);
/** Projection matrix, column-major (perspective, reversed-Z, infinite or orthographic). No GL.
 *  @return OK; INVALID_ARGUMENT (NULL, non-finite, singular); UNSUPPORTED (sheared, w from x/y) */
SSS_API sss_result sss_set_camera(sss_context *ctx, const float projection[16]);
/** Compiles and allocates all that frames like *desc need with the current settings (no hitch later).
 *  @return OK; INVALID_ARGUMENT; UNSUPPORTED; NO_CONTEXT; SHADER_COMPILE; OUT_OF_MEMORY; GL */
SSS_API sss_result sss_prepare(sss_context *ctx, const sss_prepare_desc *desc);

/** Runs the filter on *frame. Pixels with alpha 0, outside the stencil, non-finite or beyond 2^125 keep
 *  their value (and give their weight to the centre). @return OK; INVALID_ARGUMENT (a field outside its
 *  list); INVALID_TEXTURE (name, target, format or size; a profile index >= the count, debug checks);
 *  UNSUPPORTED (a format or sample count this GL lacks); INVALID_OPERATION (no camera); NO_CONTEXT (context
 *  lost: objects rebuilt on the next call); FRAMEBUFFER; OUT_OF_MEMORY; SHADER_COMPILE; GL (raised during
 *  the draws: the target may be partly written). Every check runs before the first draw. */
SSS_API sss_result sss_apply_frame(sss_context *ctx, const sss_frame *frame);
/** sss_apply_frame of color_texture in place, undescribed (not on ES 3.0). */
SSS_API sss_result sss_apply(sss_context *ctx, uint32_t color_texture, uint32_t depth_texture,
                             const sss_stencil *stencil);
/** The next frame re-checks its GL context and textures. @return OK; INVALID_ARGUMENT */
SSS_API sss_result sss_gl_context_changed(sss_context *ctx);
/** Counters and the latest measurements. No GL. @return OK; INVALID_ARGUMENT (NULL or struct_size) */
SSS_API sss_result sss_get_stats(const sss_context *ctx, sss_stats *stats);

#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_H */
