// Pass 3: the library, through its public C API only (sss/sss.h). The demo's controls map onto
// sss_settings here; the frame runs sss_apply_frame from the lighting pass's diffuse ("before")
// into a separate output texture ("after"), with the stencil the lighting pass wrote.
#pragma once

#include <sss/sss_tools.h>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace demo {

// What the panel and the command line control. Later issues add kernel family / material, jitter
// and translucency here (see panel.cpp for the marked place in the UI).
struct SssControls {
  bool enabled = true;           // S: the library runs (off: "after" is not produced, the frame shows "before")
  float scale = 1.0f;            // sss_settings.scale: multiplies every scattering distance (1 = physical size)
  float strength[3] = {0.78f, 0.70f, 0.75f};
  float falloff[3] = {0.57f, 0.13f, 0.08f};
  int taps = SSS_TAPS_MEDIUM;     // sss_settings.taps
  bool follow_surface = true;
  bool use_stencil = true;       // false: the mask is alpha > 0 alone
  bool cross_bilateral = false;  // SSS_MODE_CROSS_BILATERAL (Mikkelsen 2010) instead of the separable kernel
  // The separable mode's kernel family (sss_settings.kernel): eq. (1), sum of Gaussians, SVD rank N,
  // pre-integrated, guided rank-1, artist; the profile's material; the share of jittered taps.
  int kernel_family = SSS_KERNEL_SEPARABLE;
  int kernel_rank = 1;
  int material = SSS_PROFILE_SKIN_DEON;
  float jitter = 0.0f;
  // sss_frame.noise_index: each frame's number, so the jittered taps' pattern moves every frame (what
  // a host with TAA gives it, to average the noise away); off: 0, one pattern every frame.
  bool moving_noise = false;
  // Skipping work: the head's projected bounds, padded by the kernel's reach, as the frame's region
  // of translucent pixels (SSS_FRAME_REGION). (Taps follow each pixel's footprint in the library
  // without a switch.)
  bool region = false;
  // How the separable passes run (sss_settings.path, SSS_PATH_*): fragment passes, behind a
  // stencil from alpha, compute dispatches, half size where kernels are wide, or the fastest of them.
  int path = 0;
  // Transmittance through thin parts in the lighting pass (integration/glsl/sss_transmittance.glsl),
  // with the profile the blur uses.
  bool translucency = false;
  float translucency_amount = 0.95f;  // the include's `translucency`, 0..1 (1: the most light through)
  int thickness_source = 0;           // TransmittanceInputs::thickness_source (shadow, baked, both)
  float baked_thickness_mm = 2.0f;    // translucent materials without their own MaterialLook::baked_thickness
  int msaa_samples = 0;          // 0, or 4: the lighting pass renders 4x MSAA targets and the library gets those
  // How skin scatters: the library's screen-space filter, pre-integrated shading in the lighting
  // pass (no SSS pass), or automatic: pre-integrated once a millimetre of skin at the scene's centre
  // covers less than kAutoPreintegratedPixelsPerMm pixels (the filter's kernel then spans about a
  // pixel and has nothing left to do).
  int shading = 0;               // kShadingScreenSpace, kShadingPreintegrated, kShadingAutomatic
  int decision_height = 0;       // automatic: the image height the choice is made for (0: the target's);
                                 // the heat map's small frame passes the shown frame's, to choose alike
  // SSS_CREATE_DEBUG_CHECKS: every frame checks the GL (errors, framebuffers, textures). A create
  // flag: toggling it re-creates the library's context (render_frame).
  bool debug_checks = false;
  // The G-buffer's byte carries object IDs (profile | object << 4); off: the profile alone, so light
  // crosses between objects of one profile (the bleeding test scene shows the difference).
  bool object_ids = true;
  // sss_frame.debug_view (an sss_debug_view): what the passes see goes into "after" instead of the
  // filtered image, and the composite's debug view colours it (debug_view_refusal: when it cannot).
  int debug_view = 0;
  // sss_settings.texturing (an sss_texturing, for every profile): what of the albedo is blurred with
  // the light. Pre-scatter blurs the lighting pass's colour as it is; post-scatter and pre-and-post
  // hand the library the lighting pass's albedo target (sss_frame.albedo_texture; with --msaa its
  // multisampled one).
  int texturing = SSS_TEXTURING_PRE_SCATTER;
};

// The lighting pass's albedo target (FrameTargets::albedo): linear RGBA16F, the albedo exactly as the
// lighting multiplied the diffuse light by it (a G-buffer's SRGB8_ALPHA8 or RGBA8 would do as well).
constexpr std::uint32_t kAlbedoFormat = SSS_GL_RGBA16F;

// The demo's texturing mode unless --texturing or the panel says otherwise: post-scatter. The head
// scan's albedo map was photographed, so it already holds the skin's scattering; post-scatter keeps
// it sharp instead of blurring it a second time (docs/demo.md "Texturing modes" has the measurement).
constexpr int kDefaultTexturing = SSS_TEXTURING_POST_SCATTER;

