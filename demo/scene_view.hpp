// Camera and light of the demo scene.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace demo {

struct SceneView {
  glm::mat4 view;
  glm::mat4 projection;          // glm::perspective, GL depth convention [-1, 1]
  glm::mat4 view_projection;
  glm::vec3 eye;
  float fovy_degrees;
  float near_plane;
  float far_plane;

  glm::vec3 light_direction;     // unit vector from the surface towards the (directional) light
  glm::vec3 light_irradiance;    // linear RGB, at normal incidence
  glm::vec3 sky_ambient;         // ambient from above / below, blended by the normal's y
  glm::vec3 ground_ambient;
  glm::mat4 light_view_projection;  // orthographic, covers the sphere, the box and their shadows
  float shadow_extent;           // metres covered by the shadow map's side

  glm::vec3 focus_point;         // where the box's shadow edge crosses the front of the sphere
};

// Pixel (x right, y down) where a world point lands in a width x height image of the view.
glm::ivec2 project_to_pixel(const SceneView &view, const glm::vec3 &point, int width, int height);

SceneView make_scene_view(int width, int height);

}  // namespace demo
