#include "shadow_pass.hpp"

#include "host_gl_util.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

const char *const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_view_projection;
void main() { gl_Position = u_light_view_projection * vec4(a_position, 1.0); }
)";

const char *const kFragmentShader = R"(#version 330 core
void main() {}
)";

}  // namespace

bool create_shadow_pass(ShadowPass *pass, const DemoScene &scene) {
  pass->program = build_program("shadow", kVertexShader, kFragmentShader);
  if (pass->program == 0) return false;
  pass->u_light_view_projection = glGetUniformLocation(pass->program, "u_light_view_projection");

  glGenSamplers(1, &pass->compare_sampler);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(pass->compare_sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

  const glm::vec3 centre = scene.all.centre();
  const float radius = std::max(scene.all.radius(), 1e-4f) * 1.02f;
  pass->light_count = std::min(static_cast<int>(scene.lights.size()), kMaxLights);
  bool ok = true;
  for (int i = 0; i < pass->light_count; ++i) {
    ShadowMap &map = pass->maps[static_cast<size_t>(i)];
    const glm::vec3 direction = scene.lights[static_cast<size_t>(i)].direction;
    const glm::vec3 up = std::fabs(direction.y) > 0.95f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::mat4 light_view = glm::lookAt(centre + direction * (2.0f * radius), centre, up);
    const glm::mat4 light_projection = glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius);
    map.light_view_projection = light_projection * light_view;
    map.light_view = light_view;
    map.light_projection = light_projection;
    map.texel_world = 2.0f * radius / static_cast<float>(kShadowMapSize);

    map.depth_texture =
        make_texture(GL_DEPTH_COMPONENT32F, kShadowMapSize, kShadowMapSize, GL_DEPTH_COMPONENT, GL_FLOAT);
    glGenFramebuffers(1, &map.framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, map.framebuffer);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map.depth_texture, 0);
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    ok = check_framebuffer("shadow map") && ok;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  }
  return ok && check_gl("shadow pass setup");
}

void run_shadow_pass(const ShadowPass &pass, const DemoScene &scene, const GpuScene &gpu) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  // Slope-scaled bias against acne; the lighting pass adds a normal offset as well.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glUseProgram(pass.program);
  glBindVertexArray(gpu.vao);
  for (int i = 0; i < pass.light_count; ++i) {
    const ShadowMap &map = pass.maps[static_cast<size_t>(i)];
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, map.framebuffer);
    glViewport(0, 0, kShadowMapSize, kShadowMapSize);
    const GLfloat far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glUniformMatrix4fv(pass.u_light_view_projection, 1, GL_FALSE, glm::value_ptr(map.light_view_projection));
    for (const gltf_mesh::Primitive &p : scene.model.primitives) draw_primitive(p);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 0.0f);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void destroy_shadow_pass(ShadowPass *pass) {
  glDeleteProgram(pass->program);
  glDeleteSamplers(1, &pass->compare_sampler);
  for (ShadowMap &map : pass->maps) {
    if (map.framebuffer != 0) glDeleteFramebuffers(1, &map.framebuffer);
    if (map.depth_texture != 0) glDeleteTextures(1, &map.depth_texture);
  }
  *pass = ShadowPass{};
}

}  // namespace demo
