// The orbit camera and the three presets (close-up, mid shot, far shot).
#pragma once

#include "scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace demo {

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 1.0f;       // from the eye to the target, world units
  float yaw_degrees = 0.0f;    // around +Y, from +Z (the face) towards +X
  float pitch_degrees = 0.0f;  // elevation
  float fovy_degrees = 30.0f;
};

enum class Preset { kClose, kMid, kFar };
constexpr Preset kPresets[] = {Preset::kClose, Preset::kMid, Preset::kFar};

const char *preset_name(Preset preset);   // "close", "mid", "far"
const char *preset_title(Preset preset);  // "close-up", "mid shot", "far shot"
bool preset_from_name(const std::string &name, Preset *out);

// The presets, fitted to the scene's subject of height h (the head: 0.36 m), vertical field of view
// 30 degrees, yawed 20 degrees towards +X and 5 degrees above (the benchmark's head cameras):
//   close  frame height 0.583 h at a target 0.208 h above and 0.222 h in front of the centre (the face)
//   mid    frame height 3 h at the centre;   far  frame height 10 h at the centre.
OrbitCamera preset_camera(const DemoScene &scene, Preset preset);

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // glm::perspective: GL clip conventions, depth [-1, 1]
  glm::mat4 view_projection{1.0f};
  glm::vec3 eye{0.0f};
  float near_plane = 0.1f;
  float far_plane = 10.0f;
};

// Near and far planes hug the scene's bounds (all of it in front of the camera when possible).
CameraMatrices camera_matrices(const OrbitCamera &camera, const Bounds &scene_bounds, int width, int height);

// Mouse moves: orbit (pixels dragged), zoom (scroll steps), pan (pixels dragged, in the image plane).
void orbit(OrbitCamera *camera, float dx_pixels, float dy_pixels);
void zoom(OrbitCamera *camera, float steps);
void pan(OrbitCamera *camera, float dx_pixels, float dy_pixels, int viewport_height);

}  // namespace demo
