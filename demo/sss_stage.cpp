#include "sss_stage.hpp"

#include <sss_headless.h>

#include <glm/gtc/type_ptr.hpp>

#include <cstdio>

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

sss_stencil make_stencil(std::uint32_t depth_stencil) {
  sss_stencil stencil{};
  stencil.depth_stencil_texture = depth_stencil;
  stencil.ref = 1;  // the lighting pass writes 1 on the sphere
  stencil.mask = 0xFF;
  return stencil;
}

}  // namespace

bool create_sss_stage(SssStage *stage, void *headless, const Options &options) {
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless;
  desc.log = log_message;
  desc.log_user = nullptr;
  desc.flags = 0;
  if (!report(sss_create(&desc, &stage->context), "sss_create", nullptr)) return false;

  sss_settings settings{};
  sss_default_settings(&settings);
  // The scene is in metres: 0.001 world units per millimetre.
  settings.width = sss_width_for_world_units_per_mm(0.001f) * options.width_scale;
  if (options.samples != 0) settings.samples = options.samples;
  if (!report(sss_set_settings(stage->context, &settings), "sss_set_settings", stage->context)) return false;
  stage->settings.struct_size = sizeof stage->settings;
  if (!report(sss_get_settings(stage->context, &stage->settings), "sss_get_settings", stage->context)) return false;
  stage->use_stencil = options.use_stencil;
  return true;
}

bool apply_sss(const SssStage &stage, const glm::mat4 &projection, std::uint32_t diffuse,
               std::uint32_t depth_stencil) {
  if (!report(sss_set_camera(stage.context, glm::value_ptr(projection)), "sss_set_camera", stage.context)) {
    return false;
  }
  const sss_stencil stencil = make_stencil(depth_stencil);
  return report(sss_apply(stage.context, diffuse, depth_stencil, stage.use_stencil ? &stencil : nullptr),
                "sss_apply", stage.context);
}

bool apply_sss_into(const SssStage &stage, std::uint32_t source, std::uint32_t depth_stencil,
                    std::uint32_t scratch) {
  const sss_stencil stencil = make_stencil(depth_stencil);
  sss_frame frame{};
  frame.struct_size = sizeof frame;
  frame.color_texture = source;
  frame.depth_texture = depth_stencil;
  frame.output_texture = scratch;
  frame.stencil = stage.use_stencil ? &stencil : nullptr;
  return report(sss_apply_frame(stage.context, &frame), "sss_apply_frame", stage.context);
}

void destroy_sss_stage(SssStage *stage) {
  sss_destroy(stage->context);
  *stage = SssStage{};
}

}  // namespace demo
