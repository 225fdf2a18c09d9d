// sss_demo in a window: GLFW (GL 3.3 core), the renderer drawing into its targets, the output blitted
// to the window, the Dear ImGui panel on top. F12 (or --screenshot-frame) saves the frame as
// rendered (screenshot-NNN.png, the same pixels the headless mode writes) and the window with the
// panel (screenshot-NNN-window.png), the attribution in both files' metadata and a sidecar .txt.
#include "apps.hpp"

#include "heat_map.hpp"
#include "host_gl_util.hpp"
#include "image.hpp"
#include "png_output.hpp"
#include "renderer.hpp"
#include "report.hpp"
#include "window_state.hpp"

#define GLFW_INCLUDE_NONE  // GL comes from host_gl, not from the system's GL/gl.h
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <future>
#include <string>
#include <system_error>

namespace demo {

namespace {

std::string g_glfw_error;

void on_glfw_error(int code, const char *description) {
  g_glfw_error = description != nullptr ? description : "unknown";
  std::fprintf(stderr, "sss_demo: GLFW error 0x%x: %s\n", code, g_glfw_error.c_str());
}

// glfwGetProcAddress with the loader signature of host_gl and the library.
void *glfw_get_proc_address(const char *name, void * /*user*/) {
  const GLFWglproc proc = glfwGetProcAddress(name);
  void *address = nullptr;
  static_assert(sizeof proc == sizeof address, "function and object pointers differ in size");
  std::memcpy(&address, &proc, sizeof address);
  return address;
}

// Input the callbacks collect for the frame loop (ImGui's GLFW backend chains to them).
struct Input {
  WindowState *state = nullptr;
  double scroll = 0.0;
};

void on_key(GLFWwindow *window, int key, int /*scancode*/, int action, int /*mods*/) {
  auto *input = static_cast<Input *>(glfwGetWindowUserPointer(window));
  if (input == nullptr || action != GLFW_PRESS) return;
  WindowState *s = input->state;
  if (key == GLFW_KEY_F12) s->screenshot_requested = true;
  if (key == GLFW_KEY_ESCAPE) s->quit_requested = true;
  if (ImGui::GetIO().WantCaptureKeyboard) return;  // typing into a field
  switch (key) {
    case GLFW_KEY_S: s->controls.enabled = !s->controls.enabled; break;
    case GLFW_KEY_V: s->view = static_cast<ViewMode>((static_cast<int>(s->view) + 1) % kViewModeCount); break;
    case GLFW_KEY_1: s->preset = Preset::kClose; s->preset_requested = true; break;
    case GLFW_KEY_2: s->preset = Preset::kMid; s->preset_requested = true; break;
    case GLFW_KEY_3: s->preset = Preset::kFar; s->preset_requested = true; break;
    default: break;
  }
}

void on_scroll(GLFWwindow *window, double /*dx*/, double dy) {
  auto *input = static_cast<Input *>(glfwGetWindowUserPointer(window));
  if (input != nullptr && !ImGui::GetIO().WantCaptureMouse) input->scroll += dy;
}

// Orbit with the left button, pan with the right or middle one, while the mouse is not on the panel.
class MouseDrag {
 public:
  void update(GLFWwindow *window, WindowState *s) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                       glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    if (!left && !right) {
      dragging_ = false;
    } else if (!dragging_) {
      dragging_ = !ImGui::GetIO().WantCaptureMouse;  // a drag starts outside the panel
    } else {
      const float dx = static_cast<float>(x - last_x_), dy = static_cast<float>(y - last_y_);
      int window_height = 1;
      glfwGetWindowSize(window, nullptr, &window_height);
      if (left)
        orbit(&s->camera, dx, dy);
      else
        pan(&s->camera, dx, dy, window_height);
    }
    last_x_ = x;
    last_y_ = y;
  }

 private:
  bool dragging_ = false;
  double last_x_ = 0.0, last_y_ = 0.0;
};

bool same_camera(const OrbitCamera &a, const OrbitCamera &b) {
  return a.target == b.target && a.distance == b.distance && a.yaw_degrees == b.yaw_degrees &&
         a.pitch_degrees == b.pitch_degrees && a.fovy_degrees == b.fovy_degrees;
}

// The heat map's small frame, its exact reference (background thread) and the map's texture.
class HeatMapper {
 public:
  ~HeatMapper() { release(); }

  void release() {
    if (pending_.valid()) pending_.wait();
    if (small_.width != 0) destroy_frame_targets(&small_);
    if (texture_ != 0) glDeleteTextures(1, &texture_);
    texture_ = 0;
  }

