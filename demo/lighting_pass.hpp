// Pass 2: forward lighting into the frame targets (frame_targets.hpp):
//   diffuse   linear albedo x irradiance (every light x N.L x PCF shadow, plus a hemisphere ambient),
//             alpha = the material's SSS strength (0: not translucent)
//   specular  Kelemen/Szirmay-Kalos specular with a Beckmann lobe (d'Eon & Luebke 2007, as the paper
//             uses), per light x shadow
//   depth-stencil  stencil 1 where a translucent material (strength > 0) is the visible surface
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
  GLuint depth_sampler = 0;  // the shadow maps read as plain depth (no compare) for the thickness
};

// Transmittance through thin parts (integration/glsl/sss_transmittance.glsl).
struct TransmittanceInputs {
  bool enabled = false;
  float width = 0.0f;          // sss_settings.width the blur uses (world units)
  float translucency = 0.8f;   // 0..1
  std::uint32_t profile = 0;   // SSS_PROFILE_*: the blur's profile, whose terms the include evaluates
};

bool create_lighting_pass(LightingPass *pass);
void run_lighting_pass(const LightingPass &pass, const FrameTargets &targets, const DemoScene &scene,
                       const GpuScene &gpu, const ShadowPass &shadows, const CameraMatrices &camera,
                       const TransmittanceInputs &transmittance);
void destroy_lighting_pass(LightingPass *pass);

}  // namespace demo
