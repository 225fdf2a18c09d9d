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

// The box of a model's vertices (its bounds_min/bounds_max).
Bounds model_bounds(const gltf_mesh::Model &model);

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
  // The G-buffer's profile/object byte (sss_frame.profile_texture): profile | object << 4. `profile`
  // indexes DemoScene::profiles; `object` (1..15; 0 the background) keeps light from crossing between
  // objects of one profile (the hand and the face).
  int profile = 0;
  int object = 0;
  glm::vec3 emission{0.0f};         // linear radiance added unlit (the candle's flame), never scattered
};

// The byte the G-buffer's profile attachment gets for a material (object IDs off: the profile alone).
inline unsigned profile_byte(const MaterialLook &look, bool object_ids) {
  return static_cast<unsigned>(look.profile & 15) | (object_ids ? static_cast<unsigned>(look.object & 15) << 4 : 0u);
}

// One diffusion profile of a scene (an entry of sss_set_profiles): the demo's controls give
// profile 0 (the head's skin); the others are measured materials through a rank-1 pre-integrated
// kernel (sss_kernel_desc{SSS_KERNEL_PREINTEGRATED, rank 1, profile}).
struct SceneProfile {
  std::string name;   // "skin", "marble", ...
  int material = -1;  // sss_profile (sss.h) of a measured material; -1: the controls' own (profile 0)
};

// A point light without a shadow map (the candle's flame): irradiance colour / distance² x N.L.
struct PointLight {
  glm::vec3 position{0.0f};
  glm::vec3 colour{0.0f};  // 0: none
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
  PointLight point_light;

  // Several materials in one frame (issue 23): the profiles the G-buffer's byte indexes (at most
  // 16; one entry, the controls', for the single-material scenes) and the objects' names by ID.
  std::vector<SceneProfile> profiles{SceneProfile{"skin", -1}};
  std::vector<std::string> object_names;  // [id - 1]; empty: no object IDs
  int hand_material = -1;                 // the bleeding test scene: the hand's material (its colour is an option)
};

constexpr int kMaxLights = 2;

// Whether frames of the scene hand the library its profile/object byte (several profiles or objects).
inline bool uses_profiles(const DemoScene &scene) { return scene.profiles.size() > 1 || !scene.object_names.empty(); }


// The Lee Perry-Smith head scan from the shared assets (sss_assets::head_path()).
DemoScene load_head_scene();
// Any glTF 2.0 file: every material translucent (strength 1), skin-like specular.
DemoScene load_gltf_scene(const std::string &path);
// The procedural scene: a translucent sphere on a ground plane, a box throwing a hard shadow on it.
DemoScene make_sphere_scene();
// The head with two objects of other materials beside it (generated in code): a marble bust (a
// pedestal, shoulders and a head) and a wax candle (a cylinder with a rounded top, lit by its
// flame); three profiles, three object IDs.
DemoScene make_mixed_scene();
// The bleeding test scene: the head with a hand (a palm and five flattened finger capsules, skin)
// resting a few millimetres in front of its left cheek: one profile, two object IDs.
DemoScene make_hand_scene();
// The hand's default linear base colour (the option --hand-colour changes it).
constexpr float kHandColour[3] = {0.72f, 0.46f, 0.38f};

}  // namespace demo
