// The scenes of several materials and objects (issue 23): the head with a marble bust and a wax
// candle beside it, and the head with a hand in front of its cheek. Their objects are generated
// here (shapes.hpp); the head is the scan of load_head_scene.
#include "scene.hpp"

#include "shapes.hpp"

#include <sss/sss.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

// The head of load_head_scene as object 1 of profile 0 (skin).
DemoScene head_as_object(const char *name) {
  DemoScene scene = load_head_scene();
  scene.name = name;
  for (MaterialLook &look : scene.looks) {
    look.profile = 0;
    look.object = 1;
  }
  scene.object_names = {"head"};
  return scene;
}

int add_material(DemoScene *scene, const gltf_mesh::Material &material, const MaterialLook &look) {
  scene->model.materials.push_back(material);
  scene->looks.push_back(look);
  return static_cast<int>(scene->model.materials.size()) - 1;
}

MaterialLook translucent(int profile, int object, float specular, float roughness) {
  MaterialLook look{1.0f, specular, roughness};
  look.profile = profile;
  look.object = object;
  return look;
}

// The scan's surface nearest the viewer (largest z, the face looks along +Z) over a disk of radius
// r around (x, y): where the hand must stay in front of.
float face_front(const gltf_mesh::Model &head, float x, float y, float r) {
  float front = -1e30f;
  for (size_t v = 0; v < head.vertex_count(); ++v) {
    const float *p = &head.vertices[v * gltf_mesh::Model::kFloatsPerVertex];
    if ((p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y) <= r * r) front = std::max(front, p[2]);
  }
  return front;
}

}  // namespace

DemoScene make_mixed_scene() {
  DemoScene scene = head_as_object("mixed");
  scene.description =
      "Lee Perry-Smith head scan (skin) with a marble bust and a wax candle beside it (generated): three "
      "profiles, three objects, one pass pair";
  // Wax: no measured wax among Jensen's materials; cream is the nearest (a yellowish white of long
  // scattering and little absorption).
  scene.profiles = {SceneProfile{"skin", -1}, SceneProfile{"marble", SSS_PROFILE_MARBLE},
                    SceneProfile{"wax (cream)", SSS_PROFILE_CREAM}};
  scene.object_names = {"head", "bust", "candle"};
  const float floor_y = scene.model.bounds_min[1];
  MeshBuilder mesh(&scene.model);

  // The bust, left of the head (-X): a pedestal, shoulders and a head, all marble.
  const int marble = add_material(&scene, flat_material("marble", 0.83f, 0.82f, 0.79f), translucent(1, 2, 0.6f, 0.25f));
  const glm::vec3 bust(-0.37f, floor_y, -0.03f);
  add_box(&mesh, bust + glm::vec3(-0.065f, 0.0f, -0.065f), bust + glm::vec3(0.065f, 0.10f, 0.065f));
  add_ellipsoid(&mesh, bust + glm::vec3(0.0f, 0.14f, 0.0f), glm::vec3(0.10f, 0.045f, 0.06f), 48, 96);
  add_ellipsoid(&mesh, bust + glm::vec3(0.0f, 0.245f, 0.005f), glm::vec3(0.058f, 0.078f, 0.065f), 64, 128);
  mesh.end_primitive(marble);

  // The candle, right of the head (+X): wax with a rounded rim, a dark wick and an emissive flame
  // whose light (a point light at its centre) falls on the wax around the tip.
  const int wax = add_material(&scene, flat_material("wax", 0.93f, 0.86f, 0.70f), translucent(2, 3, 0.3f, 0.35f));
  const glm::vec3 candle(0.33f, floor_y, 0.0f);
  const float candle_height = 0.21f;
  add_rounded_cylinder(&mesh, candle, 0.035f, candle_height, 0.012f, 24, 96);
  mesh.end_primitive(wax);
  const int wick = add_material(&scene, flat_material("wick", 0.03f, 0.025f, 0.02f), MaterialLook{0.0f, 0.05f, 0.5f});
  const glm::vec3 tip = candle + glm::vec3(0.0f, candle_height, 0.0f);
  add_capsule(&mesh, tip - glm::vec3(0.0f, 0.004f, 0.0f), tip + glm::vec3(0.0f, 0.014f, 0.0f), 0.0015f,
              glm::vec3(1.0f, 0.0f, 0.0f), 1.0f, 8, 12);
  mesh.end_primitive(wick);
  MaterialLook flame{0.0f, 0.0f, 0.5f};
  flame.emission = glm::vec3(6.0f, 3.2f, 1.0f);
  const int flame_material = add_material(&scene, flat_material("flame", 0.0f, 0.0f, 0.0f), flame);
  const glm::vec3 flame_centre = tip + glm::vec3(0.0f, 0.032f, 0.0f);
  add_ellipsoid(&mesh, flame_centre, glm::vec3(0.008f, 0.021f, 0.008f), 16, 24);
  mesh.end_primitive(flame_material);
  scene.point_light = {flame_centre, glm::vec3(0.0024f, 0.0015f, 0.0006f)};

  mesh.update_bounds();
  scene.all = model_bounds(scene.model);
  return scene;
}

