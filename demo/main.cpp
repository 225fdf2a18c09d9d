// sss_demo: renders a small scene headless, applies the sss library and writes before/after PNGs.
#include "composite.hpp"
#include "context.hpp"
#include "gl_functions.hpp"
#include "host_gl_util.hpp"
#include "image.hpp"
#include "lighting_pass.hpp"
#include "options.hpp"
#include "png_output.hpp"
#include "report.hpp"
#include "scene_geometry.hpp"
#include "scene_view.hpp"
#include "shadow_pass.hpp"
#include "sss_stage.hpp"
#include "texture_copy.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace demo {
namespace {

struct Passes {
  SceneGeometry geometry;
  ShadowPass shadow;
  LightingPass lighting;
  CompositePass composite;
  GLuint before_texture = 0;   // copy of the diffuse before the library runs
  GLuint scratch_texture = 0;  // output of the timing-only second run
};

void destroy_passes(Passes *p) {
  glDeleteTextures(1, &p->before_texture);
  glDeleteTextures(1, &p->scratch_texture);
  destroy_composite_pass(&p->composite);
  destroy_lighting_pass(&p->lighting);
  destroy_shadow_pass(&p->shadow);
  destroy_scene_geometry(&p->geometry);
}

bool create_passes(Passes *p, GLsizei width, GLsizei height) {
  p->geometry = create_scene_geometry();
  if (!check_gl("scene geometry upload")) return false;
  if (!create_shadow_pass(&p->shadow, kShadowMapSize)) return false;
  if (!create_lighting_pass(&p->lighting, width, height)) return false;
  if (!create_composite_pass(&p->composite, width, height)) return false;
  p->before_texture = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  p->scratch_texture = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  return check_gl("render target creation");
}

// Ends a GL stage: waits for the GPU so the time is the stage's own, then checks for errors.
bool finish_stage(Timings *timings, const char *stage) {
  glFinish();
  timings->end();
  return check_gl(stage);
}

struct Frames {
  Image before;
  Image after;
};

// Tone-maps the "before" copy and the blurred diffuse (each + specular) and reads them back.
bool compose_frames(const Passes &p, const Options &o, Frames *frames) {
  run_composite_pass(p.composite, p.before_texture, p.lighting.specular_texture, o.exposure);
  frames->before = image_from_gl_rows(read_composite(p.composite), o.width, o.height);
  run_composite_pass(p.composite, p.lighting.diffuse_texture, p.lighting.specular_texture, o.exposure);
  frames->after = image_from_gl_rows(read_composite(p.composite), o.width, o.height);
  return check_gl("composite and read-back");
}

bool write_images(const Frames &frames, const SceneView &view, const std::filesystem::path &dir) {
  const Image split = make_split(frames.before, frames.after, 2);
  // A 3x close-up of the split where the shadow edge crosses the divider: at the physical width
  // the effect spans only a few pixels.
  const int focus_y = project_to_pixel(view, view.focus_point, split.width, split.height).y;
  return write_png((dir / "before.png").string(), frames.before) &&
         write_png((dir / "after.png").string(), frames.after) && write_png((dir / "split.png").string(), split) &&
         write_png((dir / "split_zoom.png").string(), crop_zoom(split, split.width / 2, focus_y, 160, 120, 3));
}

int run(const Options &o) {
  const std::filesystem::path dir(o.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "sss_demo: cannot create %s: %s\n", o.out_dir.c_str(), ec.message().c_str());
    return 1;
  }

  Timings timings;
  std::printf("sss_demo: %dx%d, stages:\n", o.width, o.height);
  timings.begin("context creation");
  Context context;
  if (!create_context(o.backend, &context)) return 1;
  timings.end();
  std::printf("GL_RENDERER: %s\nGL_VERSION:  %s\nbackend:     %s\n", context.renderer.c_str(),
              context.version.c_str(), context.backend.c_str());

  const SceneView view = make_scene_view(o.width, o.height);
  Passes passes;
  SssStage sss;
  int status = 1;
  do {
    timings.begin("scene and render targets");
    if (!create_passes(&passes, o.width, o.height) || !finish_stage(&timings, "setup")) break;

    timings.begin("sss_create + settings");
    if (!create_sss_stage(&sss, context.headless, o) || !finish_stage(&timings, "sss_create")) break;

    timings.begin("1 shadow map");
    run_shadow_pass(passes.shadow, passes.geometry, view.light_view_projection);
    if (!finish_stage(&timings, "the shadow pass")) break;

    timings.begin("2 lighting");
    run_lighting_pass(passes.lighting, passes.geometry, view, passes.shadow.depth_texture, passes.shadow.size);
    if (!finish_stage(&timings, "the lighting pass")) break;

    timings.begin("3a copy diffuse (before)");
    if (!copy_color_texture(passes.lighting.diffuse_texture, passes.before_texture, o.width, o.height) ||
        !finish_stage(&timings, "the diffuse copy")) {
      break;
    }

    timings.begin("3b sss_apply (first call)");
    if (!apply_sss(sss, view.projection, passes.lighting.diffuse_texture, passes.lighting.depth_stencil_texture) ||
        !finish_stage(&timings, "sss_apply")) {
      break;
    }

    timings.begin("3c sss_apply_frame (warm, timing)");
    if (!apply_sss_into(sss, passes.before_texture, passes.lighting.depth_stencil_texture, passes.scratch_texture) ||
        !finish_stage(&timings, "sss_apply_frame")) {
      break;
    }

    timings.begin("4 composite + read-back");
    Frames frames;
    if (!compose_frames(passes, o, &frames)) break;
    timings.end();

    timings.begin("5 PNG encode + write");
    if (!write_images(frames, view, dir)) break;
    timings.end();

    const float physical_width = sss_width_for_world_units_per_mm(0.001f);
    const ReportInput report{&o, &context, &view, &sss.settings, physical_width, &timings.stages()};
    if (!write_readme((dir / "README.txt").string(), report)) break;
    std::printf("wrote %s/{before,after,split,split_zoom}.png and README.txt (width %.4g m, %d taps, %s)\n",
                o.out_dir.c_str(), static_cast<double>(sss.settings.width), sss.settings.samples,
                o.use_stencil ? "stencil mask" : "alpha mask");
    status = 0;
  } while (false);

  destroy_sss_stage(&sss);
  destroy_passes(&passes);
  check_gl("clean-up");
  destroy_context(&context);
  return status;
}

}  // namespace
}  // namespace demo

int main(int argc, char **argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // keep progress lines in order with stderr messages
  demo::Options options;
  switch (demo::parse_options(argc, argv, &options)) {
    case demo::ParseResult::kHelp:
      demo::print_usage(argv[0]);
      return 0;
    case demo::ParseResult::kError:
      std::fprintf(stderr, "Try '%s --help'.\n", argv[0]);
      return 2;
    case demo::ParseResult::kRun:
      break;
  }
  return demo::run(options);
}
