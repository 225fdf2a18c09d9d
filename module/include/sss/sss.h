/*
 * sss: screen-space subsurface scattering for OpenGL hosts. The runtime API.
 *
 * C99, no GL header: GL object names are uint32_t and formats are the GL enum values, named below
 * as SSS_GL_* so that a file without GL headers can spell them. The research tools (kernel
 * families, profiles, fits, transmittance terms) are in <sss/sss_tools.h>, the skin LUTs in
 * <sss/sss_lut.h>; this header includes neither. The guide: docs/integration.md.
 *
 * A whole host, compiled and run headless by the test suite (docs.header_example):
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
 *     desc.get_proc_address = load;
 *     desc.get_proc_address_user = load_user;
 *     if (sss_create(&desc, &sss) != SSS_OK) return NULL; // sss_last_error(NULL) says why
 *     sss_default_settings(&settings);                    // d'Eon's skin at its measured size
 *     settings.world_units_per_mm = 0.001f;               // scene in metres
 *     if (sss_set_settings(sss, &settings) != SSS_OK) {
 *       sss_destroy(sss);
 *       return NULL;
 *     }
 *     prepare.struct_size = sizeof prepare;
 *     prepare.width = w;
 *     prepare.height = h;
 *     prepare.color_format = SSS_GL_RGBA16F;
 *     prepare.depth_format = SSS_GL_DEPTH24_STENCIL8;
 *     sss_prepare(sss, &prepare); // compile and allocate now, not in the first frame
 *     return sss;
 *   }
 *   // Every frame, after diffuse lighting, before specular and tone mapping:
 *   int engine_sss_frame(sss_context *sss, const float projection[16], uint32_t diffuse,
 *                        uint32_t depth, int w, int h) {
 *     sss_frame frame = {0};
 *     sss_stats stats;
 *     frame.struct_size = sizeof frame;
 *     frame.color_texture = diffuse;            // linear diffuse light x albedo, alpha = strength
 *     frame.color_format = SSS_GL_RGBA16F;      // formats and size given: a steady frame asks
 *     frame.depth_texture = depth;              // the GL nothing
 *     frame.depth_format = SSS_GL_DEPTH24_STENCIL8;
 *     frame.texture_width = w;
 *     frame.texture_height = h;
 *     frame.projection = projection;            // column-major, as glUniformMatrix4fv takes it
 *     if (sss_apply_frame(sss, &frame) != SSS_OK) return 0; // blurred in place
 *     stats.struct_size = sizeof stats;
 *     sss_get_stats(sss, &stats);               // e.g. stats.last_frame_path
 *     return 1;
 *   }
 *   void engine_sss_shutdown(sss_context *sss) { sss_destroy(sss); } // same GL context current
 * sss-h-example: end
 *
 * Threads: a context lives on its GL context's thread; contexts share nothing.
 *
 * Errors: every call that can fail returns an sss_result; sss_last_error() then names the bad
 * argument and its value. A failed call changes nothing: no setting, no GL state, no host texture
 * (one exception: SSS_ERROR_GL raised while drawing, see sss_apply_frame()).
 *
 * struct_size: every struct a host fills starts with it. Give this release's sizeof, or the size of
 * an earlier release's struct (its fields are read as that release defined them and the newer ones
 * take their defaults); any other size fails, naming the struct and the sizes it accepts.
 *
 * GL state: a call that draws, and sss_create and sss_prepare, which build, leave no GL error and
 * restore everything they changed (unless the context was created with SSS_CREATE_NO_STATE_RESTORE):
 *   - bindings: program, vertex array, draw and read framebuffers, renderbuffer, active texture,
 *     the 2D and 2D-multisample texture and the sampler of texture units 0-5 (and 6 in a frame
 *     with an albedo_texture), uniform buffer
 *     binding 0 and the generic uniform buffer, the pixel unpack buffer, image units 0 and 1;
 *   - pixel store: unpack alignment, row length and skips (pack too under SSS_CREATE_DEBUG_CHECKS);
 *   - viewport, sample mask word 0, colour mask and blend function and equation of draw buffer 0,
 *     polygon mode, front and back stencil state, depth function, depth write mask, depth range;
 *   - enables: SCISSOR_TEST, DEPTH_TEST, STENCIL_TEST, BLEND, CULL_FACE, FRAMEBUFFER_SRGB,
 *     RASTERIZER_DISCARD, SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_COVERAGE, SAMPLE_MASK,
 *     POLYGON_OFFSET_FILL, DEPTH_CLAMP, COLOR_LOGIC_OP, CLIP_DISTANCE0-7, MULTISAMPLE;
 *   - the depth texture's DEPTH_STENCIL_TEXTURE_MODE.
 * On OpenGL ES, those of the above that ES has. Not touched: the scissor box, clear values, other
 * bindings, texture parameters. The host must not have transform feedback or conditional rendering
 * active during a call.
 */
#ifndef SSS_SSS_H
#define SSS_SSS_H

#include "sss_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- GL formats the API takes (their GL enum values) ---- */

