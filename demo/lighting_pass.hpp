// Pass 2: forward lighting into the frame targets (frame_targets.hpp):
//   diffuse   linear albedo x irradiance (every light x N.L x PCF shadow, plus a hemisphere ambient),
//             alpha = the material's SSS strength (0: not translucent)
//   specular  Kelemen/Szirmay-Kalos specular with a Beckmann lobe (d'Eon & Luebke 2007, as the paper
//             uses), per light x shadow
//   depth-stencil  stencil 1 where a translucent material (strength > 0) is the visible surface
//   profile   R8UI: the material's profile | object << 4 (cleared to 0; not written with MSAA)
//   albedo    RGBA16F: the linear albedo the diffuse light was multiplied by (the albedo map x base
//             colour; cleared to 1), sss_frame.albedo_texture for the texturing modes (multisampled
//             with MSAA, as the library's MSAA path wants it)
// Normal maps use the glTF tangent frame: bitangent = cross(N, T) * w, green scaled by the scene's
// normal_green_sign.
#pragma once

#include "camera.hpp"
#include "frame_targets.hpp"
#include "gl_functions.hpp"
#include "gpu_scene.hpp"
#include "scene.hpp"
#include "shadow_pass.hpp"

#include <cstdint>

namespace demo {

struct LightingPass {
  GLuint program = 0;
  GLuint preintegrated_program = 0;  // skin shaded with the pre-integrated LUTs (no SSS pass after)
  GLuint depth_sampler = 0;  // the shadow maps read as plain depth (no compare) for the thickness
};

// Texture units of the LUTs (0, 1: material; 2, 3: shadow maps; 4, 5: the same as plain depth).
constexpr int kDiffuseLutUnit = 6;
constexpr int kShadowLutUnit = 7;

// The library's pre-integrated LUTs (sss_lut_create_texture) and the ranges they were made with.
struct PreintegratedLuts {
  GLuint diffuse = 0, shadow = 0;
  float curvature_range[2] = {0.0f, 1.0f};  // 1/mm
  float penumbra_range[2] = {0.0f, 1.0f};   // world units
};

// Transmittance through thin parts (integration/glsl/sss_transmittance.glsl).
struct TransmittanceInputs {
  bool enabled = false;
  // World units per millimetre of the profile, as the blur has it: sss_settings.world_units_per_mm
  // x scale (the transmitted light follows the scale the artist gave the scattering).
  float world_units_per_profile_mm = 0.0f;
  float translucency = 0.8f;   // 0..1
  std::uint32_t profile = 0;   // SSS_PROFILE_*: the blur's profile, whose terms the include evaluates
  // Where the thickness comes from: 0 the lights' shadow maps (sss_thickness), 1 each translucent
  // material's baked thickness (MaterialLook::baked_thickness, else baked_thickness: the shape a
  // host's baked map or attribute gives), 2 the larger of both (sss_thickness_combined).
  int thickness_source = 0;
  float baked_thickness = 0.002f;  // world units
};

bool create_lighting_pass(LightingPass *pass);
// luts != nullptr: translucent materials are shaded with pre-integrated scattering. object_ids false:
// the profile attachment gets the profile alone (object 0 everywhere: light crosses between objects).
void run_lighting_pass(const LightingPass &pass, const FrameTargets &targets, const DemoScene &scene,
                       const GpuScene &gpu, const ShadowPass &shadows, const CameraMatrices &camera,
                       const TransmittanceInputs &transmittance, const PreintegratedLuts *luts = nullptr,
                       bool object_ids = true);
void destroy_lighting_pass(LightingPass *pass);

}  // namespace demo
