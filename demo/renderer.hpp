// The demo's renderer: shadow maps, lighting, the library, the pixel counts and the composite, in
// that order, each timed with glFinish on both sides (llvmpipe's GL_TIME_ELAPSED is wrong for a
// single pass, DESIGN.md §6). The same code draws the window's frames and the headless PNGs.
#pragma once

#include "camera.hpp"
#include "composite.hpp"
#include "frame_targets.hpp"
#include "gpu_scene.hpp"
#include "lighting_pass.hpp"
#include "pixel_count.hpp"
#include "scene.hpp"
#include "shadow_pass.hpp"
#include "sss_stage.hpp"

namespace demo {

struct PassTimes {
  double shadow_ms = 0.0;
  double lighting_ms = 0.0;
  double sss_ms = 0.0;      // sss_set_camera + sss_apply_frame
  double count_ms = 0.0;    // the marked/touched pixel counts
  double composite_ms = 0.0;
  double total_ms() const { return shadow_ms + lighting_ms + sss_ms + count_ms + composite_ms; }
};

struct Renderer {
  const DemoScene *scene = nullptr;
  GpuScene gpu;
  ShadowPass shadows;
  LightingPass lighting;
  SssStage sss;
  PreintegratedLuts luts;  // the library's LUTs for pre-integrated shading (owned by sss.context)
  PixelCountPass counter;
  CompositePass composite;
};

// Uploads the scene and builds every pass; the library is created with the given loader.
bool create_renderer(Renderer *renderer, const DemoScene &scene, sss_get_proc_address_fn get_proc_address,
                     void *user);
void destroy_renderer(Renderer *renderer);

struct FrameResult {
  PassTimes times;
  PixelCounts counts;
  bool sss_ran = false;  // targets.after holds the library's output
  bool preintegrated = false;  // the skin was shaded with the pre-integrated LUTs (no SSS pass)
  float pixels_per_mm = 0.0f;  // a millimetre at the scene's centre, in pixels (the automatic choice)
  // The debug view "after" holds (SssControls::debug_view where the library ran it; 0: the image),
  // and the view distances of the subject's bounds, nearest and farthest (the depth view's range).
  int debug_view = 0;
  float view_depth[2] = {0.0f, 0.0f};
};

// Passes 1-3 and the counts into `targets` (count = false skips the counts). Returns false (after
// printing why) when the library or GL failed.
bool render_frame(Renderer *renderer, const CameraMatrices &camera, const SssControls &controls, FrameTargets *targets,
                  bool count, FrameResult *result);

// Pass 4 into targets.output; `shown_after` is the texture the final view shows (targets.after when
// the library ran, else targets.diffuse). Adds its time to *times when given.
void composite_frame(const Renderer &renderer, const FrameTargets &targets, const FrameResult &frame, ViewMode mode,
                     float exposure, float split, GLuint heat_map, PassTimes *times);

}  // namespace demo