#define SSS_GL_RGBA16F 0x881Au            /**< GL_RGBA16F: colour, output, normals */
#define SSS_GL_RGBA32F 0x8814u            /**< GL_RGBA32F: colour, output, normals (stays 32-bit) */
#define SSS_GL_R11F_G11F_B10F 0x8C3Au     /**< GL_R11F_G11F_B10F: colour, only with a strength texture */
#define SSS_GL_DEPTH_COMPONENT16 0x81A5u  /**< GL_DEPTH_COMPONENT16: hardware depth */
#define SSS_GL_DEPTH_COMPONENT24 0x81A6u  /**< GL_DEPTH_COMPONENT24: hardware depth */
#define SSS_GL_DEPTH_COMPONENT32 0x81A7u  /**< GL_DEPTH_COMPONENT32: hardware depth (desktop GL) */
#define SSS_GL_DEPTH_COMPONENT32F 0x8CACu /**< GL_DEPTH_COMPONENT32F: hardware depth */
#define SSS_GL_DEPTH24_STENCIL8 0x88F0u   /**< GL_DEPTH24_STENCIL8: hardware depth, host stencil */
#define SSS_GL_DEPTH32F_STENCIL8 0x8CADu  /**< GL_DEPTH32F_STENCIL8: hardware depth, host stencil */
#define SSS_GL_R16F 0x822Du               /**< GL_R16F: linear view distance; strength */
#define SSS_GL_R32F 0x822Eu               /**< GL_R32F: linear view distance; strength */
#define SSS_GL_R8 0x8229u                 /**< GL_R8: strength */
#define SSS_GL_RGBA8 0x8058u              /**< GL_RGBA8: albedo */
#define SSS_GL_SRGB8_ALPHA8 0x8C43u       /**< GL_SRGB8_ALPHA8: albedo (decoded to linear as it is read) */
#define SSS_GL_R8UI 0x8232u               /**< GL_R8UI: profile indices */
#define SSS_GL_R16UI 0x8234u              /**< GL_R16UI: profile and object indices */
#define SSS_GL_DEPTH_COMPONENT 0x1902u    /**< GL_DEPTH_COMPONENT: a depth-stencil texture's sampling mode */
#define SSS_GL_STENCIL_INDEX 0x1901u      /**< GL_STENCIL_INDEX: a depth-stencil texture's sampling mode */

/* ---- Creating a context ---- */

/** A context: the module's GL objects and settings for one GL context. Opaque. */
typedef struct sss_context sss_context;

/** The host's GL loader (eglGetProcAddress, glfwGetProcAddress, SDL_GL_GetProcAddress...).
 *  @param name the GL function's name ("glDrawArrays")
 *  @param user sss_create_desc.get_proc_address_user
 *  @return the function, or NULL where the GL lacks it */
typedef void *(*sss_get_proc_address_fn)(const char *name, void *user);

/** The level of a log message (the callback receives every level: filter there). */
typedef enum sss_log_level {
  SSS_LOG_ERROR = 0,   /**< a failure: the text sss_last_error() then returns */
  SSS_LOG_WARNING = 1, /**< worth a look: a GL error the host left pending (cleared), a program the
                            driver refused and what stands in, sss_destroy() without its GL context */
  SSS_LOG_INFO = 2,    /**< what was chosen: the GL and shader dialect at creation, the path
                            SSS_PATH_AUTO took, a frame that fell back to the fragment path */
  SSS_LOG_DEBUG = 3    /**< program builds, allocations, kernels kept from earlier settings */
} sss_log_level;

/** The host's log sink. `level` is an sss_log_level; `message` lives for the call only. */
typedef void (*sss_log_fn)(int level, const char *message, void *user);

/** Bits of sss_create_desc.flags. */
typedef enum sss_create_flag {
  /** The host restores GL state itself: the module reads none of it (no state queries). */
  SSS_CREATE_NO_STATE_RESTORE = 0x1,
  /** No KHR_debug labels or debug groups (they are on where the GL has them). */
  SSS_CREATE_NO_DEBUG_LABELS = 0x2,
  /** Measure the GPU (timer and sample queries, read back a frame or more later): sss_stats. */
  SSS_CREATE_STATS = 0x4,
  /** Check every frame in full: textures, framebuffers, profile indices, glGetError. Slow. */
  SSS_CREATE_DEBUG_CHECKS = 0x8
} sss_create_flag;
/** Every sss_create_flag bit. */
#define SSS_CREATE_ALL_FLAGS 0xFu

/** What sss_create needs. Zero-initialise it, then set struct_size and get_proc_address. */
typedef struct sss_create_desc {
  uint32_t struct_size;                     /**< sizeof(sss_create_desc) */
  sss_get_proc_address_fn get_proc_address; /**< required: the GL loader */
  void *get_proc_address_user;              /**< passed to get_proc_address; may be NULL */
  sss_log_fn log;                           /**< optional: receives every message (NULL: none) */
  void *log_user;                           /**< passed to log; may be NULL */
  uint32_t flags;                           /**< sss_create_flag bits; 0 for the defaults */
} sss_create_desc;

/* ---- Settings ---- */

/** The profiles the module knows: one ID space for sss_settings.cbf_profile, the LUTs
 *  (sss_lut.h) and the tools (sss_tools.h). */
