// Meshes generated in code for the demo's procedural objects (the sphere scene, the marble bust, the
// wax candle, the hand): positions, normals, texcoords and tangents in gltf_mesh's vertex layout,
// counter-clockwise from outside, appended to a Model one primitive at a time.
#pragma once

#include "gltf_mesh.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>

namespace demo {

// A material of one linear base colour, no textures.
gltf_mesh::Material flat_material(const char *name, float r, float g, float b);

class MeshBuilder {
 public:
  // Appends to `model` (its primitives so far stay as they are).
  explicit MeshBuilder(gltf_mesh::Model *model)
      : model_(model), first_index_(static_cast<uint32_t>(model->indices.size())) {}

  uint32_t base() const { return static_cast<uint32_t>(model_->vertex_count()); }
  void vertex(glm::vec3 p, glm::vec3 n, float u, float v, glm::vec3 t);
  void triangle(uint32_t a, uint32_t b, uint32_t c);
  // Closes the primitive begun at the last primitive's end (or index 0) with `material`.
  void end_primitive(int material);
  // The model's bounds from every vertex.
  void update_bounds();

 private:
  gltf_mesh::Model *model_;
  uint32_t first_index_;
};

// A closed surface as a grid of rings + 1 rows of segments + 1 vertices: `at(ring, phi, &p, &n)` for
// ring in [0, rings] (pole to pole) and phi in [0, 2 pi] (around; 0 and 2 pi the same seam) gives a
// point and its outward normal (need not be unit), with the orientation of the unit sphere's
// (sin theta cos phi, cos theta, sin theta sin phi), theta = pi ring / rings. Every shape below is one.
void add_grid(MeshBuilder *mesh, int rings, int segments,
              const std::function<void(int ring, float phi, glm::vec3 *p, glm::vec3 *n)> &at);

// An ellipsoid of semi-axes `radii` centred at `centre`.
void add_ellipsoid(MeshBuilder *mesh, glm::vec3 centre, glm::vec3 radii, int rings, int segments);
void add_sphere(MeshBuilder *mesh, glm::vec3 centre, float radius, int rings, int segments);

// One quad: corner + two edge vectors; the normal is cross(u, v).
void add_quad(MeshBuilder *mesh, glm::vec3 corner, glm::vec3 u, glm::vec3 v);
// An axis-aligned box.
void add_box(MeshBuilder *mesh, glm::vec3 lo, glm::vec3 hi);

// A cylinder around +Y from `base` up `height`, flat bottom, its top rounded by a quarter-ellipse of
// `cap` height (a candle: the wax melts round at the rim).
void add_rounded_cylinder(MeshBuilder *mesh, glm::vec3 base, float radius, float height, float cap, int rings,
                          int segments);

// A capsule (a finger) from `a` to `b`, radius `radius`, its cross-section scaled by `flatten` along
// `flat_axis` (unit, perpendicular to b - a): 1 is round, < 1 flatter.
void add_capsule(MeshBuilder *mesh, glm::vec3 a, glm::vec3 b, float radius, glm::vec3 flat_axis, float flatten,
                 int rings, int segments);

}  // namespace demo
