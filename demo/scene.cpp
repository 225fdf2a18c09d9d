#include "scene.hpp"

#include "shared_assets.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>

namespace demo {

float Bounds::radius() const { return 0.5f * glm::length(max - min); }

namespace {

Bounds model_bounds(const gltf_mesh::Model &model) {
  Bounds b;
  b.min = glm::vec3(model.bounds_min[0], model.bounds_min[1], model.bounds_min[2]);
  b.max = glm::vec3(model.bounds_max[0], model.bounds_max[1], model.bounds_max[2]);
  return b;
}

// Gives every primitive without a material the default one (white, no textures), appended last.
void add_default_material(gltf_mesh::Model *model) {
  bool needed = false;
  for (const gltf_mesh::Primitive &p : model->primitives) needed = needed || p.material < 0;
  if (!needed) return;
  gltf_mesh::Material fallback;
  fallback.name = "(default)";
  model->materials.push_back(fallback);
  const int index = static_cast<int>(model->materials.size()) - 1;
  for (gltf_mesh::Primitive &p : model->primitives)
    if (p.material < 0) p.material = index;
}

// The portrait lighting of the head (the same directions as the benchmark's head scenes, so the
// pictures can be compared): the key from above, in front and to the subject's right (-X), so the
// nose throws a hard shadow down across the subject's left cheek (+X), which the cameras (yawed
// towards +X) see; a dim cool fill from the other side, slightly below; a little ambient.
void portrait_lights(DemoScene *scene) {
  scene->lights = {{glm::normalize(glm::vec3(-0.55f, 0.62f, 0.56f)), glm::vec3(1.25f, 1.2f, 1.12f)},
                   {glm::normalize(glm::vec3(0.8f, -0.1f, 0.6f)), glm::vec3(0.10f, 0.11f, 0.13f)}};
  scene->sky_ambient = glm::vec3(0.035f, 0.035f, 0.04f);
  scene->ground_ambient = glm::vec3(0.02f, 0.018f, 0.016f);
  scene->background = glm::vec3(0.012f, 0.014f, 0.018f);
}

// ---- the procedural sphere scene ----

struct MeshBuilder {
  gltf_mesh::Model *model;

  uint32_t base() const { return static_cast<uint32_t>(model->vertex_count()); }
  void vertex(glm::vec3 p, glm::vec3 n, float u, float v, glm::vec3 t) {
    const float values[gltf_mesh::Model::kFloatsPerVertex] = {p.x, p.y, p.z, n.x, n.y, n.z, u, v, t.x, t.y, t.z, 1.0f};
    model->vertices.insert(model->vertices.end(), values, values + gltf_mesh::Model::kFloatsPerVertex);
  }
  void primitive(uint32_t first_index, int material) {
    gltf_mesh::Primitive p;
    p.first_index = first_index;
    p.index_count = static_cast<uint32_t>(model->indices.size()) - first_index;
    p.material = material;
    model->primitives.push_back(p);
  }
};

void add_sphere(MeshBuilder *mesh, glm::vec3 centre, float radius, int rings, int segments) {
  const uint32_t first = mesh->base();
  for (int r = 0; r <= rings; ++r) {
    const float theta = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * glm::pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const glm::vec3 t(-std::sin(phi), 0.0f, std::cos(phi));
      mesh->vertex(centre + radius * n, n, static_cast<float>(s) / static_cast<float>(segments),
                   static_cast<float>(r) / static_cast<float>(rings), t);
    }
  }
  const uint32_t stride = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r) {
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = first + r * stride + s;
      const uint32_t b = a + stride;
      mesh->model->indices.insert(mesh->model->indices.end(), {a, a + 1, b, a + 1, b + 1, b});  // CCW from outside
    }
  }
}

