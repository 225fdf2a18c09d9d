#include "sss_stage.hpp"

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
    const bool profiled = controls.kernel_family != SSS_KERNEL_SEPARABLE && controls.kernel_family != SSS_KERNEL_ARTIST;
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

bool set_sss_controls(SssStage *stage, const SssControls &controls, float world_units_per_mm) {
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
  if (std::memcmp(&s, &stage->settings, sizeof s) == 0) return true;  // unchanged: nothing to validate or rebuild
  if (!report(sss_set_settings(stage->context, &s), "sss_set_settings", stage->context)) return false;
  stage->kernel = kernel;
  stage->settings = s;
  if (s.kernel != nullptr) stage->settings.kernel = &stage->kernel;
  return true;
}

bool prepare_sss(SssStage *stage, const SssFrameShape &shape) {
  sss_prepare_desc d{};
  d.struct_size = sizeof d;
  d.width = shape.width;
  d.height = shape.height;
  d.color_format = 0x881A;   // GL_RGBA16F: the diffuse target
  d.output_format = 0x881A;  // GL_RGBA16F: "after"
  d.depth_format = 0x88F0;   // GL_DEPTH24_STENCIL8
  d.samples = shape.samples;
  d.stencil_format = shape.stencil ? 0x88F0u : 0u;
  d.flags = shape.region ? static_cast<std::uint32_t>(SSS_PREPARE_REGION) : 0u;
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

bool apply_sss(const SssStage &stage, const SssControls &controls, const glm::mat4 &projection,
               std::uint32_t diffuse, std::uint32_t depth_stencil, std::uint32_t after, const std::int32_t *region) {
  if (!report(sss_set_camera(stage.context, glm::value_ptr(projection)), "sss_set_camera", stage.context)) return false;
  sss_stencil stencil{};
  stencil.depth_stencil_texture = depth_stencil;
  stencil.ref = 1;  // the lighting pass writes 1 on translucent materials
  stencil.mask = 0xFF;
  sss_frame frame{};
  frame.struct_size = sizeof frame;
  frame.color_texture = diffuse;
  frame.depth_texture = depth_stencil;
  frame.output_texture = after;
  frame.stencil = controls.use_stencil ? &stencil : nullptr;
  if (region != nullptr) {
    frame.flags |= SSS_FRAME_REGION;
    for (int i = 0; i < 4; ++i) frame.region[i] = region[i];
  }
  return report(sss_apply_frame(stage.context, &frame), "sss_apply_frame", stage.context);
}

void destroy_sss_stage(SssStage *stage) {
  sss_destroy(stage->context);
  *stage = SssStage{};
}

}  // namespace demo
