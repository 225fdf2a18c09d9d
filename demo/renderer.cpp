#include "renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "host_gl_util.hpp"
#include "sss/sss_lut.h"

namespace demo {

namespace {

// The library's default LUTs, the penumbra range scaled to the scene's units (1..32 mm).
bool create_luts(Renderer *r) {
  sss_lut_desc d;
  sss_lut_default_desc(&d);
  d.world_units_per_mm = r->scene->world_units_per_mm;
  d.penumbra_min = 1.0f * d.world_units_per_mm;
  d.penumbra_max = 32.0f * d.world_units_per_mm;
  uint32_t diffuse = 0, shadow = 0;
  if (sss_lut_create_texture(r->sss.context, SSS_LUT_DIFFUSE, &d, &diffuse) != SSS_OK ||
      sss_lut_create_texture(r->sss.context, SSS_LUT_SHADOW, &d, &shadow) != SSS_OK) {
    std::fprintf(stderr, "sss_lut_create_texture: %s\n", sss_last_error(r->sss.context));
    return false;
  }
  r->luts.diffuse = diffuse;
  r->luts.shadow = shadow;
  r->luts.curvature_range[0] = d.curvature_min;
  r->luts.curvature_range[1] = d.curvature_max;
  r->luts.penumbra_range[0] = d.penumbra_min;
  r->luts.penumbra_range[1] = d.penumbra_max;
  return true;
}

// SSS_CREATE_DEBUG_CHECKS is a create flag: a new library context with or without it, and the
// LUTs again (they belonged to the old context). The next set_sss_controls gives it the settings.
bool recreate_sss(Renderer *r, bool debug_checks) {
  const SssStage old = r->sss;
  destroy_sss_stage(&r->sss);
  if (!create_sss_stage(&r->sss, old.get_proc_address, old.user, debug_checks) || !create_luts(r)) return false;
  std::printf("sss_demo: the library's context re-created %s SSS_CREATE_DEBUG_CHECKS\n",
              debug_checks ? "with" : "without");
  return true;
}

// targets.diffuse into targets.after (same size and format) through two temporary framebuffers.
void copy_diffuse_to_after(const FrameTargets &targets) {
  GLuint framebuffers[2] = {0, 0};
  glGenFramebuffers(2, framebuffers);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers[0]);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, targets.diffuse, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers[1]);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, targets.after, 0);
  glBlitFramebuffer(0, 0, targets.width, targets.height, 0, 0, targets.width, targets.height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, framebuffers);
}

// Pixels per millimetre at the scene's centre: the projection's vertical scale over the distance.
float pixels_per_mm(const DemoScene &scene, const CameraMatrices &camera, int height) {
  const float distance = glm::length(scene.subject.centre() - camera.eye);
  if (!(distance > 0.0f)) return 0.0f;
  return 0.5f * static_cast<float>(height) * camera.projection[1][1] * scene.world_units_per_mm / distance;
}

// SSS_FRAME_REGION as a host computes it: the screen rectangle of every vertex's bounds (all
// translucent geometry is inside them), padded by the kernel's reach in pixels at the nearest
// corner, at alpha 1: eq. (1) reaches 2 kernel mm at every tap count, which is 2 / separable_scale mm of
// surface, times scale. (The other families reach as far as their profile does, sss_kernel_plan's
// out_reach_mm; the pad is eq. (1)'s for all.) False when a corner is behind the camera: then no
// region is given (the whole viewport is filtered).
bool translucent_region(const DemoScene &scene, const CameraMatrices &camera, const SssControls &controls, int width,
                        int height, std::int32_t region[4]) {
  float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f, nearest = 1e30f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? scene.all.max.x : scene.all.min.x, (corner & 2) ? scene.all.max.y : scene.all.min.y,
                      (corner & 4) ? scene.all.max.z : scene.all.min.z);
    const glm::vec4 clip = camera.view_projection * glm::vec4(p, 1.0f);
    if (!(clip.w > camera.near_plane * 0.5f)) return false;
    const float sx = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width);
    const float sy = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(height);
    x0 = std::min(x0, sx);
    x1 = std::max(x1, sx);
    y0 = std::min(y0, sy);
    y1 = std::max(y1, sy);
    nearest = std::min(nearest, clip.w);
  }
  sss_settings defaults{};
  sss_default_settings(&defaults);  // the demo leaves separable_scale at the library's default
  const float reach_mm = 2.0f / defaults.separable_scale * controls.scale;
  const float pixels_per_mm_at_nearest =
      0.5f * static_cast<float>(std::max(width, height)) *
      std::max(camera.projection[0][0], camera.projection[1][1]) * scene.world_units_per_mm / nearest;
  const float pad = std::ceil(reach_mm * pixels_per_mm_at_nearest) + 2.0f;
  const int left = std::clamp(static_cast<int>(std::floor(x0 - pad)), 0, width);
  const int bottom = std::clamp(static_cast<int>(std::floor(y0 - pad)), 0, height);
  const int right = std::clamp(static_cast<int>(std::ceil(x1 + pad)), 0, width);
  const int top = std::clamp(static_cast<int>(std::ceil(y1 + pad)), 0, height);
  region[0] = left;
  region[1] = bottom;
  region[2] = right - left;  // 0 when the bounds are off screen: nothing translucent is visible
  region[3] = top - bottom;
  return true;
}