  // Renders the small frame and refreshes the map; returns the texture to show, or 0 while the
  // reference for this camera is still being computed.
  GLuint update(Renderer *renderer, WindowState *s) {
    int w = 0, h = 0;
    small_frame_size(s->width, s->height, s->heat_factor, &w, &h);
    s->small_width = w;
    s->small_height = h;
    if (small_.width != w || small_.height != h) {
      if (small_.width != 0) destroy_frame_targets(&small_);
      if (!create_frame_targets(&small_, w, h)) return 0;
      if (texture_ != 0) glDeleteTextures(1, &texture_);
      texture_ = make_texture(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE);
    }
    const CameraMatrices m = camera_matrices(s->camera, renderer->scene->all, w, h);
    FrameResult frame;
    SssControls controls = s->controls;
    controls.decision_height = s->height;  // choose the shading as the shown frame does
    controls.debug_view = 0;  // the error of the filtered image
    if (!render_frame(renderer, m, controls, &small_, false, &frame)) return 0;
    SmallFrame data = read_small_frame(small_, m, frame.sss_ran, renderer->scene->world_units_per_mm,
                                       frame.preintegrated ? 0 : static_cast<int>(renderer->sss.settings.texturing));
    data.materials = reference_materials(*renderer->scene);

    // Collect a finished reference; start one when the camera or size moved on.
    if (pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      reference_ = pending_.get();
      reference_camera_ = pending_camera_;
      have_reference_ = true;
    }
    const bool current = have_reference_ && same_camera(reference_camera_, s->camera) && reference_.width == w &&
                         reference_.height == h && reference_.texturing == data.texturing;
    if (!current && !pending_.valid()) {
      pending_camera_ = s->camera;
      pending_ = std::async(std::launch::async, [data]() { return compute_reference(data); });
    }
    s->heat_computing = pending_.valid();
    s->heat_ready = current;
    if (!current) return 0;
    s->reference_seconds = reference_.seconds;
    s->heat = make_heat_map(data, reference_, s->controls.enabled, s->heat_scale, s->exposure);
    const std::vector<std::uint8_t> rows = gl_rows_from_image(s->heat.image);
    s->heat.image = Image{};
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture_;
  }

 private:
  FrameTargets small_;
  GLuint texture_ = 0;
  std::future<Reference> pending_;
  OrbitCamera pending_camera_;
  Reference reference_;
  OrbitCamera reference_camera_;
  bool have_reference_ = false;
};

// screenshot-NNN with the first NNN not taken in the output folder.
std::string next_screenshot_stem(const std::string &dir) {
  for (int n = 1; n < 100000; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "screenshot-%03d", n);
    const std::filesystem::path stem = std::filesystem::path(dir) / name;
    std::error_code ec;
    if (!std::filesystem::exists(stem.string() + ".png", ec)) return stem.string();
  }
  return (std::filesystem::path(dir) / "screenshot").string();
}

// The frame as rendered (targets.output) and the window's back buffer with the panel.
void save_screenshot(WindowState *s, const FrameTargets &targets, const sss_settings &settings_held) {
  std::error_code ec;
  std::filesystem::create_directories(s->out_dir, ec);
  const std::string stem = next_screenshot_stem(s->out_dir);
  const Image frame = image_from_gl_rows(read_output(targets), targets.width, targets.height);
  std::vector<std::uint8_t> window_rows(static_cast<size_t>(s->width) * static_cast<size_t>(s->height) * 4u);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, s->width, s->height, GL_RGBA, GL_UNSIGNED_BYTE, window_rows.data());
  const Image window = image_from_gl_rows(window_rows, s->width, s->height);

  const std::string settings =
      format_settings(settings_held, s->controls, s->scene->world_units_per_mm);
  char camera[256];
  std::snprintf(camera, sizeof camera, "camera: target (%.3f, %.3f, %.3f), distance %.3f, yaw %.1f, pitch %.1f, fovy %.0f",
                static_cast<double>(s->camera.target.x), static_cast<double>(s->camera.target.y),
                static_cast<double>(s->camera.target.z), static_cast<double>(s->camera.distance),
                static_cast<double>(s->camera.yaw_degrees), static_cast<double>(s->camera.pitch_degrees),
                static_cast<double>(s->camera.fovy_degrees));
  const std::string description = std::string("view ") + view_mode_name(s->view) + ", " + s->scene->name + ", " +
                                  std::to_string(targets.width) + "x" + std::to_string(targets.height) + ". " +
                                  settings + ". " + camera;
  bool ok = write_png(stem + ".png", frame, image_text(*s->scene, "sss_demo screenshot", description, s->renderer_name));
  ok = write_png(stem + "-window.png", window,
                 image_text(*s->scene, "sss_demo screenshot (window)", description, s->renderer_name)) &&
       ok;
  if (std::FILE *f = std::fopen((stem + ".txt").c_str(), "w")) {
    std::fprintf(f, "%s.png: the frame as rendered; %s-window.png: the window with the panel.\n%s\nGL_RENDERER %s\n",
                 stem.c_str(), stem.c_str(), description.c_str(), s->renderer_name.c_str());
    if (!s->scene->attribution.empty()) std::fprintf(f, "Attribution: %s\n", s->scene->attribution.c_str());
    ok = std::fclose(f) == 0 && ok;
  } else {
    ok = false;
  }
  s->message = ok ? "saved " + stem + ".png (+ -window.png, .txt)" : "could not save " + stem + ".png";
  std::printf("sss_demo: %s\n", s->message.c_str());
}

}  // namespace