DemoScene make_hand_scene() {
  DemoScene scene = head_as_object("hand");
  scene.description =
      "Lee Perry-Smith head scan with a hand (generated) resting a few millimetres in front of its left cheek: "
      "one skin profile, two objects";
  scene.object_names = {"head", "hand"};
  const gltf_mesh::Model head = scene.model;
  MeshBuilder mesh(&scene.model);
  scene.hand_material = add_material(&scene, flat_material("hand", kHandColour[0], kHandColour[1], kHandColour[2]),
                                     translucent(0, 2, 0.8f, 0.32f));
  // Four fingers from the knuckles (below the jaw) up across the cheek on the subject's left (+X, the
  // side the cameras see), and the thumb towards the chin, each pushed out until its back is `gap`
  // in front of the face under it; the palm below the jaw.
  const float gap = -0.001f, flatten = 0.6f;
  const glm::vec3 out(0.0f, 0.0f, 1.0f);
  struct Digit {
    float x0, y0, x1, y1, radius;
  };
  const Digit digits[5] = {{0.020f, -0.052f, 0.016f, 0.030f, 0.0075f},
                           {0.034f, -0.054f, 0.032f, 0.040f, 0.0078f},
                           {0.048f, -0.056f, 0.048f, 0.034f, 0.0076f},
                           {0.062f, -0.058f, 0.064f, 0.018f, 0.0070f},
                           {0.006f, -0.080f, -0.010f, -0.046f, 0.0085f}};
  // Each digit in three segments (the phalanges), each joint as near the face as the segments on
  // either side allow, so the hand follows the cheek's curve.
  constexpr int kJoints = 4;
  float palm_z = head.bounds_min[2];
  for (const Digit &f : digits) {
    glm::vec3 joint[kJoints];
    float clearance[kJoints - 1];
    for (int j = 0; j + 1 < kJoints; ++j) {
      clearance[j] = head.bounds_min[2];
      for (int k = 0; k <= 4; ++k) {
        const float s = (static_cast<float>(j) + static_cast<float>(k) / 4.0f) / static_cast<float>(kJoints - 1);
        clearance[j] = std::max(clearance[j], face_front(head, f.x0 + s * (f.x1 - f.x0), f.y0 + s * (f.y1 - f.y0), f.radius));
      }
    }
    for (int j = 0; j < kJoints; ++j) {
      const float s = static_cast<float>(j) / static_cast<float>(kJoints - 1);
      const float z = std::max(clearance[std::max(j - 1, 0)], clearance[std::min(j, kJoints - 2)]) + gap + f.radius * flatten;
      joint[j] = glm::vec3(f.x0 + s * (f.x1 - f.x0), f.y0 + s * (f.y1 - f.y0), z);
      palm_z = std::max(palm_z, z);
    }
    for (int j = 0; j + 1 < kJoints; ++j) add_capsule(&mesh, joint[j], joint[j + 1], f.radius, out, flatten, 12, 32);
  }
  add_ellipsoid(&mesh, glm::vec3(0.040f, -0.082f, palm_z), glm::vec3(0.036f, 0.034f, 0.011f), 32, 64);
  mesh.end_primitive(scene.hand_material);
  mesh.update_bounds();
  scene.all = model_bounds(scene.model);
  return scene;
}

}  // namespace demo