// The nearest and farthest view distance (-z in view space) of the subject's bounds' corners (the
// head, not the whole scene: the depth view's contrast is on the skin), the nearest kept in front of
// the near plane.
void view_depth_range(const DemoScene &scene, const CameraMatrices &camera, float range[2]) {
  const Bounds &b = scene.subject;
  range[0] = 1e30f;
  range[1] = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y, (corner & 4) ? b.max.z : b.min.z);
    const float distance = -(camera.view * glm::vec4(p, 1.0f)).z;
    range[0] = std::min(range[0], distance);
    range[1] = std::max(range[1], distance);
  }
  range[0] = std::max(range[0], camera.near_plane);
  range[1] = std::max(range[1], range[0] * 1.001f);
}

}  // namespace

bool create_renderer(Renderer *r, const DemoScene &scene, sss_get_proc_address_fn get_proc_address, void *user) {
  r->scene = &scene;
  return create_gpu_scene(scene, &r->gpu) && create_shadow_pass(&r->shadows, scene) &&
         create_lighting_pass(&r->lighting) && create_pixel_count_pass(&r->counter) &&
         create_composite_pass(&r->composite) && create_sss_stage(&r->sss, get_proc_address, user) &&
         create_luts(r) && check_gl("renderer setup");
}

void destroy_renderer(Renderer *r) {
  if (r->sss.context != nullptr) destroy_sss_stage(&r->sss);
  destroy_composite_pass(&r->composite);
  destroy_pixel_count_pass(&r->counter);
  destroy_lighting_pass(&r->lighting);
  destroy_shadow_pass(&r->shadows);
  destroy_gpu_scene(&r->gpu);
  r->scene = nullptr;
}

