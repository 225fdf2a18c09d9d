#include "scene_geometry.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstddef>

namespace demo {

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct MeshBuilder {
  std::vector<Vertex> vertices;
  std::vector<GLuint> indices;

  GLuint base() const { return static_cast<GLuint>(vertices.size()); }
};

void add_sphere(MeshBuilder *mesh, glm::vec3 centre, float radius, int rings, int segments) {
  const GLuint first = mesh->base();
  for (int r = 0; r <= rings; ++r) {
    const float theta = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * glm::pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh->vertices.push_back({centre + radius * n, n});
    }
  }
  const GLuint stride = static_cast<GLuint>(segments + 1);
  for (GLuint r = 0; r < static_cast<GLuint>(rings); ++r) {
    for (GLuint s = 0; s < static_cast<GLuint>(segments); ++s) {
      const GLuint a = first + r * stride + s;
      const GLuint b = a + stride;
      // Counter-clockwise seen from outside.
      mesh->indices.insert(mesh->indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
}

// One quad: corner + two edge vectors; the normal is cross(u, v).
void add_quad(MeshBuilder *mesh, glm::vec3 corner, glm::vec3 u, glm::vec3 v) {
  const GLuint first = mesh->base();
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  mesh->vertices.push_back({corner, n});
  mesh->vertices.push_back({corner + u, n});
  mesh->vertices.push_back({corner + u + v, n});
  mesh->vertices.push_back({corner + v, n});
  mesh->indices.insert(mesh->indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
}

void add_box(MeshBuilder *mesh, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  add_quad(mesh, lo, y, x);                      // -z
  add_quad(mesh, lo + z, x, y);                  // +z
  add_quad(mesh, lo, z, y);                      // -x
  add_quad(mesh, lo + x, y, z);                  // +x
  add_quad(mesh, lo, x, z);                      // -y
  add_quad(mesh, lo + y, z, x);                  // +y
}

SceneObject make_object(const char *name, const MeshBuilder &mesh, size_t first_index) {
  SceneObject o{};
  o.name = name;
  o.index_offset = first_index * sizeof(GLuint);
  o.index_count = static_cast<GLsizei>(mesh.indices.size() - first_index);
  return o;
}

}  // namespace

SceneGeometry create_scene_geometry() {
  MeshBuilder mesh;
  SceneGeometry geometry;

  size_t first = mesh.indices.size();
  add_quad(&mesh, glm::vec3(-1.5f, 0.0f, -1.5f), glm::vec3(0, 0, 3.0f), glm::vec3(3.0f, 0, 0));
  SceneObject ground = make_object("ground", mesh, first);
  ground.albedo = glm::vec3(0.42f, 0.42f, 0.40f);
  ground.specular_f0 = 0.02f;
  ground.gloss = 8.0f;
  geometry.objects.push_back(ground);

  first = mesh.indices.size();
  add_box(&mesh, glm::vec3(-0.26f, 0.0f, -0.12f), glm::vec3(-0.16f, 0.24f, 0.27f));
  SceneObject box = make_object("box", mesh, first);
  box.albedo = glm::vec3(0.30f, 0.36f, 0.48f);
  box.specular_f0 = 0.04f;
  box.gloss = 32.0f;
  geometry.objects.push_back(box);

  first = mesh.indices.size();
  add_sphere(&mesh, kSphereCentre, kSphereRadius, 96, 192);
  SceneObject sphere = make_object("sphere", mesh, first);
  sphere.albedo = glm::vec3(0.85f, 0.55f, 0.45f);
  sphere.sss_strength = 1.0f;
  sphere.specular_f0 = 0.028f;  // skin
  sphere.gloss = 40.0f;
  sphere.translucent = true;
  geometry.objects.push_back(sphere);

  glGenVertexArrays(1, &geometry.vao);
  glBindVertexArray(geometry.vao);
  glGenBuffers(1, &geometry.vertex_buffer);
  glBindBuffer(GL_ARRAY_BUFFER, geometry.vertex_buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &geometry.index_buffer);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, geometry.index_buffer);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(GLuint)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void *>(offsetof(Vertex, position)));
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void *>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return geometry;
}

void destroy_scene_geometry(SceneGeometry *geometry) {
  glDeleteVertexArrays(1, &geometry->vao);
  glDeleteBuffers(1, &geometry->vertex_buffer);
  glDeleteBuffers(1, &geometry->index_buffer);
  *geometry = SceneGeometry{};
}

void draw_object(const SceneObject &object) {
  glDrawElements(GL_TRIANGLES, object.index_count, GL_UNSIGNED_INT,
                 reinterpret_cast<const void *>(object.index_offset));
}

}  // namespace demo
