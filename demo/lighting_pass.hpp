// Pass 2: forward lighting into three textures of one framebuffer:
//   diffuse  RGBA16F  linear irradiance x albedo, alpha = SSS strength (1 on skin, 0 elsewhere)
//   specular RGBA16F  linear specular radiance (kept out of the blur)
//   depth    DEPTH24_STENCIL8, stencil = 1 where the translucent sphere is the visible surface
#pragma once

#include "gl_functions.hpp"
#include "scene_geometry.hpp"
#include "scene_view.hpp"

namespace demo {

struct LightingPass {
  GLuint program = 0;
  GLuint framebuffer = 0;
  GLuint diffuse_texture = 0;
  GLuint specular_texture = 0;
  GLuint depth_stencil_texture = 0;
  GLsizei width = 0;
  GLsizei height = 0;
};

bool create_lighting_pass(LightingPass *pass, GLsizei width, GLsizei height);
void run_lighting_pass(const LightingPass &pass, const SceneGeometry &geometry, const SceneView &view,
                       GLuint shadow_map, GLsizei shadow_map_size);
void destroy_lighting_pass(LightingPass *pass);

}  // namespace demo
