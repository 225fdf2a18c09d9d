#include "shapes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace demo {

gltf_mesh::Material flat_material(const char *name, float r, float g, float b) {
  gltf_mesh::Material m;
  m.name = name;
  m.base_color[0] = r;
  m.base_color[1] = g;
  m.base_color[2] = b;
  return m;
}

void MeshBuilder::vertex(glm::vec3 p, glm::vec3 n, float u, float v, glm::vec3 t) {
  const float values[gltf_mesh::Model::kFloatsPerVertex] = {p.x, p.y, p.z, n.x, n.y, n.z, u, v, t.x, t.y, t.z, 1.0f};
  model_->vertices.insert(model_->vertices.end(), values, values + gltf_mesh::Model::kFloatsPerVertex);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) { model_->indices.insert(model_->indices.end(), {a, b, c}); }

void MeshBuilder::end_primitive(int material) {
  gltf_mesh::Primitive p;
  p.first_index = first_index_;
  p.index_count = static_cast<uint32_t>(model_->indices.size()) - first_index_;
  p.material = material;
  model_->primitives.push_back(p);
  first_index_ = static_cast<uint32_t>(model_->indices.size());
}

void MeshBuilder::update_bounds() {
  constexpr size_t kStride = gltf_mesh::Model::kFloatsPerVertex;
  for (size_t k = 0; k < 3; ++k) {
    model_->bounds_min[k] = model_->vertices.empty() ? 0.0f : model_->vertices[k];
    model_->bounds_max[k] = model_->bounds_min[k];
  }
  for (size_t v = 0; v < model_->vertex_count(); ++v) {
    for (size_t k = 0; k < 3; ++k) {
      const float x = model_->vertices[v * kStride + k];
      model_->bounds_min[k] = std::min(model_->bounds_min[k], x);
      model_->bounds_max[k] = std::max(model_->bounds_max[k], x);
    }
  }
}

void add_grid(MeshBuilder *mesh, int rings, int segments,
              const std::function<void(int ring, float phi, glm::vec3 *p, glm::vec3 *n)> &at) {
  const uint32_t first = mesh->base();
  const float step = 2.0f * glm::pi<float>() / static_cast<float>(segments);
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const float phi = step * static_cast<float>(s);
      glm::vec3 p, n, ahead, behind, unused;
      at(r, phi, &p, &n);
      // The tangent along phi, by central differences (zero only on a pole, where any will do).
      at(r, phi + 0.01f * step, &ahead, &unused);
      at(r, phi - 0.01f * step, &behind, &unused);
      glm::vec3 t = ahead - behind;
      t = glm::length(t) > 0.0f ? glm::normalize(t) : glm::vec3(-std::sin(phi), 0.0f, std::cos(phi));
      const float len = glm::length(n);
      mesh->vertex(p, len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f), static_cast<float>(s) / static_cast<float>(segments),
                   static_cast<float>(r) / static_cast<float>(rings), t);
    }
  }
  const uint32_t stride = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r) {
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = first + r * stride + s;
      const uint32_t b = a + stride;
      mesh->triangle(a, a + 1, b);  // CCW from outside
      mesh->triangle(a + 1, b + 1, b);
    }
  }
}

void add_ellipsoid(MeshBuilder *mesh, glm::vec3 centre, glm::vec3 radii, int rings, int segments) {
  add_grid(mesh, rings, segments, [&](int ring, float phi, glm::vec3 *p, glm::vec3 *n) {
    const float theta = glm::pi<float>() * static_cast<float>(ring) / static_cast<float>(rings);
    const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    *p = centre + radii * d;
    *n = d / radii;  // the gradient of |(p - centre) / radii|²
  });
}

void add_sphere(MeshBuilder *mesh, glm::vec3 centre, float radius, int rings, int segments) {
  add_ellipsoid(mesh, centre, glm::vec3(radius), rings, segments);
}

void add_quad(MeshBuilder *mesh, glm::vec3 corner, glm::vec3 u, glm::vec3 v) {
  const uint32_t first = mesh->base();
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  const glm::vec3 t = glm::normalize(u);
  mesh->vertex(corner, n, 0, 0, t);
  mesh->vertex(corner + u, n, 1, 0, t);
  mesh->vertex(corner + u + v, n, 1, 1, t);
  mesh->vertex(corner + v, n, 0, 1, t);
  mesh->triangle(first, first + 1, first + 2);
  mesh->triangle(first, first + 2, first + 3);
}

void add_box(MeshBuilder *mesh, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  add_quad(mesh, lo, y, x);      // -z
  add_quad(mesh, lo + z, x, y);  // +z
  add_quad(mesh, lo, z, y);      // -x
  add_quad(mesh, lo + x, y, z);  // +x
  add_quad(mesh, lo, x, z);      // -y
  add_quad(mesh, lo + y, z, x);  // +y
}

void add_rounded_cylinder(MeshBuilder *mesh, glm::vec3 base, float radius, float height, float cap, int rings,
                          int segments) {
  // Rows: the top's centre, `cap_rows` down the quarter-ellipse to the side, the side's foot, the
  // bottom's rim again (facing down: a hard edge) and its centre.
  const int cap_rows = std::max(rings - 3, 2);
  add_grid(mesh, cap_rows + 3, segments, [&](int ring, float phi, glm::vec3 *p, glm::vec3 *n) {
    float r = 0.0f, h = 0.0f, nr = 0.0f, nh = 0.0f;
    if (ring <= cap_rows) {
      const float alpha = 0.5f * glm::pi<float>() * static_cast<float>(ring) / static_cast<float>(cap_rows);
      r = radius * std::sin(alpha);
      h = height - cap + cap * std::cos(alpha);
      nr = std::sin(alpha) / radius;  // the ellipse's gradient
      nh = std::cos(alpha) / cap;
    } else if (ring == cap_rows + 1) {
      r = radius;
      nr = 1.0f;
    } else {
      r = ring == cap_rows + 2 ? radius : 0.0f;
      nh = -1.0f;
    }
    *p = base + glm::vec3(r * std::cos(phi), h, r * std::sin(phi));
    *n = glm::vec3(nr * std::cos(phi), nh, nr * std::sin(phi));
  });
}

void add_capsule(MeshBuilder *mesh, glm::vec3 a, glm::vec3 b, float radius, glm::vec3 flat_axis, float flatten,
                 int rings, int segments) {
  // Rows 0..half around the end b (theta 0..pi/2), half+1..2 half + 1 around a (pi/2..pi); the row
  // between the two hemispheres' equators is the cylinder. Frame: e1 x axis = e2, as x x y = z.
  const int half = std::max(rings / 2, 2);
  const glm::vec3 axis = glm::normalize(b - a);
  const glm::vec3 e1 = glm::normalize(flat_axis - axis * glm::dot(flat_axis, axis));
  const glm::vec3 e2 = glm::cross(e1, axis);
  add_grid(mesh, 2 * half + 1, segments, [&](int ring, float phi, glm::vec3 *p, glm::vec3 *n) {
    const bool top = ring <= half;
    const float theta = 0.5f * glm::pi<float>() * (top ? static_cast<float>(ring) : static_cast<float>(ring - 1)) /
                        static_cast<float>(half);
    const glm::vec3 d = std::cos(theta) * axis + std::sin(theta) * (std::cos(phi) * e1 + std::sin(phi) * e2);
    const float along = glm::dot(d, e1);
    *p = (top ? b : a) + radius * (d - (1.0f - flatten) * along * e1);
    *n = d + (1.0f / flatten - 1.0f) * along * e1;  // the inverse transpose of the flattening
  });
}

}  // namespace demo
