// The web demo's WebAssembly side: a WebGL2 context on the page's canvas, the App, and the C
// functions the page's script calls (web/page/sss_page.js, through Module.ccall). Emscripten only.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <GLES3/gl3.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include "web_app.hpp"
#include "web_materials.hpp"

namespace {

std::unique_ptr<web::App> g_app;
web::Knobs g_knobs;
std::string g_text;   // why web_init failed
std::string g_probe;  // the library's message from the last probe (web_try_without, web_try_fitted_kernel)

// sss_create_desc.get_proc_address: Emscripten's own table of the WebGL2 entry points.
void* webgl_get_proc_address(const char* name, void*) { return emscripten_webgl_get_proc_address(name); }

// For the browser test of what WebGL2 may lack: a loader whose glGetStringi(GL_EXTENSIONS) hides
// the extensions in g_hidden (each with and without Emscripten's "GL_" prefix), as a browser
// without them would. A plain function (the GL calls it through a pointer), hence the global.
std::string g_hidden;  // ",NAME,NAME,"

const GLubyte* hiding_get_stringi(GLenum name, GLuint index) {
  const GLubyte* value = glGetStringi(name, index);
  if (name != GL_EXTENSIONS || value == nullptr) return value;
  std::string ext = reinterpret_cast<const char*>(value);
  if (ext.compare(0, 3, "GL_") == 0) ext = ext.substr(3);
  static const GLubyte kHidden[] = "GL_hidden_by_the_test";
  return g_hidden.find("," + ext + ",") != std::string::npos ? kHidden : value;
}

void* hiding_get_proc_address(const char* name, void*) {
  if (std::strcmp(name, "glGetStringi") == 0) return reinterpret_cast<void*>(&hiding_get_stringi);
  return emscripten_webgl_get_proc_address(name);
}

// A context of its own for a probe (web_try_without, web_try_fitted_kernel), `settings` taken (NULL:
// the defaults in metres), and `run` on it when both succeed; then the context is destroyed. Returns the first sss_result
// that is not SSS_OK (or SSS_OK); the library's message, if any, in g_probe.
template <typename Run>
sss_result probe(sss_get_proc_address_fn get_proc_address, const sss_settings* settings, Run run) {
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = get_proc_address;
  sss_context* sss = nullptr;
  sss_result r = sss_create(&desc, &sss);
  g_probe = r == SSS_OK ? "" : sss_last_error(nullptr);
  if (r != SSS_OK) return r;
  sss_settings defaults;
  sss_default_settings(&defaults);
  defaults.world_units_per_mm = 0.001f;
  r = sss_set_settings(sss, settings != nullptr ? settings : &defaults);
  if (r == SSS_OK) r = run(sss);
  if (r != SSS_OK) g_probe = sss_last_error(sss);
  sss_destroy(sss);
  return r;
}

}  // namespace

