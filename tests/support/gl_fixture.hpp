// A GL test: a fresh headless context per test on the backend chosen with --sss-backend (see
// gl_test_main.cpp; ctest runs every GL test once per backend), the host-side GL loaded, and
// helpers to make and read textures.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "host_gl.hpp"
#include "sss/sss_tools.h"
#include "sss_headless.h"

namespace sss_test {

// The messages a context logged (sss_create_desc.log), in order, with their levels.
struct LogRecord {
  std::vector<std::pair<int, std::string>> messages;
  bool has(int level, const std::string& part) const { return count(level, part) > 0; }
  int count(int level, const std::string& part = "") const;  // messages of `level` containing `part`
};
// An sss_log_fn that appends to the LogRecord `user`.
void record_log(int level, const char* message, void* user);

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
  // sss_ replaced by a fresh context (create_sss) with the settings `s` and the camera `projection`
  // (16 floats); the test fails where any of it does.
  void fresh_sss(const sss_settings& s, const float* projection);

  // When set, create_sss loads GL through it instead (user: the sss_headless).
  sss_get_proc_address_fn loader_override_ = nullptr;
  // When set, create_sss's contexts log into it (else they log nothing).
  LogRecord* log_ = nullptr;
  sss_headless* headless_ = nullptr;
  sss_context* sss_ = nullptr;
  std::vector<GLuint> textures_;
  std::string backend_name_;
};

// A full-screen draw into `target`: a framebuffer with it as colour attachment 0 and an empty
// vertex array, both bound, and the viewport over width x height. Both deleted on destruction.
class DrawTarget {
 public:
  DrawTarget(GLuint target, int width, int height);
  ~DrawTarget();
  DrawTarget(const DrawTarget&) = delete;
  DrawTarget& operator=(const DrawTarget&) = delete;

 private:
  GLuint framebuffer_ = 0, vertex_array_ = 0;
};

// A program that links and draws nothing of note (a point at the origin, white): what a host leaves
// bound, for the tests of the state the module restores. GLSL ES 3.00 when `es`, else 330 core.
GLuint make_host_program(bool es);

// A frame of these textures (output 0: write back), every other field zero.
sss_frame frame_of(GLuint color, GLuint depth, GLuint output = 0);
// Describes *f (sss.h: a described frame asks the GL nothing about its textures): the formats,
// the output's only where it has an output texture, and the size.
void describe_frame(sss_frame* f, uint32_t color_format, uint32_t output_format, uint32_t depth_format, int width,
                    int height);

// sss_headless_get_proc_address without glGetTexLevelParameteriv (ES 3.1+): an ES 3.2 context then
// looks like ES 3.0 to the module. `user` is the sss_headless.
void* es30_get_proc_address(const char* name, void* user);

// Checks that sss_set_settings refuses `bad` (SSS_ERROR_INVALID_ARGUMENT, the message naming
// `field`), and returns the settings `ctx` holds afterwards, for the caller to find them unchanged.
sss_settings expect_settings_refused(sss_context* ctx, const sss_settings& bad, const std::string& field);

// A loader whose glGetString answers `name` (GL_VERSION, GL_RENDERER...) with `value` and everything
// else as `base` loads it (user: the sss_headless): the module then sees another GL version or
// renderer. One such loader at a time (it keeps its answer in globals).
sss_get_proc_address_fn loader_telling(GLenum name, const char* value, sss_get_proc_address_fn base);

// The backend the tests run on (default OSMesa).
sss_headless_backend test_backend();
void set_test_backend(sss_headless_backend backend);

}  // namespace sss_test
