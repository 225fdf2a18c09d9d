#include "frame_targets.hpp"

#include "host_gl_util.hpp"

namespace demo {

bool create_frame_targets(FrameTargets *t, GLsizei width, GLsizei height) {
  t->width = width;
  t->height = height;
  t->diffuse = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->specular = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->depth_stencil = make_texture(GL_DEPTH24_STENCIL8, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
  t->after = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->output = make_texture(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);

  glGenFramebuffers(1, &t->lighting_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->lighting_framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->diffuse, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t->specular, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, t->depth_stencil, 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  bool ok = check_framebuffer("lighting");

  glGenFramebuffers(1, &t->output_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->output_framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->output, 0);
  glDrawBuffers(1, buffers);
  ok = check_framebuffer("output") && ok;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return ok && check_gl("frame targets");
}

void destroy_frame_targets(FrameTargets *t) {
  glDeleteFramebuffers(1, &t->lighting_framebuffer);
  glDeleteFramebuffers(1, &t->output_framebuffer);
  const GLuint textures[5] = {t->diffuse, t->specular, t->depth_stencil, t->after, t->output};
  glDeleteTextures(5, textures);
  *t = FrameTargets{};
}

}  // namespace demo