extern "C" {

// Creates the WebGL2 context on #canvas (width x height), loads the head (preloaded at
// /assets/head.glb) and the library. 0 on success; else web_message() says why.
EMSCRIPTEN_KEEPALIVE int web_init(int width, int height) {
  EmscriptenWebGLContextAttributes attributes;
  emscripten_webgl_init_context_attributes(&attributes);
  attributes.majorVersion = 2;
  attributes.minorVersion = 0;
  attributes.antialias = EM_FALSE;
  attributes.depth = EM_FALSE;
  attributes.preserveDrawingBuffer = EM_TRUE;  // screenshots read the canvas after the frame
  emscripten_set_canvas_element_size("#canvas", width, height);
  const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context("#canvas", &attributes);
  g_app = std::make_unique<web::App>();
  if (context <= 0) {
    g_text = "WebGL2 is not available in this browser (emscripten_webgl_create_context: " + std::to_string(context) + ")";
    return 1;
  }
  emscripten_webgl_make_context_current(context);
  if (!g_app->init(webgl_get_proc_address, nullptr, "/assets/head.glb", width, height)) return 1;
  g_knobs = g_app->default_knobs();
  return 0;
}

// The last error (the library's sss_last_error after a refused setting) or "".
EMSCRIPTEN_KEEPALIVE const char* web_message() {
  if (g_app && !g_app->message().empty()) return g_app->message().c_str();
  return g_text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* web_gl_renderer() { return g_app ? g_app->renderer().c_str() : ""; }

// The library's defaults: index 0..2 strength, 3..5 falloff, 6 scale, 7 taps.
EMSCRIPTEN_KEEPALIVE double web_default(int index) {
  const web::Knobs k = g_app->default_knobs();
  if (index < 3) return k.strength[index];
  if (index < 6) return k.falloff[index - 3];
  return index == 6 ? k.scale : k.taps;
}

// The page's controls, passed as they are (NaN and out-of-range values included: the library
// judges them). Returns the sss_result of sss_set_settings.
EMSCRIPTEN_KEEPALIVE int web_set_knobs(int enabled, float scale, float strength_multiplier, float falloff_multiplier,
                                       int taps, int follow_surface, int material) {
  const web::Knobs defaults = g_app->default_knobs();
  web::Knobs k = defaults;
  k.enabled = enabled != 0;
  k.scale = scale;
  for (int c = 0; c < 3; ++c) {
    k.strength[c] = defaults.strength[c] * strength_multiplier;
    k.falloff[c] = defaults.falloff[c] * falloff_multiplier;
  }
  k.taps = taps;
  k.follow_surface = follow_surface != 0;
  k.material = material;
  const sss_result r = g_app->set_knobs(k);
  if (r == SSS_OK) g_knobs = k;
  return r;
}

// The material control's entries (web_materials.hpp).
EMSCRIPTEN_KEEPALIVE int web_material_count() { return web::kMaterialCount; }
EMSCRIPTEN_KEEPALIVE const char* web_material_label(int index) {
  return index >= 0 && index < web::kMaterialCount ? web::kMaterials[index].label : "";
}

// One frame onto the canvas; returns the sss_result of sss_apply_frame.
EMSCRIPTEN_KEEPALIVE int web_render(float split) {
  const sss_result r = g_app->render(split);
  g_app->scene().blit_to(0);
  return r;
}

// Median ms of `frames` frames, each waited for (web::App::time_frames).
EMSCRIPTEN_KEEPALIVE double web_time_frames(int frames, float split) {
  const double ms = g_app->time_frames(frames, split);
  g_app->scene().blit_to(0);
  return ms;
}

// The last frame's image, RGBA8 top row first, into out (width * height * 4 bytes).
EMSCRIPTEN_KEEPALIVE void web_read_pixels(uint8_t* out) {
  const std::vector<uint8_t> pixels = g_app->pixels_top_first();
  std::memcpy(out, pixels.data(), pixels.size());
}

// sss_create with the extensions in `names` (comma-separated, no "GL_" prefix) hidden; when that
// succeeds, one frame with the default settings through that context (read with web_read_pixels),
// then the context is destroyed. Returns the sss_result of sss_create or of the frame; the
// library's message in web_probe_message().
EMSCRIPTEN_KEEPALIVE int web_try_without(const char* names) {
  g_hidden = std::string(",") + names + ",";
  const sss_result r =
      probe(hiding_get_proc_address, nullptr, [](sss_context* sss) { return g_app->render_with(sss, 0.0f); });
  g_hidden.clear();
  return r;
}

// The guided kernel family runs NLopt's optimiser, which the WebAssembly build of the tools lacks
// (SSS_NO_NLOPT): sss_set_settings must refuse it with SSS_ERROR_UNSUPPORTED naming NLopt (with the
// tools registered, so the refusal is the optimiser's, not a missing sss_tools_init). Tried on a
// context of its own; returns the sss_result, the message in web_probe_message().
EMSCRIPTEN_KEEPALIVE int web_try_fitted_kernel() {
  sss_kernel_desc kernel;
  sss_default_kernel_desc(&kernel);  // registers the tools' kernels
  kernel.family = SSS_KERNEL_GUIDED;
  sss_settings s;
  sss_default_settings(&s);
  s.kernel = &kernel;
  return probe(webgl_get_proc_address, &s, [](sss_context*) { return SSS_OK; });
}

EMSCRIPTEN_KEEPALIVE const char* web_probe_message() { return g_probe.c_str(); }

EMSCRIPTEN_KEEPALIVE const char* web_result_string(int r) { return sss_result_string(static_cast<sss_result>(r)); }

}  // extern "C"

int main() { return 0; }  // the page calls web_init once the runtime is ready