typedef enum sss_profile {
  SSS_PROFILE_SKIN_DEON = 0,       /**< d'Eon and Luebke's six-Gaussian skin (the default's target) */
  SSS_PROFILE_APPLE = 1,           /**< Jensen et al. 2001's measured dipole: apple */
  SSS_PROFILE_CHICKEN1 = 2,        /**< measured dipole: chicken 1 */
  SSS_PROFILE_CHICKEN2 = 3,        /**< measured dipole: chicken 2 */
  SSS_PROFILE_CREAM = 4,           /**< measured dipole: cream */
  SSS_PROFILE_KETCHUP = 5,         /**< measured dipole: ketchup */
  SSS_PROFILE_MARBLE = 6,          /**< measured dipole: marble */
  SSS_PROFILE_POTATO = 7,          /**< measured dipole: potato */
  SSS_PROFILE_SKIMMILK = 8,        /**< measured dipole: skim milk */
  SSS_PROFILE_SKIN1 = 9,           /**< measured dipole: skin 1 */
  SSS_PROFILE_SKIN2 = 10,          /**< measured dipole: skin 2 */
  SSS_PROFILE_WHOLEMILK = 11,      /**< measured dipole: whole milk */
  SSS_PROFILE_TABULATED = 12,      /**< a table the caller gives (sss_tools.h sss_profile_desc only) */
  SSS_PROFILE_MIKKELSEN_2010 = 13, /**< a spike and one Gaussian per channel: the cross-bilateral default */
  SSS_PROFILE_KERNEL = 14,         /**< cbf_profile only: the profile of settings.kernel */
  SSS_PROFILE_BURLEY = 15          /**< Burley's normalized diffusion (sss_tools.h sss_profile_desc only) */
} sss_profile;
/** The number of sss_profile values. */
#define SSS_PROFILE_COUNT 16

/** The filter's two modes. */
typedef enum sss_mode {
  SSS_MODE_SEPARABLE = 0,      /**< two passes, horizontal then vertical (the separable SSS paper) */
  SSS_MODE_CROSS_BILATERAL = 1 /**< Mikkelsen 2010's cross-bilateral passes over a profile */
} sss_mode;

/** How the separable mode's passes run. FRAGMENT, COMPUTE, AUTO and FRAGMENT_MASKED give the same
 *  image to within fp16 rounding; HALF_RESOLUTION does not (the guide, "half resolution"). */
typedef enum sss_path {
  SSS_PATH_FRAGMENT = 0,        /**< two full-screen fragment passes */
  SSS_PATH_COMPUTE = 1,         /**< compute shaders (desktop GL 4.3+); elsewhere the fragment passes */
  SSS_PATH_AUTO = 2,            /**< the default: the fastest path that can run the frame (timed where
                                     the GL's timers can be trusted) */
  SSS_PATH_FRAGMENT_MASKED = 3, /**< fragment passes drawn only over bands of the 16x16 tiles that
                                     hold alpha > 0 (cheap where little is translucent) */
  SSS_PATH_HALF_RESOLUTION = 4  /**< the passes at half size where the kernel is wide, then upsampled */
} sss_path;

/** Where the albedo goes (sss_settings.texturing): what of the surface's colour is blurred with the
 *  light. The host's colour is irradiance E times albedo A (sss_frame.color_texture); with an
 *  albedo_texture the passes blur E·A_pre and the output is A_post·(blurred), with A_pre·A_post = A.
 *  Where a channel of the albedo is below 1/256, 1/256 stands in for it on both sides (the colour is
 *  near 0 there: its light is taken as colour·256, so the output at such a pixel is its blurred
 *  light times 1/256, and it lends its neighbours that light; docs/integration.md "Texturing modes"
 *  measures what that costs). */
typedef enum sss_texturing {
  SSS_TEXTURING_PRE_SCATTER = 0,         /**< A_pre = A: the colour blurred as it is, albedo detail
                                              with it (the default; needs no albedo_texture) */
  SSS_TEXTURING_POST_SCATTER = 1,        /**< A_post = A: the light alone blurred, the albedo's detail
                                              kept sharp (a scanned albedo that already holds the
                                              scattering; needs an albedo_texture) */
  SSS_TEXTURING_PRE_AND_POST_SCATTER = 2 /**< A_pre = A_post = sqrt(A): half the detail blurred
                                              (needs an albedo_texture) */
} sss_texturing;

/** sss_settings.flags: fade taps that lie off the centre's surface (a depth step). Default on. */
#define SSS_FOLLOW_SURFACE 0x1u
/** sss_settings.flags: SSS_PATH_AUTO may choose SSS_PATH_HALF_RESOLUTION (by timing). Default off. */
#define SSS_AUTO_HALF_RESOLUTION 0x4u
/** Every sss_settings.flags bit. */
#define SSS_SETTINGS_ALL_FLAGS 0x5u

struct sss_kernel_desc; /* defined in sss_tools.h */

/** What the filter does. Fill it with sss_default_settings(), then change what you need; the
 *  scene's scale (world units per millimetre) is the one field every host sets. */
