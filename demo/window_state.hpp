// What the window shows and what the panel changes (window_app.cpp owns it, panel.cpp draws it).
#pragma once

#include "camera.hpp"
#include "composite.hpp"
#include "heat_map.hpp"
#include "pixel_count.hpp"
#include "renderer.hpp"
#include "scene.hpp"
#include "sss_stage.hpp"

#include <deque>
#include <string>

namespace demo {

struct WindowState {
  const DemoScene *scene = nullptr;
  std::string renderer_name;  // GL_RENDERER
  std::string out_dir;        // screenshots

  // The picture.
  OrbitCamera camera;
  Preset preset = Preset::kClose;  // the last preset chosen
  SssControls controls;
  ViewMode view = ViewMode::kFinal;
  float exposure = 1.0f;
  float split = 0.5f;
  float heat_scale = 0.05f;
  int heat_factor = 4;

  // What the last frames measured.
  std::deque<PassTimes> times;  // the last kTimeHistory frames
  PixelCounts counts;
  bool preintegrated = false;  // the last frame shaded skin with the pre-integrated LUTs
  float pixels_per_mm = 0.0f;  // a millimetre at the subject, in pixels (the automatic choice)
  std::string profile_note;    // SssStage::profile_note: why the other materials are left unfiltered
  int width = 0, height = 0;  // framebuffer
  double frame_ms = 0.0;      // wall clock between frames

  // The heat map (heat_map.hpp).
  bool heat_ready = false;     // the texture shows the current camera
  bool heat_computing = false; // the exact reference runs on a background thread
  HeatMap heat;                // errors of the last map (image dropped)
  double reference_seconds = 0.0;
  int small_width = 0, small_height = 0;

  // Requests from keys and buttons, handled by the frame loop.
  bool screenshot_requested = false;
  bool preset_requested = false;
  bool quit_requested = false;
  std::string message;  // the last screenshot written, or an error
};

constexpr size_t kTimeHistory = 120;

// Draws the panel (ImGui::NewFrame has run) and the attribution overlay; changes the state.
void draw_panel(WindowState *state);

}  // namespace demo
