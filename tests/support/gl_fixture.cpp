#include "gl_fixture.hpp"

using namespace host_gl;

namespace sss_test {

namespace {
// glGetTexImage of level 0 as floats, leaving the caller's binding, pack buffer and alignment.
void read_level0(GLuint texture, GLenum format, float* out) {
  GLint previous = 0, pack_buffer = 0, alignment = 4;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, format, GL_FLOAT, out);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
}
}  // namespace

namespace {
sss_headless_backend g_backend = SSS_HEADLESS_OSMESA;
}

sss_headless_backend test_backend() { return g_backend; }
void set_test_backend(sss_headless_backend backend) { g_backend = backend; }

void GlTest::SetUp() {
  sss_headless_desc desc = {};
  desc.backend = test_backend();
  desc.major = 3;
  desc.minor = 3;
  desc.core_profile = 1;
  char error[512] = "";
  ASSERT_EQ(sss_headless_create(&desc, &headless_, error, sizeof error), 0) << error;
  backend_name_ = sss_headless_backend_name(desc.backend);
  std::string missing;
  ASSERT_TRUE(host_gl::load(sss_headless_get_proc_address, headless_, &missing)) << missing;
}

void GlTest::TearDown() {
  if (headless_ == nullptr) return;
  sss_headless_make_current(headless_);
  sss_destroy(sss_);
  sss_ = nullptr;
  if (!textures_.empty()) glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  textures_.clear();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  sss_headless_destroy(headless_);
  headless_ = nullptr;
}

sss_context* GlTest::create_sss(uint32_t flags) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless_;
  desc.flags = flags;
  sss_context* ctx = nullptr;
  const sss_result r = sss_create(&desc, &ctx);
  EXPECT_EQ(r, SSS_OK) << sss_last_error(nullptr);
  return ctx;
}

GLuint GlTest::make_texture(GLenum internal_format, int width, int height, GLenum format, GLenum type,
                            const void* data) {
  // Leaves the caller's binding, unpack buffer and alignment as they were (state tests set them).
  GLint previous = 0, unpack_buffer = 0, alignment = 4;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer));
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  textures_.push_back(texture);
  return texture;
}

GLuint GlTest::make_rgba32f(int width, int height, const std::vector<float>& rgba) {
  return make_texture(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, rgba.data());
}

GLuint GlTest::make_rgba16f(int width, int height, const std::vector<float>& rgba) {
  return make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_FLOAT, rgba.data());
}

GLuint GlTest::make_depth32f(int width, int height, const std::vector<float>& depth) {
  return make_texture(GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
}

std::vector<float> GlTest::read_rgba(GLuint texture, int width, int height) {
  std::vector<float> out(static_cast<std::size_t>(width) * height * 4);
  read_level0(texture, GL_RGBA, out.data());
  return out;
}

std::vector<float> GlTest::read_depth(GLuint texture, int width, int height) {
  std::vector<float> out(static_cast<std::size_t>(width) * height);
  read_level0(texture, GL_DEPTH_COMPONENT, out.data());
  return out;
}

}  // namespace sss_test