typedef struct sss_settings {
  uint32_t struct_size;     /**< sizeof(sss_settings), or an earlier release's size (converted) */
  float world_units_per_mm; /**< [0, 1e6]: the scene's units per millimetre: 0.001 for metres (the
                                 default), 0.1 for centimetres, 1 for millimetres; 0 blurs nothing */
  float scale;              /**< [0, 1000]: multiplies the scattering distance; 1 = physical (default) */
  float strength[3];        /**< [0, 1] each: how much light scatters, red, green, blue. Default: the
                                 calibrated fit to d'Eon's skin */
  float falloff[3];         /**< [0, 1] each: the profile's radius, red, green, blue. Default: the fit */
  float separable_scale;    /**< (0, 100]: the kernel's millimetres per surface millimetre (eq. (1)
                                 of the paper). Default: calibrated with strength and falloff */
  int32_t taps;             /**< odd, [SSS_MIN_TAPS, SSS_MAX_TAPS]: the most taps per pass. Default 17 */
  uint32_t flags;           /**< SSS_FOLLOW_SURFACE (default), SSS_AUTO_HALF_RESOLUTION */
  uint32_t mode;            /**< an sss_mode. Default SSS_MODE_SEPARABLE */
  /* Advanced: the cross-bilateral mode (mode = SSS_MODE_CROSS_BILATERAL). */
  int32_t cbf_taps;         /**< odd, [3, 65]: the most taps per pass. Default 13 */
  float cbf_r_max_mm;       /**< (0, 50]: the footprint's radius in profile millimetres. Default 4.5 */
  uint32_t cbf_profile;     /**< an sss_profile but TABULATED and BURLEY (KERNEL: settings.kernel's
                                 profile); a measured one (1-11), or a profile that must be fitted,
                                 needs the tools library (sss_tools.h). Default MIKKELSEN_2010 */
  /* Advanced: another kernel family (sss_tools.h). */
  const struct sss_kernel_desc *kernel; /**< NULL: eq. (1) from the fields above (the default); else
                                             the kernel it describes (copied by sss_set_settings) */
  float jitter;             /**< [0, 1]: the share of the outer taps that move per pixel, trading
                                 banding for noise (see sss_frame.noise_index). Default 0 */
  uint32_t path;            /**< an sss_path. Default SSS_PATH_AUTO */
  uint32_t texturing;       /**< an sss_texturing. Default SSS_TEXTURING_PRE_SCATTER; the other modes
                                 need the frame's albedo_texture. Per profile (sss_set_profiles) */
} sss_settings;

/** How many profiles one frame may use (sss_set_profiles). */
#define SSS_MAX_PROFILES 16

/* ---- A frame ---- */

/** The host's stencil as the mask of translucent pixels: those where
 *  (stencil & mask) == (ref & mask). */
typedef struct sss_stencil {
  uint32_t depth_stencil_texture; /**< SSS_GL_DEPTH24_STENCIL8 or SSS_GL_DEPTH32F_STENCIL8, the
                                       colour's size and sample count (it may be depth_texture) */
  uint32_t ref;                   /**< [0, 255] */
  uint32_t mask;                  /**< [0, 255] */
} sss_stencil;

/** Bits of sss_frame.flags. */
typedef enum sss_frame_flag {
  /** The depth texture holds depths in [0, 1] as glClipControl(..., GL_ZERO_TO_ONE) writes them
   *  (else GL's [-1, 1] mapped to [0, 1]). Ignored for a linear depth (R16F, R32F). */
  SSS_FRAME_DEPTH_ZERO_TO_ONE = 0x1,
  /** sss_frame.region is set: nothing translucent lies outside it. */
  SSS_FRAME_REGION = 0x2,
  /** The texture written (output, or colour in place) is complete (no mipmap filter on a texture
   *  without mipmaps): desktop GL 4.3+ may then write it as an image (faster). */
  SSS_FRAME_TARGET_COMPLETE = 0x4
} sss_frame_flag;
/** Every sss_frame_flag bit. */
#define SSS_FRAME_ALL_FLAGS 0x7u

/** How an MSAA depth texture's samples become one depth per pixel. */
typedef enum sss_msaa_depth {
  SSS_MSAA_DEPTH_AVERAGE = 0, /**< the mean of the samples' view distances (the default) */
  SSS_MSAA_DEPTH_SAMPLE0 = 1, /**< sample 0 */
  SSS_MSAA_DEPTH_MIN = 2,     /**< the nearest sample */
  SSS_MSAA_DEPTH_MAX = 3      /**< the farthest sample */
} sss_msaa_depth;

/** What a frame writes into its output_texture instead of the filtered image (sss_frame.debug_view):
 *  what the passes see, per pixel. A pixel the passes leave alone (not translucent, outside the
 *  stencil, a colour that is not finite, an unusable depth, a profile index with no profile) is
 *  (0, 0, 0, 1); every other pixel (r, g, b, 1) as below. The views but the tiles run the fragment
 *  passes of the kernel's first term; the tiles view runs the masked path's tile marks. */