int run_window(const Options &o, const DemoScene &scene) {
  glfwSetErrorCallback(on_glfw_error);
  if (glfwInit() != GLFW_TRUE) {
    std::fprintf(stderr, "sss_demo: cannot open a window (%s). Without a display, run with --headless.\n",
                 g_glfw_error.c_str());
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  const std::string title = "sss demo: " + scene.name + " (S: SSS on/off, F12: screenshot)";
  GLFWwindow *window = glfwCreateWindow(o.width, o.height, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "sss_demo: cannot create a GL 3.3 core window (%s)\n", g_glfw_error.c_str());
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  std::string missing;
  if (!host_gl::load(glfw_get_proc_address, nullptr, &missing)) {
    std::fprintf(stderr, "sss_demo: GL functions missing: %s\n", missing.c_str());
    glfwDestroyWindow(window);
    glfwTerminate();
    return 1;
  }

  WindowState s;
  s.scene = &scene;
  s.out_dir = o.out_dir;
  const char *renderer_name = reinterpret_cast<const char *>(glGetString(GL_RENDERER));
  s.renderer_name = renderer_name != nullptr ? renderer_name : "(unknown)";
  s.controls = controls_from_options(o);
  s.view = o.view;
  s.exposure = o.exposure;
  s.heat_scale = o.heat_scale;
  s.heat_factor = o.heat_factor;
  s.preset = o.presets.front();
  s.camera = preset_camera(scene, s.preset);
  std::printf("sss_demo: window %dx%d, %s, GL_RENDERER %s\n", o.width, o.height, scene.name.c_str(),
              s.renderer_name.c_str());

  // Our callbacks first: ImGui's GLFW backend installs its own and chains to these.
  Input input;
  input.state = &s;
  glfwSetWindowUserPointer(window, &input);
  glfwSetKeyCallback(window, on_key);
  glfwSetScrollCallback(window, on_scroll);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  Renderer renderer;
  FrameTargets targets;
  HeatMapper heat;
  MouseDrag drag;
  bool ok = create_renderer(&renderer, scene, glfw_get_proc_address, nullptr);
  int frame_index = 0;
  auto last = std::chrono::steady_clock::now();
  while (ok && glfwWindowShouldClose(window) == 0 && !s.quit_requested) {
    glfwPollEvents();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (w <= 0 || h <= 0) {  // minimised
      glfwWaitEvents();
      continue;
    }
    if (w != targets.width || h != targets.height || s.controls.msaa_samples != targets.samples) {
      if (targets.width != 0) destroy_frame_targets(&targets);
      if (!(ok = create_frame_targets(&targets, w, h, s.controls.msaa_samples))) break;
    }
    s.width = w;
    s.height = h;
    drag.update(window, &s);
    if (input.scroll != 0.0) {
      zoom(&s.camera, static_cast<float>(input.scroll));
      input.scroll = 0.0;
    }
    if (s.preset_requested) {
      s.camera = preset_camera(scene, s.preset);
      s.preset_requested = false;
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    draw_panel(&s);
    ImGui::Render();

    const CameraMatrices m = camera_matrices(s.camera, scene.all, w, h);
    FrameResult frame;
    if (!(ok = render_frame(&renderer, m, s.controls, &targets, true, &frame))) break;
    s.counts = frame.counts;
    s.preintegrated = frame.preintegrated;
    s.pixels_per_mm = frame.pixels_per_mm;
    s.profile_note = renderer.sss.profile_note;
    GLuint heat_texture = 0;
    ViewMode mode = s.view;
    if (mode == ViewMode::kHeatMap) {
      heat_texture = heat.update(&renderer, &s);
      if (heat_texture == 0) mode = ViewMode::kFinal;  // until the reference is there
    }
    composite_frame(renderer, targets, frame, mode, s.exposure, s.split, heat_texture, &frame.times);
    s.times.push_back(frame.times);
    while (s.times.size() > kTimeHistory) s.times.pop_front();

    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.output_framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (frame_index == o.screenshot_frame) s.screenshot_requested = true;
    if (s.screenshot_requested) {
      save_screenshot(&s, targets, renderer.sss.settings);
      s.screenshot_requested = false;
    }
    ok = check_gl("the window frame");
    glfwSwapBuffers(window);

    const auto now = std::chrono::steady_clock::now();
    s.frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
    ++frame_index;
    if (o.frames > 0 && frame_index >= o.frames) break;
  }
  if (ok && !s.times.empty()) {
    std::printf("sss_demo: %d frames; last: %s\n", frame_index, format_times(s.times.back()).c_str());
  }
  heat.release();
  if (targets.width != 0) destroy_frame_targets(&targets);
  destroy_renderer(&renderer);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return ok ? 0 : 1;
}

}  // namespace demo
