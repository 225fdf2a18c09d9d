// A GL test: a fresh headless context per test on the backend chosen with --sss-backend (see
// gl_test_main.cpp; ctest runs every GL test once per backend), the host-side GL loaded, and
// helpers to make and read textures.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "host_gl.hpp"
#include "sss/sss.h"
#include "sss_headless.h"

namespace sss_test {

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // A GL_TEXTURE_2D with the given storage; data may be NULL. Deleted in TearDown.
  GLuint make_texture(GLenum internal_format, int width, int height, GLenum format, GLenum type, const void* data);
  GLuint make_rgba32f(int width, int height, const std::vector<float>& rgba);
  GLuint make_rgba16f(int width, int height, const std::vector<float>& rgba);
  GLuint make_depth32f(int width, int height, const std::vector<float>& depth);
  // Every texel of level 0 as floats (RGBA for colour, one value for depth/R formats). On OpenGL ES
  // colour is read through a framebuffer; depth cannot be read back there (read_depth fails the test).
  std::vector<float> read_rgba(GLuint texture, int width, int height);
  std::vector<float> read_depth(GLuint texture, int width, int height);
  // The test runs on an OpenGL ES context (backend egl-gles).
  bool is_gles() const;

  // On OpenGL ES through es30_get_proc_address (the module's ES 3.0 path).
  sss_context* create_sss(uint32_t flags = 0);

  // When set, create_sss loads GL through it instead (user: the sss_headless).
  sss_get_proc_address_fn loader_override_ = nullptr;
  sss_headless* headless_ = nullptr;
  sss_context* sss_ = nullptr;
  std::vector<GLuint> textures_;
  std::string backend_name_;
};

// sss_headless_get_proc_address without glGetTexLevelParameteriv (ES 3.1+): an ES 3.2 context then
// looks like ES 3.0 to the module. `user` is the sss_headless.
void* es30_get_proc_address(const char* name, void* user);

// The backend the tests run on (default OSMesa).
sss_headless_backend test_backend();
void set_test_backend(sss_headless_backend backend);

}  // namespace sss_test