bool render_frame(Renderer *r, const CameraMatrices &camera, const SssControls &controls, FrameTargets *targets,
                  bool count, FrameResult *result) {
  *result = FrameResult{};
  PassTimes &t = result->times;
  glFinish();
  double start = now_ms();
  auto lap = [&start](double *ms) {
    glFinish();
    const double now = now_ms();
    *ms = now - start;
    start = now;
  };

  run_shadow_pass(r->shadows, *r->scene, r->gpu);
  lap(&t.shadow_ms);
  result->pixels_per_mm =
      pixels_per_mm(*r->scene, camera, controls.decision_height > 0 ? controls.decision_height : targets->height);
  result->preintegrated = controls.enabled && (controls.shading == kShadingPreintegrated ||
                                               (controls.shading == kShadingAutomatic &&
                                                result->pixels_per_mm < kAutoPreintegratedPixelsPerMm));
  TransmittanceInputs transmittance;
  transmittance.enabled = controls.translucency;
  transmittance.world_units_per_profile_mm = r->scene->world_units_per_mm * controls.scale;  // as the blur
  transmittance.translucency = controls.translucency_amount;
  transmittance.profile = blur_profile(controls);
  transmittance.thickness_source = controls.thickness_source;
  // A thickness is geometry: millimetres of the scene, not scaled with the scattering.
  transmittance.baked_thickness = controls.baked_thickness_mm * r->scene->world_units_per_mm;
  run_lighting_pass(r->lighting, *targets, *r->scene, r->gpu, r->shadows, camera, transmittance,
                    result->preintegrated ? &r->luts : nullptr, controls.object_ids);
  resolve_lighting(*targets);  // MSAA: the single-sample "before", specular and stencil for the composite
  lap(&t.lighting_ms);
  if (!check_gl("the shadow and lighting passes")) return false;
  if (result->preintegrated) {
    // The frame is done (pre-integrated skin needs no pass). For the views that compare, the
    // result goes where the library's output would ("after") and a Lambert lighting pass refills
    // "before"; untimed: a renderer using pre-integrated shading would not draw it.
    copy_diffuse_to_after(*targets);
    run_lighting_pass(r->lighting, *targets, *r->scene, r->gpu, r->shadows, camera, transmittance, nullptr,
                      controls.object_ids);
    resolve_lighting(*targets);
    result->sss_ran = true;
    double untimed = 0.0;
    lap(&untimed);
    if (!check_gl("the pre-integrated frame's comparison pass")) return false;
  }

  if (controls.debug_checks != r->sss.debug_checks && !recreate_sss(r, controls.debug_checks)) return false;
  if (controls.enabled && !result->preintegrated) {
    // A debug view the library would refuse here is not asked for (the panel says why); a view
    // covers the whole viewport, so it goes without the region.
    SssControls frame_controls = controls;
    if (debug_view_refusal(controls, targets->samples) != nullptr) frame_controls.debug_view = 0;
    std::int32_t region[4] = {0, 0, 0, 0};
    const bool has_region = controls.region && frame_controls.debug_view == 0 &&
                            translucent_region(*r->scene, camera, controls, targets->width, targets->height, region);
    SssFrameShape shape;
    shape.width = targets->width;
    shape.height = targets->height;
    shape.samples = targets->samples;
    shape.stencil = controls.use_stencil;
    shape.region = has_region;
    std::vector<int> materials;
    for (size_t i = 1; i < r->scene->profiles.size(); ++i) materials.push_back(r->scene->profiles[i].material);
    if (!set_sss_controls(&r->sss, controls, r->scene->world_units_per_mm, materials, uses_profiles(*r->scene)))
      return false;
    // Several profiles or objects: the G-buffer's byte goes with the frame when the controls allow
    // per-pixel profiles (else every pixel is profile 0, as before them), single-sample only (the
    // library refuses a profile texture with MSAA colour).
    shape.profile_texture = uses_profiles(*r->scene) && targets->samples == 0 && r->sss.per_pixel;
    // A texturing mode other than pre-scatter divides by the lighting pass's albedo (with MSAA its
    // multisampled target: each sample is divided by its own albedo).
    shape.albedo_texture = r->sss.settings.texturing != SSS_TEXTURING_PRE_SCATTER;
    // After new settings or a resize, sss_prepare builds and allocates what the frame will need,
    // so the frame itself does not (no hitch; a no-op when nothing changed).
    if (!prepare_sss(&r->sss, shape) ||
        !apply_sss(r->sss, frame_controls, camera.projection, targets->samples > 0 ? targets->diffuse_ms : targets->diffuse,
                   targets->samples > 0 ? targets->depth_stencil_ms : targets->depth_stencil, targets->after,
                   has_region ? region : nullptr, shape.profile_texture ? targets->profile : 0u,
                   shape.albedo_texture ? (targets->samples > 0 ? targets->albedo_ms : targets->albedo) : 0u)) {
      return false;
    }
    result->sss_ran = true;
    result->debug_view = frame_controls.debug_view;
    view_depth_range(*r->scene, camera, result->view_depth);
  }
  lap(&t.sss_ms);

  if (count) {
    result->counts = count_pixels(r->counter, *targets, targets->diffuse,
                                  result->sss_ran ? targets->after : targets->diffuse);
    lap(&t.count_ms);
  }
  return check_gl("the frame");
}

void composite_frame(const Renderer &r, const FrameTargets &targets, const FrameResult &frame, ViewMode mode,
                     float exposure, float split, GLuint heat_map, PassTimes *times) {
  glFinish();
  const double start = now_ms();
  CompositeInput in;
  in.mode = mode;
  in.before = targets.diffuse;
  in.after = frame.sss_ran ? targets.after : targets.diffuse;
  in.specular = targets.specular;
  in.heat_map = heat_map;
  in.exposure = exposure;
  in.split = split;
  in.debug_view = frame.sss_ran ? frame.debug_view : 0;
  in.view_depth[0] = frame.view_depth[0];
  in.view_depth[1] = frame.view_depth[1];
  in.taps = static_cast<int>(r.sss.settings.taps);
  run_composite_pass(r.composite, targets, in);
  glFinish();
  if (times != nullptr) times->composite_ms = now_ms() - start;
}

}  // namespace demo