typedef enum sss_debug_view {
  SSS_DEBUG_VIEW_NONE = 0,         /**< the filtered image (the default) */
  SSS_DEBUG_VIEW_MASK = 1,         /**< (1, 1, 1): the pixels the passes change */
  SSS_DEBUG_VIEW_LINEAR_DEPTH = 2, /**< (d, d, d): the view distance the passes read, world units */
  SSS_DEBUG_VIEW_FOOTPRINT = 3,    /**< (x, y, 0): profile millimetres one pixel step spans along the
                                        horizontal and the vertical pass (the surface's turn included;
                                        surface millimetres over scale and the pixel's strength) */
  SSS_DEBUG_VIEW_TAPS = 4,         /**< (x, y, 0): taps the horizontal and the vertical pass read,
                                        the centre included */
  SSS_DEBUG_VIEW_PROFILE = 5,      /**< (p, o, 1): the profile (value & 15) and object (value >> 4)
                                        index; (0, 0, 1) without a profile_texture */
  SSS_DEBUG_VIEW_TILES = 6,        /**< (r, g, b): the 16x16 tiles SSS_PATH_FRAGMENT_MASKED draws, at
                                        every pixel of the viewport: r 1 where its blur passes draw,
                                        g 1 where its inputs draw does, b 1 where the tile holds a
                                        translucent pixel; 0 elsewhere. Not with a stencil (that
                                        path draws no tiles then) */
  SSS_DEBUG_VIEW_ALBEDO = 7        /**< (r, g, b): A_post, what the passes divided the colour by and
                                        multiply their result by (sss_texturing: the floored albedo
                                        or its square root; (1, 1, 1) for pre-scatter) */
} sss_debug_view;
/** The largest sss_debug_view. */
#define SSS_DEBUG_VIEW_LAST 7u

/** One application of the filter. Zero-initialise it and fill what you have: each texture with its
 *  format beside it. A frame that gives its size and the format of every texture it names is
 *  "described"; a described frame equal to the last successful one is "steady" and asks the GL
 *  nothing (no round trips) unless the state is to be restored. Re-created a texture under the same
 *  name, or lost the GL context? Call sss_gl_context_changed(). Multisampled inputs need desktop GL.
 *  Formats 0 mean "ask the GL", which OpenGL ES 3.0 cannot: give every format there. */
typedef struct sss_frame {
  uint32_t struct_size;        /**< sizeof(sss_frame), or an earlier release's size (converted) */
  /* The colour: required. */
  uint32_t color_texture;      /**< 2D or 2D-multisample: linear diffuse light times albedo, alpha the
                                    SSS strength in [0, 1] (0: left alone); blurred in place unless
                                    output_texture is set */
  uint32_t color_format;       /**< 0, SSS_GL_RGBA16F, SSS_GL_RGBA32F, or SSS_GL_R11F_G11F_B10F with a
                                    strength_texture */
  /* The depth: required. */
  uint32_t depth_texture;      /**< the colour's target, size and sample count: hardware depth, or the
                                    linear view distance in world units */
  uint32_t depth_format;       /**< 0, SSS_GL_DEPTH_COMPONENT16/24/32/32F, SSS_GL_DEPTH24_STENCIL8,
                                    SSS_GL_DEPTH32F_STENCIL8 (hardware), SSS_GL_R16F, SSS_GL_R32F (linear) */
  uint32_t depth_stencil_mode; /**< 0, SSS_GL_DEPTH_COMPONENT or SSS_GL_STENCIL_INDEX: what the host
                                    leaves a depth-stencil texture sampling; 0: GL_DEPTH_COMPONENT in
                                    a described frame, else asked of the GL */
  uint32_t msaa_depth_resolve; /**< an sss_msaa_depth. Default SSS_MSAA_DEPTH_AVERAGE */
  /* Where the result goes: optional. */
  uint32_t output_texture;     /**< 0: in place; else a single-sample 2D texture of the colour's size */
  uint32_t output_format;      /**< 0, SSS_GL_RGBA16F, SSS_GL_RGBA32F */
  int32_t texture_width;       /**< 0 (ask the GL), or the size every texture shares, > 0 */
  int32_t texture_height;      /**< 0 (ask the GL), or the size every texture shares, > 0 */
  /* The camera. */
  const float *projection;     /**< NULL: the last sss_set_camera(); else this frame's projection,
                                    16 floats column-major, checked as sss_set_camera checks them */
  uint32_t flags;              /**< sss_frame_flag bits (the depth's convention, a region) */
  int32_t viewport[4];         /**< x, y, width, height in texels; all 0: the whole texture */
  int32_t region[4];           /**< with SSS_FRAME_REGION: x, y, width, height inside the viewport */
  /* Which pixels are translucent: alpha > 0, or a stencil. Optional. */
  const sss_stencil *stencil;  /**< NULL: alpha > 0; else the host's stencil */
  uint32_t stencil_format;     /**< 0, SSS_GL_DEPTH24_STENCIL8, SSS_GL_DEPTH32F_STENCIL8 */
  /* The strength apart from the colour: optional. */
  uint32_t strength_texture;   /**< 0: alpha is the strength; else a single-sample 2D texture, red the
                                    strength (the colour's alpha is then unused) */
  uint32_t strength_format;    /**< 0, SSS_GL_R8, SSS_GL_R16F, SSS_GL_R32F */
  /* Several materials: optional (sss_set_profiles). */
  uint32_t profile_texture;    /**< 0: one profile; else a single-sample 2D texture: value & 15 the
                                    profile, value >> 4 an object; a tap of another value is not taken */
  uint32_t profile_format;     /**< 0, SSS_GL_R8UI, SSS_GL_R16UI */
  /* Advanced: the cross-bilateral mode's normals. Optional. */
  uint32_t normal_texture;     /**< 0: the surface from the depth; else view-space normals in rgb */
  uint32_t normal_format;      /**< 0, SSS_GL_RGBA16F, SSS_GL_RGBA32F */
  /* Temporal anti-aliasing. */
  uint32_t noise_index;        /**< any value: moves the jittered taps' pattern (settings.jitter > 0),
                                    so that a host that averages frames (TAA) averages the noise away:
                                    give it the frame counter. 0: the same pattern every frame */
  /* Debugging. */
  uint32_t debug_view;         /**< an sss_debug_view: 0 filters; else that view goes into
                                    output_texture (required), the kernel's first term on the
                                    fragment passes; not with SSS_FRAME_REGION, a multisampled colour
                                    or the cross-bilateral mode (the tiles view: nor a stencil) */
  /* The surface's albedo: optional, needed by a texturing mode other than pre-scatter. */
  uint32_t albedo_texture;     /**< 0: none; else a texture of the colour's size, target and sample
                                    count (multisampled colour: multisampled alike, each sample
                                    divided by its own; another count, size or a single-sample one:
                                    SSS_ERROR_INVALID_TEXTURE), rgb the diffuse albedo the colour was
                                    multiplied by (alpha unused), read where a pixel's profile's
                                    texturing is not pre-scatter */
  uint32_t albedo_format;      /**< 0, SSS_GL_SRGB8_ALPHA8 (decoded), SSS_GL_RGBA8, SSS_GL_RGBA16F */
} sss_frame;

