#include "fullscreen.hpp"

#include <stdexcept>
#include <vector>

#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_bench {


FullscreenPass::FullscreenPass() {
  glGenFramebuffers(1, &framebuffer_);
  glGenVertexArrays(1, &vertex_array_);
}

FullscreenPass::~FullscreenPass() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

bool FullscreenPass::bind_targets(std::initializer_list<GLuint> targets, int width, int height, std::string* error) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  std::vector<GLenum> buffers;
  int index = 0;
  for (GLuint target : targets) {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index), GL_TEXTURE_2D,
                           target, 0);
    buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index));
    ++index;
  }
  for (int stale = index; stale < attached_; ++stale) {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(stale), GL_TEXTURE_2D, 0, 0);
  }
  attached_ = index;
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  glViewport(0, 0, width, height);
  const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    if (error != nullptr) *error = "framebuffer incomplete: status " + std::to_string(status);
    return false;
  }
  return true;
}

void FullscreenPass::bind_texture(GLuint unit, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture);
}

void FullscreenPass::draw() const {
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

GLuint build_fullscreen_program(const char* name, const char* fragment_source) {
  const GLuint program = build_program(name, host_gl::kFullscreenVertexShader, fragment_source);
  if (program == 0) throw std::runtime_error(std::string("cannot build the ") + name + " program");
  return program;
}

}  // namespace sss_bench
