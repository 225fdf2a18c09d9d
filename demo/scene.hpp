// What the demo draws: a mesh with materials (integration/gltf_mesh), how translucent and shiny each
// material is, the lights, and the boxes the cameras and the shadow maps are fitted to.
// World units are metres (glTF's unit): sss_settings.world_units_per_mm is 0.001, and scale 1 gives
// the scattering its physical size.
#pragma once

#include "gltf_mesh.hpp"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace demo {

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  glm::vec3 centre() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
  float radius() const;  // half the diagonal
};

// A directional light with a shadow map.
struct Light {
  glm::vec3 direction;   // unit vector from the surface towards the light
  glm::vec3 irradiance;  // linear RGB at normal incidence
};

// How the lighting pass treats one material of the model (same index as model.materials).
struct MaterialLook {
  float sss_strength = 0.0f;        // the diffuse alpha (scales the scattering per pixel); > 0 sets stencil 1
  float baked_thickness = 0.0f;     // world units, for --thickness baked/both; 0: the --baked-thickness value
  float specular_intensity = 0.0f;  // rho_s of the Kelemen/Szirmay-Kalos specular
  float roughness = 0.35f;          // Beckmann m
};

struct DemoScene {
  std::string name;         // "head", "sphere" or the glTF file's name
  std::string description;  // one line for the panel and the README.txt
  std::string attribution;  // the licence text any image of it must carry; may be empty
  gltf_mesh::Model model;   // every primitive has a material (a default one is appended when needed)
  std::vector<MaterialLook> looks;
  float normal_green_sign = 1.0f;  // -1 where the file's tangent frame disagrees with its normal map (the head)
  float world_units_per_mm = 0.001f;

  Bounds subject;  // what the camera presets frame
  Bounds all;      // every vertex: near/far planes and the shadow maps' frusta

  std::vector<Light> lights;  // at most kMaxLights, each with a shadow map
  glm::vec3 sky_ambient{0.0f};
  glm::vec3 ground_ambient{0.0f};
  glm::vec3 background{0.0f};  // linear radiance behind the model (alpha 0: not translucent)
};

constexpr int kMaxLights = 2;

// The Lee Perry-Smith head scan from the shared assets (sss_assets::head_path()).
DemoScene load_head_scene();
// Any glTF 2.0 file: every material translucent (strength 1), skin-like specular.
DemoScene load_gltf_scene(const std::string &path);
// The procedural scene: a translucent sphere on a ground plane, a box throwing a hard shadow on it.
DemoScene make_sphere_scene();

}  // namespace demo