/** Bits of sss_prepare_desc.flags: what the frames will use besides the formats. */
typedef enum sss_prepare_flag {
  SSS_PREPARE_NORMALS = 0x1,                   /**< frames give normal_texture */
  SSS_PREPARE_REGION = 0x2,                    /**< frames set SSS_FRAME_REGION */
  SSS_PREPARE_UNFIXED_SAMPLE_LOCATIONS = 0x4   /**< MSAA textures without fixed sample locations */
} sss_prepare_flag;
/** Every sss_prepare_flag bit. */
#define SSS_PREPARE_ALL_FLAGS 0x7u

/** The frames sss_prepare() gets ready for: formats as in sss_frame. */
typedef struct sss_prepare_desc {
  uint32_t struct_size;     /**< sizeof(sss_prepare_desc), or an earlier release's size */
  int32_t width;            /**< [1, GL_MAX_TEXTURE_SIZE]: the textures' width */
  int32_t height;           /**< [1, GL_MAX_TEXTURE_SIZE]: the textures' height */
  uint32_t color_format;    /**< required: as sss_frame.color_format */
  uint32_t output_format;   /**< 0: in place; else as sss_frame.output_format */
  uint32_t depth_format;    /**< required: as sss_frame.depth_format */
  int32_t samples;          /**< 0 or 1: single-sample; [2, 32]: multisampled */
  uint32_t stencil_format;  /**< 0: no host stencil; else as sss_frame.stencil_format */
  uint32_t flags;           /**< sss_prepare_flag bits */
  uint32_t strength_format; /**< 0: no strength texture; else as sss_frame.strength_format (single-sample) */
  uint32_t profile_format;  /**< 0: no profile texture; else as sss_frame.profile_format (single-sample) */
  uint32_t albedo_format;   /**< 0: no albedo texture; else as sss_frame.albedo_format, samples alike */
} sss_prepare_desc;

/* ---- What the module reports ---- */

/** The shaders' GLSL dialect (sss_stats.glsl_variant). */
typedef enum sss_glsl {
  SSS_GLSL_330_CORE = 0, /**< OpenGL 3.3 to 4.1, or 4.2 without GL_ARB_explicit_uniform_location */
  SSS_GLSL_420_CORE = 1, /**< OpenGL 4.2+ with GL_ARB_explicit_uniform_location (compute from 4.3) */
  SSS_GLSL_300_ES = 2    /**< OpenGL ES 3.0+, WebGL 2 */
} sss_glsl;

/** Bits of sss_stats.measured: which GPU measurements the stats hold. */
typedef enum sss_stats_flag {
  SSS_STATS_PIXELS = 0x1,  /**< pixels_touched */
  SSS_STATS_GPU_TIME = 0x2 /**< gpu_time_ms */
} sss_stats_flag;

/** Counters, and with SSS_CREATE_STATS the GPU's measurements, read back without a stall (so a
 *  frame or more old: measured_frame says which). */
typedef struct sss_stats {
  uint32_t struct_size;        /**< set by the caller: sizeof(sss_stats), or an earlier release's */
  uint32_t glsl_variant;       /**< an sss_glsl */
  uint64_t frames;             /**< successful frames */
  uint64_t passes;             /**< draws and dispatches over those frames */
  uint32_t last_frame_passes;  /**< draws and dispatches of the last successful frame */
  uint32_t measured;           /**< sss_stats_flag bits: which of the fields below hold a value */
  uint64_t measured_frame;     /**< the frame the measurements come from (1: the first); 0: none yet */
  uint64_t pixels_touched;     /**< pixels the vertical pass wrote (SSS_CREATE_STATS, desktop GL, the
                                    fragment paths) */
  double gpu_time_ms[2];       /**< GPU time of the horizontal and of the vertical pass(es) */
  uint32_t last_frame_path;    /**< the sss_path that ran the last successful frame */
  uint64_t gpu_memory_bytes;   /**< the bytes the context's GL textures, renderbuffers and buffers
                                    hold now (their storage, as allocated; the driver may hold more) */
} sss_stats;

