#include "scene.hpp"

#include "shapes.hpp"
#include "shared_assets.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>

namespace demo {

float Bounds::radius() const { return 0.5f * glm::length(max - min); }

Bounds model_bounds(const gltf_mesh::Model &model) {
  Bounds b;
  b.min = glm::vec3(model.bounds_min[0], model.bounds_min[1], model.bounds_min[2]);
  b.max = glm::vec3(model.bounds_max[0], model.bounds_max[1], model.bounds_max[2]);
  return b;
}

namespace {

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
  MeshBuilder mesh(&model);
  add_quad(&mesh, glm::vec3(-0.6f, 0.0f, -0.6f), glm::vec3(0, 0, 1.2f), glm::vec3(1.2f, 0, 0));
  mesh.end_primitive(0);
  add_box(&mesh, glm::vec3(-0.26f, 0.0f, -0.12f), glm::vec3(-0.16f, 0.24f, 0.27f));
  mesh.end_primitive(1);
  const glm::vec3 centre(0.0f, 0.1f, 0.0f);
  add_sphere(&mesh, centre, 0.1f, 96, 192);
  mesh.end_primitive(2);
  mesh.update_bounds();
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
