// Full-screen passes for the benchmark's own GL methods: a framebuffer with any number of colour
// targets, a full-screen triangle, and the vertex shader every pass shares.
#pragma once

#include <initializer_list>
#include <string>

#include "host_gl.hpp"

namespace sss_bench {

class FullscreenPass {
 public:
  FullscreenPass();
  ~FullscreenPass();
  FullscreenPass(const FullscreenPass&) = delete;
  FullscreenPass& operator=(const FullscreenPass&) = delete;

  // Attaches `targets` as colour attachments 0..n-1 (draw buffers in that order) of the pass's
  // framebuffer, binds it and sets the viewport. False (with `error`) when incomplete.
  bool bind_targets(std::initializer_list<GLuint> targets, int width, int height, std::string* error);
  static void bind_texture(GLuint unit, GLuint texture);
  void draw() const;

 private:
  GLuint framebuffer_ = 0, vertex_array_ = 0;
  int attached_ = 0;
};

// Compiles host_gl::kFullscreenVertexShader with `fragment_source`; throws std::runtime_error on failure.
GLuint build_fullscreen_program(const char* name, const char* fragment_source);

}  // namespace sss_bench
