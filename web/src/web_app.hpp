// The web demo's state, shared by the page (web/src/web_page.cpp, Emscripten) and its native twin
// (web/src/web_frame.cpp, OpenGL ES 3.0 through EGL): the head, the library's context and the
// knobs. Uses the runtime API of <sss/sss.h>, and the tools' sss_kernel_desc for the material
// control (web_materials.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <sss/sss.h>

#include "web_scene.hpp"

namespace web {

// What the page's controls set (web/page/index.html). strength and falloff are per channel, in
// the library's units; the page scales the defaults.
struct Knobs {
  bool enabled = true;
  float scale = 1.0f;
  float strength[3] = {0, 0, 0};
  float falloff[3] = {0, 0, 0};
  int taps = 17;
  bool follow_surface = true;
  int material = 0;  // index into web::kMaterials (web_materials.hpp)
};

class App {
 public:
  App() = default;
  App(const App&) = delete;
  App& operator=(const App&) = delete;
  ~App();

  // Loads the glTF file, builds the scene (width x height) and the library's context with the
  // given loader. False with message() set on failure.
  bool init(sss_get_proc_address_fn get_proc_address, void* user, const std::string& gltf_path, int width, int height);
  // The library's defaults, as the page's controls start.
  Knobs default_knobs() const;
  // sss_set_settings with these knobs; on an error the library keeps its settings, message() holds
  // sss_last_error and the next frames render as before.
  sss_result set_knobs(const Knobs& knobs);
  // One frame (split: texture x in [0, 1] left of which the unscattered diffuse shows).
  sss_result render(float split);
  // One frame through another context of the library (the browser test's probes of what WebGL2 lacks).
  sss_result render_with(sss_context* sss, float split) { return scene_->render(sss, split); }
  // Median milliseconds of `frames` frames, each finished by a one-pixel read (a full round trip).
  double time_frames(int frames, float split);
  std::vector<uint8_t> pixels_top_first() const;

  const std::string& message() const { return message_; }
  const std::string& renderer() const { return renderer_; }
  const Scene& scene() const { return *scene_; }

 private:
  std::unique_ptr<Scene> scene_;
  sss_context* sss_ = nullptr;
  bool enabled_ = true;
  std::string message_;
  std::string renderer_;
};

}  // namespace web