// One quad: corner + two edge vectors; the normal is cross(u, v).
void add_quad(MeshBuilder *mesh, glm::vec3 corner, glm::vec3 u, glm::vec3 v) {
  const uint32_t first = mesh->base();
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  const glm::vec3 t = glm::normalize(u);
  mesh->vertex(corner, n, 0, 0, t);
  mesh->vertex(corner + u, n, 1, 0, t);
  mesh->vertex(corner + u + v, n, 1, 1, t);
  mesh->vertex(corner + v, n, 0, 1, t);
  mesh->model->indices.insert(mesh->model->indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
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

gltf_mesh::Material flat_material(const char *name, float r, float g, float b) {
  gltf_mesh::Material m;
  m.name = name;
  m.base_color[0] = r;
  m.base_color[1] = g;
  m.base_color[2] = b;
  return m;
}

}  // namespace

DemoScene load_head_scene() {
  DemoScene scene;
  scene.name = "head";
  scene.description = "Lee Perry-Smith head scan (glTF, albedo and normal maps), metres";
  scene.attribution = sss_assets::head_attribution();
  scene.model = gltf_mesh::load_gltf(sss_assets::head_path());
  add_default_material(&scene.model);
  // The scan's tangent frame: cross(N, T) * w points towards +v while its normal map stores +green
  // towards -v (the glTF convention), so green is read inverted; tests/bench/scenes checks both
  // facts on the asset (NormalMapGreenConvention).
  scene.normal_green_sign = -1.0f;
  scene.looks.assign(scene.model.materials.size(), MaterialLook{1.0f, 1.0f, 0.3f});
  scene.subject = model_bounds(scene.model);
  scene.all = scene.subject;
  portrait_lights(&scene);
  return scene;
}

DemoScene load_gltf_scene(const std::string &path) {
  DemoScene scene;
  scene.name = std::filesystem::path(path).filename().string();
  scene.model = gltf_mesh::load_gltf(path);
  scene.description = "glTF " + path;
  if (!scene.model.copyright.empty()) scene.attribution = scene.model.copyright;
  add_default_material(&scene.model);
  scene.looks.assign(scene.model.materials.size(), MaterialLook{1.0f, 1.0f, 0.3f});
  scene.subject = model_bounds(scene.model);
  scene.all = scene.subject;
  portrait_lights(&scene);
  return scene;
}

DemoScene make_sphere_scene() {
  DemoScene scene;
  scene.name = "sphere";
  scene.description = "procedural: a translucent sphere (r = 0.1 m) on a ground plane, a box's hard shadow across it";
  gltf_mesh::Model &model = scene.model;
  model.path = "(procedural)";
  model.materials = {flat_material("ground", 0.42f, 0.42f, 0.40f), flat_material("box", 0.30f, 0.36f, 0.48f),
                     flat_material("skin", 0.85f, 0.55f, 0.45f)};
  scene.looks = {MaterialLook{0.0f, 0.03f, 0.5f}, MaterialLook{0.0f, 0.05f, 0.3f}, MaterialLook{1.0f, 1.0f, 0.3f}};
  MeshBuilder mesh{&model};
  uint32_t first = 0;
  add_quad(&mesh, glm::vec3(-0.6f, 0.0f, -0.6f), glm::vec3(0, 0, 1.2f), glm::vec3(1.2f, 0, 0));
  mesh.primitive(first, 0);
  first = static_cast<uint32_t>(model.indices.size());
  add_box(&mesh, glm::vec3(-0.26f, 0.0f, -0.12f), glm::vec3(-0.16f, 0.24f, 0.27f));
  mesh.primitive(first, 1);
  first = static_cast<uint32_t>(model.indices.size());
  const glm::vec3 centre(0.0f, 0.1f, 0.0f);
  add_sphere(&mesh, centre, 0.1f, 96, 192);
  mesh.primitive(first, 2);
  for (int k = 0; k < 3; ++k) {
    model.bounds_min[k] = model.vertices[static_cast<size_t>(k)];
    model.bounds_max[k] = model.vertices[static_cast<size_t>(k)];
  }
  for (size_t v = 0; v < model.vertex_count(); ++v)
    for (size_t k = 0; k < 3; ++k) {
      const float x = model.vertices[v * gltf_mesh::Model::kFloatsPerVertex + k];
      model.bounds_min[k] = std::min(model.bounds_min[k], x);
      model.bounds_max[k] = std::max(model.bounds_max[k], x);
    }
  scene.all = model_bounds(model);
  scene.subject.min = centre - glm::vec3(0.1f);
  scene.subject.max = centre + glm::vec3(0.1f);
  scene.lights = {{glm::normalize(glm::vec3(-0.8f, 0.7f, 0.6f)), glm::vec3(2.0f, 1.9f, 1.8f)}};
  scene.sky_ambient = glm::vec3(0.16f, 0.18f, 0.22f);
  scene.ground_ambient = glm::vec3(0.08f, 0.07f, 0.06f);
  scene.background = glm::vec3(0.020f, 0.024f, 0.030f);
  return scene;
}

}  // namespace demo
