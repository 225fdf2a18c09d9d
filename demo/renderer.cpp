#include "renderer.hpp"

#include "host_gl_util.hpp"

namespace demo {

bool create_renderer(Renderer *r, const DemoScene &scene, sss_get_proc_address_fn get_proc_address, void *user) {
  r->scene = &scene;
  return create_gpu_scene(scene, &r->gpu) && create_shadow_pass(&r->shadows, scene) &&
         create_lighting_pass(&r->lighting) && create_pixel_count_pass(&r->counter) &&
         create_composite_pass(&r->composite) && create_sss_stage(&r->sss, get_proc_address, user) &&
         check_gl("renderer setup");
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
  TransmittanceInputs transmittance;
  transmittance.enabled = controls.translucency;
  transmittance.width = sss_width_for_world_units_per_mm(r->scene->world_units_per_mm) * controls.width_scale;
  transmittance.translucency = controls.translucency_amount;
  transmittance.profile = blur_profile(controls);
  run_lighting_pass(r->lighting, *targets, *r->scene, r->gpu, r->shadows, camera, transmittance);
  resolve_lighting(*targets);  // MSAA: the single-sample "before", specular and stencil for the composite
  lap(&t.lighting_ms);
  if (!check_gl("the shadow and lighting passes")) return false;

  if (controls.enabled) {
    if (!set_sss_controls(&r->sss, controls, r->scene->world_units_per_mm) ||
        !apply_sss(r->sss, controls, camera.projection, targets->samples > 0 ? targets->diffuse_ms : targets->diffuse,
                   targets->samples > 0 ? targets->depth_stencil_ms : targets->depth_stencil, targets->after)) {
      return false;
    }
    result->sss_ran = true;
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
  run_composite_pass(r.composite, targets, in);
  glFinish();
  if (times != nullptr) times->composite_ms = now_ms() - start;
}

}  // namespace demo
