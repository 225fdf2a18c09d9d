// The demo scene's meshes and materials: a skin-coloured sphere on a ground plane and a box that
// throws a hard shadow across it. World units are metres; all meshes are in world space.
#pragma once

#include "gl_functions.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace demo {

struct SceneObject {
  const char *name;
  GLsizei index_count;
  size_t index_offset;  // bytes into the index buffer
  glm::vec3 albedo;
  float sss_strength;   // written to the diffuse alpha: the library's per-pixel width scale
  float specular_f0;    // Fresnel reflectance at normal incidence
  float gloss;          // Blinn-Phong exponent
  bool translucent;     // marked with stencil = 1
};

struct SceneGeometry {
  GLuint vao = 0;
  GLuint vertex_buffer = 0;
  GLuint index_buffer = 0;
  std::vector<SceneObject> objects;
};

// Builds the meshes and uploads them (attribute 0: position, 1: normal). Needs a current context.
SceneGeometry create_scene_geometry();
void destroy_scene_geometry(SceneGeometry *geometry);

// Draws one object; the scene's VAO must be bound.
void draw_object(const SceneObject &object);

// Sphere placement, for the camera and the light to aim at.
constexpr float kSphereRadius = 0.1f;
const glm::vec3 kSphereCentre(0.0f, 0.1f, 0.0f);

}  // namespace demo
