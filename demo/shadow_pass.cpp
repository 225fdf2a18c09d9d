#include "shadow_pass.hpp"

#include "host_gl_util.hpp"

#include <glm/gtc/type_ptr.hpp>

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

bool create_shadow_pass(ShadowPass *pass, GLsizei size) {
  pass->size = size;
  pass->program = build_program("shadow", kVertexShader, kFragmentShader);
  if (pass->program == 0) return false;
  pass->u_light_view_projection = glGetUniformLocation(pass->program, "u_light_view_projection");

  pass->depth_texture = make_texture(GL_DEPTH_COMPONENT24, size, size, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
  glBindTexture(GL_TEXTURE_2D, pass->depth_texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);

  glGenFramebuffers(1, &pass->framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass->framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, pass->depth_texture, 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
  const bool complete = check_framebuffer("shadow map");
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return complete && check_gl("shadow pass setup");
}

void run_shadow_pass(const ShadowPass &pass, const SceneGeometry &geometry, const glm::mat4 &light_view_projection) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass.framebuffer);
  glViewport(0, 0, pass.size, pass.size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  // Slope-scaled bias against acne; the lighting pass adds a small normal offset as well.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);

  glUseProgram(pass.program);
  glUniformMatrix4fv(pass.u_light_view_projection, 1, GL_FALSE, glm::value_ptr(light_view_projection));
  glBindVertexArray(geometry.vao);
  for (const SceneObject &object : geometry.objects) draw_object(object);
  glBindVertexArray(0);
  glUseProgram(0);

  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void destroy_shadow_pass(ShadowPass *pass) {
  glDeleteProgram(pass->program);
  glDeleteFramebuffers(1, &pass->framebuffer);
  glDeleteTextures(1, &pass->depth_texture);
  *pass = ShadowPass{};
}

}  // namespace demo
