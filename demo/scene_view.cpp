#include "scene_view.hpp"

#include "scene_geometry.hpp"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace demo {

SceneView make_scene_view(int width, int height) {
  SceneView v{};
  v.fovy_degrees = 30.0f;
  v.near_plane = 0.05f;
  v.far_plane = 20.0f;
  v.eye = glm::vec3(0.02f, 0.25f, 0.72f);
  const glm::vec3 target(0.0f, 0.10f, 0.0f);
  v.view = glm::lookAt(v.eye, target, glm::vec3(0, 1, 0));
  v.projection = glm::perspective(glm::radians(v.fovy_degrees),
                                  static_cast<float>(width) / static_cast<float>(height), v.near_plane,
                                  v.far_plane);
  v.view_projection = v.projection * v.view;

  v.light_direction = glm::normalize(glm::vec3(-0.8f, 0.7f, 0.6f));
  v.light_irradiance = glm::vec3(2.0f, 1.9f, 1.8f);
  v.sky_ambient = glm::vec3(0.16f, 0.18f, 0.22f);
  v.ground_ambient = glm::vec3(0.08f, 0.07f, 0.06f);

  v.shadow_extent = 1.2f;
  const float half = 0.5f * v.shadow_extent;
  const glm::vec3 light_eye = kSphereCentre + v.light_direction * 2.0f;
  const glm::mat4 light_view = glm::lookAt(light_eye, kSphereCentre, glm::vec3(0, 1, 0));
  const glm::mat4 light_projection = glm::ortho(-half, half, -half, half, 0.5f, 4.0f);
  v.light_view_projection = light_projection * light_view;

  // The box's top edge (x = -0.16, y = 0.24) throws its shadow plane through this point.
  v.focus_point = kSphereCentre + glm::vec3(0.0f, 0.0f, kSphereRadius);
  return v;
}

glm::ivec2 project_to_pixel(const SceneView &view, const glm::vec3 &point, int width, int height) {
  const glm::vec4 clip = view.view_projection * glm::vec4(point, 1.0f);
  const float nx = clip.x / clip.w;
  const float ny = clip.y / clip.w;
  return glm::ivec2(static_cast<int>((nx * 0.5f + 0.5f) * static_cast<float>(width)),
                    static_cast<int>((0.5f - ny * 0.5f) * static_cast<float>(height)));
}

}  // namespace demo
