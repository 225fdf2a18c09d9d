// Pass 1: depth from each directional light into a DEPTH_COMPONENT32F texture, orthographic,
// fitted around the scene's bounding sphere. The lighting pass reads it with hardware PCF
// (GL_COMPARE_REF_TO_TEXTURE, linear filtering, sampler2DShadow) through `compare_sampler`.
//
// Transmittance (the paper's translucency through thin parts, JWSG10) reads the same maps as plain
// depth, through a sampler without compare mode (lighting_pass.cpp, with the library's include
// integration/glsl/sss_transmittance.glsl): the thickness the light travels inside the object is
// the distance between the shaded point and the map's depth, both along the light.
#pragma once

#include "gl_functions.hpp"
#include "gpu_scene.hpp"
#include "scene.hpp"

#include <glm/mat4x4.hpp>

#include <array>

namespace demo {

constexpr GLsizei kShadowMapSize = 2048;

struct ShadowMap {
  GLuint depth_texture = 0;
  GLuint framebuffer = 0;
  glm::mat4 light_view_projection{1.0f};  // world -> light clip space
  glm::mat4 light_view{1.0f}, light_projection{1.0f};  // its two factors (the transmittance include takes them)
  float texel_world = 0.0f;               // world units covered by one texel
};

struct ShadowPass {
  GLuint program = 0;
  GLint u_light_view_projection = -1;
  GLuint compare_sampler = 0;  // PCF: compare mode, linear
  int light_count = 0;
  std::array<ShadowMap, kMaxLights> maps{};
};

// One map per light of the scene (at most kMaxLights), fitted to scene.all.
bool create_shadow_pass(ShadowPass *pass, const DemoScene &scene);
void run_shadow_pass(const ShadowPass &pass, const DemoScene &scene, const GpuScene &gpu);
void destroy_shadow_pass(ShadowPass *pass);

}  // namespace demo
