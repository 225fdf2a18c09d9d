// sss_demo: the Lee Perry-Smith head scan (or any glTF), lit with shadow-mapped lights, through the
// library's screen-space separable subsurface scattering. A GLFW window with a Dear ImGui panel, or
// --headless PNGs for each camera preset. See `sss_demo --help` and docs/demo.md.
#include "apps.hpp"
#include "options.hpp"
#include "scene.hpp"

#include <glm/geometric.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace demo {

SssControls controls_from_options(const Options &o) {
  SssControls c = default_sss_controls();
  c.enabled = o.sss;
  if (o.taps != 0) c.taps = o.taps;
  c.scale = o.scale;
  c.follow_surface = o.follow_surface;
  c.shading = o.shading;
  c.use_stencil = o.use_stencil;
  c.cross_bilateral = o.cross_bilateral;
  c.kernel_family = o.kernel_family;
  c.kernel_rank = o.kernel_rank;
  c.material = o.material;
  c.jitter = o.jitter;
  c.moving_noise = o.moving_noise;
  c.region = o.region;
  c.path = static_cast<int>(o.path);
  c.translucency = o.translucency;
  c.translucency_amount = o.translucency_amount;
  c.thickness_source = o.thickness_source;
  c.baked_thickness_mm = o.baked_thickness_mm;
  c.msaa_samples = o.msaa;
  c.texturing = o.texturing;
  c.object_ids = o.object_ids;
  // The window starts on the first debug view asked for; headless keeps the filter for its usual
  // images and writes each view apart (headless_app.cpp's write_debug_views).
  if (!o.headless && !o.debug_views.empty()) c.debug_view = o.debug_views.front();
  return c;
}

namespace {

bool load_scene(const Options &o, DemoScene *scene) {
  try {
    if (!o.gltf_path.empty())
      *scene = load_gltf_scene(o.gltf_path);
    else if (o.scene == "sphere")
      *scene = make_sphere_scene();
    else if (o.scene == "mixed")
      *scene = make_mixed_scene();
    else if (o.scene == "hand")
      *scene = make_hand_scene();
    else
      *scene = load_head_scene();
  } catch (const std::exception &e) {
    std::fprintf(stderr, "sss_demo: %s\n", e.what());
    return false;
  }
  if (scene->hand_material >= 0) {
    float *colour = scene->model.materials[static_cast<size_t>(scene->hand_material)].base_color;
    for (int k = 0; k < 3; ++k) colour[k] = o.hand_colour[k];
  }
  if (o.back_light && !scene->lights.empty()) {
    // Behind the head and a little to the side: the ears and the nostrils' wings stand between it
    // and the camera presets, so the light they let through shows.
    if (scene->lights.size() < 2) scene->lights.push_back(scene->lights.front());
    scene->lights[1] = {glm::normalize(glm::vec3(0.45f, 0.25f, -1.0f)), glm::vec3(2.4f, 2.3f, 2.2f)};
  }
  for (const std::string &warning : scene->model.warnings) std::fprintf(stderr, "sss_demo: glTF: %s\n", warning.c_str());
  return true;
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
  demo::DemoScene scene;
  if (!demo::load_scene(options, &scene)) return 1;
  return options.headless ? demo::run_headless(options, scene) : demo::run_window(options, scene);
}
