// Pass 1: depth from the light into a DEPTH_COMPONENT24 texture set up for hardware PCF
// (GL_COMPARE_REF_TO_TEXTURE with LINEAR filtering, read through sampler2DShadow).
#pragma once

#include "gl_functions.hpp"
#include "scene_geometry.hpp"

#include <glm/mat4x4.hpp>

namespace demo {

constexpr GLsizei kShadowMapSize = 2048;

struct ShadowPass {
  GLuint program = 0;
  GLuint framebuffer = 0;
  GLuint depth_texture = 0;
  GLsizei size = 0;
  GLint u_light_view_projection = -1;
};

bool create_shadow_pass(ShadowPass *pass, GLsizei size);
void run_shadow_pass(const ShadowPass &pass, const SceneGeometry &geometry, const glm::mat4 &light_view_projection);
void destroy_shadow_pass(ShadowPass *pass);

}  // namespace demo