/** The kinds of projection (sss_projection_info.kind). */
typedef enum sss_projection_kind {
  SSS_PROJECTION_PERSPECTIVE = 0, /**< clip w grows with the distance */
  SSS_PROJECTION_ORTHOGRAPHIC = 1 /**< clip w is constant */
} sss_projection_kind;
/** sss_projection_info.flags: depth falls as the distance grows (reversed-Z). */
#define SSS_PROJECTION_REVERSED_Z 0x1u
/** sss_projection_info.flags: the far plane is at infinity. */
#define SSS_PROJECTION_INFINITE_FAR 0x2u

/** What sss_get_projection_info() asks about. */
typedef struct sss_projection_query {
  uint32_t struct_size;    /**< sizeof(sss_projection_query) */
  const float *projection; /**< NULL: the last sss_set_camera(); else 16 floats as sss_frame takes */
  uint32_t frame_flags;    /**< 0 or SSS_FRAME_DEPTH_ZERO_TO_ONE: the depth's convention */
  int32_t width;           /**< > 0: the viewport's width in pixels */
  int32_t height;          /**< > 0: the viewport's height in pixels */
  float view_distance;     /**< > 0, finite: where mm_per_pixel is measured, in world units */
} sss_projection_query;

/** How the module understands a projection. */
typedef struct sss_projection_info {
  uint32_t struct_size;   /**< set by the caller: sizeof(sss_projection_info) */
  uint32_t kind;          /**< an sss_projection_kind */
  uint32_t flags;         /**< SSS_PROJECTION_REVERSED_Z, SSS_PROJECTION_INFINITE_FAR */
  float near_distance;    /**< the view distance at the depth range's near end, world units */
  float far_distance;     /**< the view distance at its far end; +infinity when infinite */
  float mm_per_pixel[2];  /**< millimetres of a surface facing the camera that one pixel spans at
                               view_distance, across and up (settings.world_units_per_mm) */
} sss_projection_info;

/* ---- Entry points ---- */

/** This library's version, packed as SSS_MAKE_VERSION (sss_common.h): compare with SSS_VERSION to
 *  catch a header and a library from different releases. Needs no context; never fails. */
SSS_API uint32_t sss_get_version(void);

/** The name of a result code: "SSS_ERROR_INVALID_TEXTURE"; "SSS_ERROR_UNKNOWN" for a value that is
 *  none. Never NULL. */
SSS_API const char *sss_result_string(sss_result r);

/** The message of the last failure on `ctx` ("SSS_ERROR_...: " and what was wrong, naming the
 *  argument and its value); with NULL, of the last failure on this thread of a call without a
 *  context (sss_create, a NULL ctx). A success leaves it; "" before any failure. The text lives
 *  until the next failure on the same context (or thread). Never NULL. */
SSS_API const char *sss_last_error(const sss_context *ctx);

/** Creates a context in the current GL context and compiles its shaders.
 *  @param desc what it needs (see sss_create_desc)
 *  @param out  receives the context; NULL on failure
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT   desc or out NULL, desc->struct_size, get_proc_address NULL,
 *                                       unknown flags
 *  @retval SSS_ERROR_NO_CONTEXT         no GL context is current
 *  @retval SSS_ERROR_UNSUPPORTED        OpenGL below 3.3, ES below 3.0, or no float render targets
 *  @retval SSS_ERROR_GL_FUNCTION_MISSING the loader gave no pointer for a function the GL must have
 *  @retval SSS_ERROR_SHADER_COMPILE     a shader did not compile or link (the driver's log in the message)
 *  @retval SSS_ERROR_OUT_OF_MEMORY      an allocation failed
 *  On failure nothing is left in the GL. */
SSS_API sss_result sss_create(const sss_create_desc *desc, sss_context **out);

/** Deletes the context and its GL objects (no binding of yours changes); its GL context must be
 *  current. NULL: nothing. */
SSS_API void sss_destroy(sss_context *ctx);

/** Fills *s with the defaults (struct_size = sizeof(sss_settings)). NULL: nothing. */
SSS_API void sss_default_settings(sss_settings *s);

/** Validates *s and makes it the context's settings (one profile for every pixel). No GL call; the
 *  kernel is built here, never in a frame (a fitted family may take up to ~0.7 s).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT a field outside its range (named), ctx or s NULL
 *  @retval SSS_ERROR_UNSUPPORTED      a kernel or profile that needs the tools library, which was not
 *                                     linked or sss_tools_init() not called
 *  @retval SSS_ERROR_OUT_OF_MEMORY    an allocation failed
 *  On failure the previous settings stay. */
SSS_API sss_result sss_set_settings(sss_context *ctx, const sss_settings *s);

/** Several materials in one frame: profiles[i] filters the pixels whose profile_texture value & 15
 *  is i. Each may differ in world_units_per_mm, scale, strength, falloff, separable_scale, kernel
 *  (one term when count > 1) and texturing; every other field must equal profiles[0]'s, which become the
 *  settings (sss_set_settings() is count 1). Pixels of an index >= count are left alone (refused
 *  under SSS_CREATE_DEBUG_CHECKS). No GL call.
 *  @param count [1, SSS_MAX_PROFILES]
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT count out of range, profiles NULL, profiles[i].field out of
 *                                     range or unlike profiles[0]'s (named)
 *  @retval SSS_ERROR_UNSUPPORTED      a kernel of several terms, or the cross-bilateral mode, with
 *                                     count > 1; more profiles than the GL's uniform blocks hold
 *  @retval SSS_ERROR_OUT_OF_MEMORY    an allocation failed
 *  On failure the previous profiles stay. */