// The texturing modes' names on the command line and in the panel: "pre", "post", "pre-and-post";
// nullptr out of range.
const char *texturing_name(int texturing);

// The debug views' names on the command line and in the panel (SSS_DEBUG_VIEW_MASK .. _TILES):
// "mask", "depth", "footprint", "taps", "profile", "tiles"; nullptr for 0 and out of range.
const char *debug_view_name(int view);
// Why the library would refuse `controls.debug_view` on the demo's frames of `samples` (the views
// need single-sample colour and the separable mode), or nullptr when it runs.
const char *debug_view_refusal(const SssControls &controls, int samples);

constexpr int kShadingScreenSpace = 0;
constexpr int kShadingPreintegrated = 1;
constexpr int kShadingAutomatic = 2;
constexpr float kAutoPreintegratedPixelsPerMm = 0.5f;

// The radial profile the blur of these controls uses (for the transmittance terms): Mikkelsen's in
// the cross-bilateral mode (the library's default cbf_profile), d'Eon's skin profile otherwise (the
// separable kernel's base).
std::uint32_t blur_profile(const SssControls &controls);

// The library's defaults (sss_default_settings) as controls.
SssControls default_sss_controls();

struct SssStage {
  sss_context *context = nullptr;
  sss_settings settings{};  // as the library holds them after the last successful sss_set_settings
  sss_kernel_desc kernel{};  // what settings.kernel points at (the tools' kernel families)
  // The scene's other profiles (sss_set_profiles; [0] is `settings`): a measured material each, as a
  // rank-1 pre-integrated kernel (profile_kernels[i], which profiles[i].kernel points at).
  // profile_count: how many the library holds; per_pixel: frames may bring the profile texture (the
  // library takes it, and several profiles, only with a one-term kernel in the separable mode; else
  // profile_count is 1 and frames come without the texture: every pixel profile 0).
  std::vector<sss_settings> profiles;
  std::vector<sss_kernel_desc> profile_kernels;
  std::uint32_t profile_count = 1;
  bool per_pixel = true;
  std::string profile_note;  // why a scene of several profiles or objects runs without them; empty otherwise
  sss_get_proc_address_fn get_proc_address = nullptr;  // as created, for a re-creation
  void *user = nullptr;
  bool debug_checks = false;  // created with SSS_CREATE_DEBUG_CHECKS
  // What sss_prepare last got ready (prepared false: nothing yet): the frames' description and the
  // settings it was called with.
  bool prepared = false;
  sss_prepare_desc prepared_desc{};
  sss_settings prepared_settings{};
  sss_kernel_desc prepared_kernel{};
  std::uint32_t frames_applied = 0;  // successful sss_apply_frame calls (the moving noise index)
};

// The frames sss_prepare gets ready for: the demo's targets (RGBA16F diffuse, DEPTH24_STENCIL8,
// into the RGBA16F "after"; multisampled with `samples` > 0).
struct SssFrameShape {
  int width = 0, height = 0, samples = 0;
  bool stencil = false, region = false;
  bool profile_texture = false;  // frames bring an R8UI profile/object texture
  bool albedo_texture = false;   // frames bring the albedo (kAlbedoFormat), for a texturing other than pre-scatter
};

// sss_create with the given loader (a GL context must be current), with SSS_CREATE_DEBUG_CHECKS
// when `debug_checks`. Prints the error on failure.
bool create_sss_stage(SssStage *stage, sss_get_proc_address_fn get_proc_address, void *user,
                      bool debug_checks = false);

// sss_prepare for frames of `shape` when they or the settings changed since the last call (a
// resize, new settings), so the next frame compiles and allocates nothing: no hitch. Returns false
// after printing the error.
bool prepare_sss(SssStage *stage, const SssFrameShape &shape);

// sss_set_profiles from the controls (profile 0) and the scene's other profiles (`materials`: an
// sss_profile per profile index >= 1, each a rank-1 pre-integrated kernel with profile 0's taps,
// flags, mode, jitter and path), at the scene's world units per millimetre of surface
// (sss_settings.world_units_per_mm) and the controls' scale. `per_pixel`: the scene's frames would
// bring a profile texture (profile_note says when the controls rule it out). Prints the error on failure.
bool set_sss_controls(SssStage *stage, const SssControls &controls, float world_units_per_mm,
                      const std::vector<int> &materials = {}, bool per_pixel = false);

// sss_apply_frame with the camera in the frame: `diffuse` (left as it is) into `after`; region: x, y,
// width, height of the translucent pixels (SSS_FRAME_REGION), or nullptr for none; profile: the R8UI
// profile/object texture (sss_frame.profile_texture), or 0 for none (every pixel profile 0); albedo:
// the lighting pass's albedo target (sss_frame.albedo_texture, kAlbedoFormat), or 0 for none.
bool apply_sss(SssStage &stage, const SssControls &controls, const glm::mat4 &projection, std::uint32_t diffuse,
               std::uint32_t depth_stencil, std::uint32_t after, const std::int32_t *region = nullptr,
               std::uint32_t profile = 0, std::uint32_t albedo = 0);

void destroy_sss_stage(SssStage *stage);

}  // namespace demo
