#include "camera.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace demo {

const char *preset_name(Preset preset) {
  switch (preset) {
    case Preset::kClose: return "close";
    case Preset::kMid: return "mid";
    case Preset::kFar: return "far";
  }
  return "?";
}

const char *preset_title(Preset preset) {
  switch (preset) {
    case Preset::kClose: return "close-up";
    case Preset::kMid: return "mid shot";
    case Preset::kFar: return "far shot";
  }
  return "?";
}

bool preset_from_name(const std::string &name, Preset *out) {
  for (Preset p : kPresets) {
    if (name == preset_name(p)) {
      *out = p;
      return true;
    }
  }
  return false;
}

OrbitCamera preset_camera(const DemoScene &scene, Preset preset) {
  OrbitCamera c;
  c.fovy_degrees = 30.0f;
  c.yaw_degrees = 20.0f;
  c.pitch_degrees = 5.0f;
  const float h = std::max(scene.subject.size().y, 1e-6f);
  float frame_height = 0.0f;
  switch (preset) {
    case Preset::kClose:
      c.target = scene.subject.centre() + glm::vec3(0.0f, 0.208f * h, 0.222f * h);
      frame_height = 0.583f * h;
      break;
    case Preset::kMid:
      c.target = scene.subject.centre();
      frame_height = 3.0f * h;
      break;
    case Preset::kFar:
      c.target = scene.subject.centre();
      frame_height = 10.0f * h;
      break;
  }
  c.distance = frame_height / (2.0f * std::tan(glm::radians(0.5f * c.fovy_degrees)));
  return c;
}

CameraMatrices camera_matrices(const OrbitCamera &camera, const Bounds &scene_bounds, int width, int height) {
  CameraMatrices m;
  const float yaw = glm::radians(camera.yaw_degrees);
  const float pitch = glm::radians(camera.pitch_degrees);
  const glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  m.eye = camera.target + offset * camera.distance;
  m.view = glm::lookAt(m.eye, camera.target, glm::vec3(0.0f, 1.0f, 0.0f));

  // Distance range of the scene's bounding sphere along the view axis, with a margin.
  const glm::vec3 forward = -offset;
  const float centre_depth = glm::dot(scene_bounds.centre() - m.eye, forward);
  const float radius = std::max(scene_bounds.radius(), 1e-4f) * 1.05f;
  m.far_plane = std::max(centre_depth + radius, 1e-3f);
  m.near_plane = std::max(centre_depth - radius, m.far_plane * 2e-3f);
  m.projection = glm::perspective(glm::radians(camera.fovy_degrees),
                                  static_cast<float>(width) / static_cast<float>(height), m.near_plane, m.far_plane);
  m.view_projection = m.projection * m.view;
  return m;
}

void orbit(OrbitCamera *camera, float dx_pixels, float dy_pixels) {
  camera->yaw_degrees -= 0.3f * dx_pixels;
  camera->yaw_degrees = std::remainder(camera->yaw_degrees, 360.0f);
  camera->pitch_degrees = std::clamp(camera->pitch_degrees + 0.3f * dy_pixels, -85.0f, 85.0f);
}

void zoom(OrbitCamera *camera, float steps) {
  camera->distance = std::clamp(camera->distance * std::pow(0.9f, steps), 0.02f, 100.0f);
}

void pan(OrbitCamera *camera, float dx_pixels, float dy_pixels, int viewport_height) {
  const float yaw = glm::radians(camera->yaw_degrees);
  const float pitch = glm::radians(camera->pitch_degrees);
  const glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), offset));
  const glm::vec3 up = glm::cross(offset, right);
  // World units per pixel at the target's distance.
  const float scale = 2.0f * camera->distance * std::tan(glm::radians(0.5f * camera->fovy_degrees)) /
                      static_cast<float>(std::max(viewport_height, 1));
  camera->target += (-dx_pixels * right + dy_pixels * up) * scale;
}

}  // namespace demo