SSS_API sss_result sss_set_profiles(sss_context *ctx, const sss_settings *profiles, uint32_t count);

/** Writes the current settings into *s, in the layout s->struct_size names (this release's or an
 *  earlier one's). s->kernel then points at the context's copy until the next sss_set_settings().
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or s NULL, or s->struct_size of no release */
SSS_API sss_result sss_get_settings(const sss_context *ctx, sss_settings *s);

/** Sets the camera of the frames that carry no projection of their own. No GL call.
 *  @param projection 16 floats, column-major as glUniformMatrix4fv takes them: perspective (also
 *                    off-centre, reversed-Z, infinite far) or orthographic
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or projection NULL, an element not finite, a matrix whose
 *                                     depth cannot be linearised (the element named)
 *  @retval SSS_ERROR_UNSUPPORTED      a projection that shears depth into x or y, or takes w from x or y
 *  On failure the previous camera stays. */
SSS_API sss_result sss_set_camera(sss_context *ctx, const float projection[16]);

/** How the module reads a projection (the query's, or the camera's): its kind, depth direction,
 *  near and far distances, and the millimetres one pixel spans at a distance. No GL call.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx, query or info NULL, a struct_size, a field of *query out
 *                                     of range, or a projection sss_set_camera() would refuse
 *  @retval SSS_ERROR_UNSUPPORTED      a projection sss_set_camera() would refuse as unsupported
 *  @retval SSS_ERROR_INVALID_OPERATION query->projection NULL and no camera set yet */
SSS_API sss_result sss_get_projection_info(const sss_context *ctx, const sss_projection_query *query,
                                           sss_projection_info *info);

/** Compiles and allocates what frames like *desc need with the current settings, so that the first
 *  such frame does no work that belongs in setup. Optional.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or desc NULL, a field out of range (named)
 *  @retval SSS_ERROR_UNSUPPORTED      a format or sample count this GL lacks
 *  @retval SSS_ERROR_NO_CONTEXT       the context's GL context is not current
 *  @retval SSS_ERROR_SHADER_COMPILE   a shader did not compile or link
 *  @retval SSS_ERROR_OUT_OF_MEMORY    an allocation failed
 *  @retval SSS_ERROR_GL               the GL raised an error */
SSS_API sss_result sss_prepare(sss_context *ctx, const sss_prepare_desc *desc);

/** Runs the filter on *frame. Pixels with strength 0, outside the stencil, or whose colour is not
 *  finite or beyond 2^125 keep their value (and their taps' weight goes to the centre). Every check
 *  runs before the first draw: a failure other than SSS_ERROR_GL leaves every texture as it was.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT  ctx or frame NULL, a field outside its range (named), a
 *                                      described format or size that is not the texture's, a
 *                                      debug_view without an output_texture or with a region
 *  @retval SSS_ERROR_INVALID_TEXTURE   a texture's name, target, format or size; under
 *                                      SSS_CREATE_DEBUG_CHECKS a profile index >= the profile count
 *  @retval SSS_ERROR_UNSUPPORTED       a format or sample count this GL lacks; a projection
 *                                      sss_set_camera() would refuse as unsupported; a debug_view
 *                                      with a multisampled colour or in the cross-bilateral mode;
 *                                      SSS_DEBUG_VIEW_TILES with a stencil
 *  @retval SSS_ERROR_INVALID_OPERATION no projection in the frame and no camera set
 *  @retval SSS_ERROR_NO_CONTEXT        the GL context is not current or was lost (the module's
 *                                      objects are rebuilt by the next call that finds one)
 *  @retval SSS_ERROR_FRAMEBUFFER       a framebuffer the module built is incomplete
 *  @retval SSS_ERROR_OUT_OF_MEMORY     an allocation failed
 *  @retval SSS_ERROR_SHADER_COMPILE    a shader did not compile or link
 *  @retval SSS_ERROR_GL                the GL raised an error while drawing: the texture written
 *                                      may be partly written */
SSS_API sss_result sss_apply_frame(sss_context *ctx, const sss_frame *frame);

/** sss_apply_frame() in place with only the colour, the depth and a stencil given (undescribed: the
 *  module asks the GL for the formats, which OpenGL ES 3.0 cannot answer).
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT on OpenGL ES 3.0 (the formats are needed: use sss_apply_frame()),
 *                                     and as sss_apply_frame()
 *  Every other code as sss_apply_frame() returns it. */
SSS_API sss_result sss_apply(sss_context *ctx, uint32_t color_texture, uint32_t depth_texture,
                             const sss_stencil *stencil);

/** Tells the context that its GL context was re-created or that textures were re-created under the
 *  same names: the next frame checks everything again.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx NULL */
SSS_API sss_result sss_gl_context_changed(sss_context *ctx);

/** Counters and the latest GPU measurements into *stats, in the layout stats->struct_size names.
 *  No GL call.
 *  @retval SSS_OK
 *  @retval SSS_ERROR_INVALID_ARGUMENT ctx or stats NULL, or stats->struct_size of no release */
SSS_API sss_result sss_get_stats(const sss_context *ctx, sss_stats *stats);

#ifdef __cplusplus
}
#endif

#endif /* SSS_SSS_H */
