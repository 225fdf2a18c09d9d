#include "report.hpp"

#include "host_gl_util.hpp"
#include "shadow_pass.hpp"

#include <cstdio>

namespace demo {

void Timings::begin(const std::string &name) {
  if (running_) end();
  current_ = name;
  started_ = now_ms();
  running_ = true;
}

void Timings::end() {
  if (!running_) return;
  const double ms = now_ms() - started_;
  stages_.push_back({current_, ms});
  std::printf("  %-34s %9.2f ms\n", current_.c_str(), ms);
  running_ = false;
}

bool write_readme(const std::string &path, const ReportInput &in) {
  std::FILE *f = std::fopen(path.c_str(), "w");
  if (f == nullptr) {
    std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
    return false;
  }
  const Options &o = *in.options;
  const sss_settings &s = *in.settings;
  const SceneView &v = *in.view;
  std::fprintf(f,
               "sss_demo: screen-space separable subsurface scattering (Jimenez et al. 2012)\n\n"
               "before.png  diffuse + specular, no subsurface scattering\n"
               "after.png   the diffuse blurred by sss_apply, then + specular\n"
               "split.png   left half before, right half after (2-pixel white divider)\n"
               "split_zoom.png  split.png around the shadow edge on the sphere, magnified 3x\n\n");
  std::fprintf(f, "GL_RENDERER  %s\nGL_VERSION   %s\nbackend      %s (requested %s)\n", in.context->renderer.c_str(),
               in.context->version.c_str(), in.context->backend.c_str(), o.backend.c_str());
  std::fprintf(f, "size         %dx%d\n\n", o.width, o.height);
  std::fprintf(f,
               "SSS settings (sss_get_settings after sss_set_settings):\n"
               "  width      %.6g world units = sss_width_for_world_units_per_mm(0.001) (%.6g, metres scene)"
               " x width-scale %.6g\n"
               "  strength   %.3f %.3f %.3f\n"
               "  falloff    %.3f %.3f %.3f\n"
               "  samples    %d taps per pass\n"
               "  flags      0x%x%s\n"
               "  mask       %s\n\n",
               static_cast<double>(s.width), static_cast<double>(in.physical_width),
               static_cast<double>(o.width_scale), static_cast<double>(s.strength[0]),
               static_cast<double>(s.strength[1]), static_cast<double>(s.strength[2]),
               static_cast<double>(s.falloff[0]), static_cast<double>(s.falloff[1]),
               static_cast<double>(s.falloff[2]), s.samples, s.flags,
               (s.flags & SSS_FOLLOW_SURFACE) != 0 ? " (SSS_FOLLOW_SURFACE)" : "",
               o.use_stencil ? "stencil == 1 (ref 1, mask 0xff) and alpha > 0" : "alpha > 0 (no stencil)");
  std::fprintf(f,
               "Scene (metres): sphere r = 0.1 albedo (0.85, 0.55, 0.45), SSS strength (alpha) 1; box and ground alpha 0.\n"
               "Camera: glm::perspective fovy %.0f deg, near %.3g, far %.3g, eye (%.2f, %.2f, %.2f).\n"
               "Light: directional towards (%.3f, %.3f, %.3f), shadow map %d^2 DEPTH_COMPONENT24, 3x3 hardware PCF.\n"
               "Composite: (diffuse + specular) x exposure %.3g, ACES filmic fit, sRGB encode.\n\n",
               static_cast<double>(v.fovy_degrees), static_cast<double>(v.near_plane),
               static_cast<double>(v.far_plane), static_cast<double>(v.eye.x), static_cast<double>(v.eye.y),
               static_cast<double>(v.eye.z), static_cast<double>(v.light_direction.x),
               static_cast<double>(v.light_direction.y), static_cast<double>(v.light_direction.z), kShadowMapSize,
               static_cast<double>(o.exposure));
  std::fprintf(f, "Stage timings (glFinish after each GL stage):\n");
  for (const StageTiming &t : *in.timings) std::fprintf(f, "  %-34s %9.2f ms\n", t.name.c_str(), t.milliseconds);
  const bool ok = std::ferror(f) == 0;
  return std::fclose(f) == 0 && ok;
}

}  // namespace demo
