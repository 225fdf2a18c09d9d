#include "frame_targets.hpp"

#include "host_gl_util.hpp"

namespace demo {

namespace {
GLuint make_multisample(GLenum internal_format, GLsizei width, GLsizei height, int samples) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, GL_TRUE);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  return texture;
}
}  // namespace

void resolve_lighting(const FrameTargets &t) {
  if (t.samples == 0) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.lighting_framebuffer_ms);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.lighting_framebuffer);
  for (const GLenum attachment : {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT3}) {
    glReadBuffer(attachment);
    const GLenum draw = attachment;
    glDrawBuffers(1, &draw);
    glBlitFramebuffer(0, 0, t.width, t.height, 0, 0, t.width, t.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBlitFramebuffer(0, 0, t.width, t.height, 0, 0, t.width, t.height, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                    GL_NEAREST);
  const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(4, buffers);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

bool create_frame_targets(FrameTargets *t, GLsizei width, GLsizei height, int samples) {
  t->width = width;
  t->height = height;
  t->diffuse = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->specular = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->depth_stencil = make_texture(GL_DEPTH24_STENCIL8, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
  t->after = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->albedo = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
  t->profile = make_texture(GL_R8UI, width, height, GL_RED_INTEGER, GL_UNSIGNED_BYTE);
  t->output = make_texture(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);

  glGenFramebuffers(1, &t->lighting_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->lighting_framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->diffuse, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t->specular, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, t->profile, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, t->albedo, 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, t->depth_stencil, 0);
  const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(4, buffers);
  bool ok = check_framebuffer("lighting");

  glGenFramebuffers(1, &t->output_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->output_framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->output, 0);
  glDrawBuffers(1, buffers);
  ok = check_framebuffer("output") && ok;

  if (samples > 0) {
    t->samples = samples;
    t->diffuse_ms = make_multisample(GL_RGBA16F, width, height, samples);
    t->specular_ms = make_multisample(GL_RGBA16F, width, height, samples);
    t->albedo_ms = make_multisample(GL_RGBA16F, width, height, samples);
    t->depth_stencil_ms = make_multisample(GL_DEPTH24_STENCIL8, width, height, samples);
    glGenFramebuffers(1, &t->lighting_framebuffer_ms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->lighting_framebuffer_ms);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, t->diffuse_ms, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D_MULTISAMPLE, t->specular_ms, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D_MULTISAMPLE, t->albedo_ms, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D_MULTISAMPLE,
                           t->depth_stencil_ms, 0);
    // The lighting shader's outputs keep their locations; the profile byte's (2) has no target here.
    const GLenum ms_buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE, GL_COLOR_ATTACHMENT3};
    glDrawBuffers(4, ms_buffers);
    ok = check_framebuffer("lighting (MSAA)") && ok;
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return ok && check_gl("frame targets");
}

void destroy_frame_targets(FrameTargets *t) {
  glDeleteFramebuffers(1, &t->lighting_framebuffer);
  glDeleteFramebuffers(1, &t->output_framebuffer);
  if (t->samples > 0) {
    glDeleteFramebuffers(1, &t->lighting_framebuffer_ms);
    const GLuint ms[4] = {t->diffuse_ms, t->specular_ms, t->albedo_ms, t->depth_stencil_ms};
    glDeleteTextures(4, ms);
  }
  const GLuint textures[7] = {t->diffuse, t->specular, t->depth_stencil, t->after, t->output, t->profile, t->albedo};
  glDeleteTextures(7, textures);
  *t = FrameTargets{};
}

}  // namespace demo
