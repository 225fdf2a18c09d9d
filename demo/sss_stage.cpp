#include "sss_stage.hpp"

#include "kernel_family.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cstdio>
#include <cstring>

namespace demo {

namespace {

void log_message(int level, const char *message, void * /*user*/) {
  static const char *const kLevels[] = {"error", "warning", "info", "debug"};
  const char *name = level >= 0 && level <= 3 ? kLevels[level] : "?";
  std::fprintf(stderr, "sss_demo: [sss %s] %s\n", name, message);
}

bool report(sss_result r, const char *call, const sss_context *context) {
  if (r == SSS_OK) return true;
  std::fprintf(stderr, "sss_demo: %s failed: %s: %s\n", call, sss_result_string(r), sss_last_error(context));
  return false;
}

}  // namespace

SssControls default_sss_controls() {
  sss_settings s{};
  sss_default_settings(&s);
  SssControls c;
  c.scale = s.scale;
  for (int i = 0; i < 3; ++i) {
    c.strength[i] = s.strength[i];
    c.falloff[i] = s.falloff[i];
  }
  c.taps = s.taps;
  c.follow_surface = (s.flags & SSS_FOLLOW_SURFACE) != 0;
  return c;
}

std::uint32_t blur_profile(const SssControls &controls) {
  if (!controls.cross_bilateral) {
    // The families built from a profile blur with the chosen material's; eq. (1) and the artist
    // model have their own shapes, closest to skin.
    const bool profiled = kernel_family_info(controls.kernel_family)->from_profile;
    return profiled ? static_cast<std::uint32_t>(controls.material) : static_cast<std::uint32_t>(SSS_PROFILE_SKIN_DEON);
  }
  sss_settings s{};
  sss_default_settings(&s);
  return s.cbf_profile;
}

bool create_sss_stage(SssStage *stage, sss_get_proc_address_fn get_proc_address, void *user, bool debug_checks) {
  *stage = SssStage{};
  stage->get_proc_address = get_proc_address;
  stage->user = user;
  stage->debug_checks = debug_checks;
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = get_proc_address;
  desc.get_proc_address_user = user;
  desc.log = log_message;
  desc.log_user = nullptr;
  desc.flags = debug_checks ? static_cast<std::uint32_t>(SSS_CREATE_DEBUG_CHECKS) : 0u;
  if (!report(sss_create(&desc, &stage->context), "sss_create", nullptr)) return false;
  stage->settings.struct_size = sizeof stage->settings;
  return report(sss_get_settings(stage->context, &stage->settings), "sss_get_settings", stage->context);
}

// Profile 0's kernel is one term (eq. (1), guided, artist, or rank 1 of a ranked family) and the
// mode separable: sss_set_profiles takes several profiles only then.
bool one_term(const sss_settings &s) {
  if (s.mode != SSS_MODE_SEPARABLE) return false;
  if (s.kernel == nullptr) return true;
  const bool ranked = s.kernel->family == SSS_KERNEL_SUM_OF_GAUSSIANS || s.kernel->family == SSS_KERNEL_SVD ||
                      s.kernel->family == SSS_KERNEL_PREINTEGRATED;
  return !ranked || s.kernel->rank == 1;
}

// The scene's profiles after the controls' (profile 0): the same settings with a measured material's
// rank-1 pre-integrated kernel each.
void build_profiles(SssStage *stage, const std::vector<int> &materials) {
  stage->profile_kernels.assign(materials.size() + 1, stage->kernel);
  stage->profiles.assign(materials.size() + 1, stage->settings);
  for (size_t i = 1; i <= materials.size(); ++i) {
    sss_kernel_desc &k = stage->profile_kernels[i];
    sss_default_kernel_desc(&k);
    k.family = SSS_KERNEL_PREINTEGRATED;
    k.rank = 1;
    k.profile.profile = materials[i - 1];
    stage->profiles[i].kernel = &k;
  }
}

bool set_sss_controls(SssStage *stage, const SssControls &controls, float world_units_per_mm,
                      const std::vector<int> &materials, bool per_pixel) {
  sss_settings s{};
  sss_default_settings(&s);
  s.world_units_per_mm = world_units_per_mm;
  s.scale = controls.scale;
  for (int i = 0; i < 3; ++i) {
    s.strength[i] = controls.strength[i];
    s.falloff[i] = controls.falloff[i];
  }
  s.taps = controls.taps;
  s.flags = controls.follow_surface ? SSS_FOLLOW_SURFACE : 0u;
  s.mode = controls.cross_bilateral ? SSS_MODE_CROSS_BILATERAL : SSS_MODE_SEPARABLE;
  sss_kernel_desc kernel;
  sss_default_kernel_desc(&kernel);
  kernel.family = controls.kernel_family;
  kernel.rank = controls.kernel_rank;
  kernel.profile.profile = controls.material;
  s.kernel = controls.kernel_family == SSS_KERNEL_SEPARABLE ? nullptr : &kernel;
  s.jitter = controls.jitter;
  s.path = static_cast<uint32_t>(controls.path);
  s.texturing = static_cast<uint32_t>(controls.texturing);
  // Unchanged: nothing to validate or rebuild (the scene's other profiles never change).
  // (The scene, so `materials` and `per_pixel`, is the same for the stage's whole life.)
  if (std::memcmp(&s, &stage->settings, sizeof s) == 0 && stage->profiles.size() == materials.size() + 1) return true;
  const std::uint32_t count = one_term(s) ? static_cast<std::uint32_t>(materials.size() + 1) : 1u;
  sss_settings old = stage->settings;
  const sss_kernel_desc old_kernel = stage->kernel;
  stage->kernel = kernel;
  stage->settings = s;
  if (s.kernel != nullptr) stage->settings.kernel = &stage->kernel;
  build_profiles(stage, materials);
  if (!report(sss_set_profiles(stage->context, stage->profiles.data(), count), "sss_set_profiles", stage->context)) {
    stage->kernel = old_kernel;  // the library kept the old set
    if (old.kernel != nullptr) old.kernel = &stage->kernel;
    stage->settings = old;
    stage->profiles.clear();
    return false;
  }
  stage->profile_count = count;
  stage->per_pixel = one_term(s);
  stage->profile_note = per_pixel && !stage->per_pixel
                            ? "no per-pixel profiles or object IDs (they need a one-term kernel in the separable "
                              "mode): every material is filtered with profile 0's, and light crosses between objects"
                            : "";
  return true;
}

bool prepare_sss(SssStage *stage, const SssFrameShape &shape) {
  sss_prepare_desc d{};
  d.struct_size = sizeof d;
  d.width = shape.width;
  d.height = shape.height;
  d.color_format = SSS_GL_RGBA16F;   // the diffuse target
  d.output_format = SSS_GL_RGBA16F;  // "after"
  d.depth_format = SSS_GL_DEPTH24_STENCIL8;
  d.samples = shape.samples;
  d.stencil_format = shape.stencil ? SSS_GL_DEPTH24_STENCIL8 : 0u;
  d.flags = shape.region ? static_cast<std::uint32_t>(SSS_PREPARE_REGION) : 0u;
  d.profile_format = shape.profile_texture ? SSS_GL_R8UI : 0u;
  d.albedo_format = shape.albedo_texture ? kAlbedoFormat : 0u;
  // Settings compare byte for byte, and the kernel they point at (always stage->kernel, so the pointer
  // alone would not show a new family) too: the demo's kernels hold no pointers (no tabulated profile).
  const bool same = stage->prepared && std::memcmp(&d, &stage->prepared_desc, sizeof d) == 0 &&
                    std::memcmp(&stage->settings, &stage->prepared_settings, sizeof stage->settings) == 0 &&
                    std::memcmp(&stage->kernel, &stage->prepared_kernel, sizeof stage->kernel) == 0;
  if (same) return true;
  if (!report(sss_prepare(stage->context, &d), "sss_prepare", stage->context)) return false;
  stage->prepared = true;
  stage->prepared_desc = d;
  stage->prepared_settings = stage->settings;
  stage->prepared_kernel = stage->kernel;
  return true;
}

const char *texturing_name(int texturing) {
  static const char *const kNames[] = {"pre", "post", "pre-and-post"};
  return texturing >= 0 && texturing <= SSS_TEXTURING_PRE_AND_POST_SCATTER ? kNames[texturing] : nullptr;
}

const char *debug_view_name(int view) {
  static const char *const kNames[] = {"mask", "depth", "footprint", "taps", "profile", "tiles"};
  return view >= 1 && view <= static_cast<int>(SSS_DEBUG_VIEW_LAST) ? kNames[view - 1] : nullptr;
}

const char *debug_view_refusal(const SssControls &controls, int samples) {
  if (controls.debug_view == 0) return nullptr;
  if (samples > 0) return "the debug views need single-sample targets (MSAA is on)";
  if (controls.cross_bilateral) return "the debug views show the separable passes (the cross-bilateral mode is on)";
  return nullptr;
}

bool apply_sss(SssStage &stage, const SssControls &controls, const glm::mat4 &projection, std::uint32_t diffuse,
               std::uint32_t depth_stencil, std::uint32_t after, const std::int32_t *region, std::uint32_t profile,
               std::uint32_t albedo) {
  sss_stencil stencil{};
  stencil.depth_stencil_texture = depth_stencil;
  stencil.ref = 1;  // the lighting pass writes 1 on translucent materials
  stencil.mask = 0xFF;
  sss_frame frame{};
  frame.struct_size = sizeof frame;
  frame.color_texture = diffuse;
  frame.depth_texture = depth_stencil;
  frame.output_texture = after;
  // The tiles view shows what the masked path draws, which culls by alpha alone: no stencil with it.
  frame.stencil = controls.use_stencil && controls.debug_view != SSS_DEBUG_VIEW_TILES ? &stencil : nullptr;
  frame.profile_texture = profile;
  frame.profile_format = profile != 0 ? SSS_GL_R8UI : 0u;
  frame.albedo_texture = albedo;
  frame.albedo_format = albedo != 0 ? kAlbedoFormat : 0u;
  frame.projection = glm::value_ptr(projection);  // the frame carries its camera
  frame.noise_index = controls.moving_noise ? stage.frames_applied : 0u;
  frame.debug_view = static_cast<std::uint32_t>(controls.debug_view);  // render_frame: 0 where refused
  if (region != nullptr) {
    frame.flags |= SSS_FRAME_REGION;
    for (int i = 0; i < 4; ++i) frame.region[i] = region[i];
  }
  if (!report(sss_apply_frame(stage.context, &frame), "sss_apply_frame", stage.context)) return false;
  ++stage.frames_applied;
  return true;
}

void destroy_sss_stage(SssStage *stage) {
  sss_destroy(stage->context);
  *stage = SssStage{};
}

}  // namespace demo
