#include "gl_fixture.hpp"

#include <cstring>

#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_test {

namespace {
// OpenGL ES has no glGetTexImage: the texture goes on a framebuffer of its own and glReadPixels
// reads it (RGBA/FLOAT, which EXT_color_buffer_float allows for float colour buffers). Leaves the
// caller's read framebuffer, pack buffer and alignment.
void read_rgba_es(GLuint texture, int width, int height, float* out) {
  GLint read_fb = 0, pack_buffer = 0, alignment = 4;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fb);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  GLuint fb = 0;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  EXPECT_EQ(glCheckFramebufferStatus(GL_READ_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fb));
  glDeleteFramebuffers(1, &fb);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
}

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
  desc.minor = sss_headless_backend_is_gles(desc.backend) ? 0 : 3;  // OpenGL ES 3.0, or GL 3.3 core
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

DrawTarget::DrawTarget(GLuint target, int width, int height) {
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  glViewport(0, 0, width, height);
}

DrawTarget::~DrawTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

GLuint make_host_program(bool es) {
  const char* vs = es ? "#version 300 es\nvoid main(){gl_Position=vec4(0.0);}\n"
                      : "#version 330 core\nvoid main(){gl_Position=vec4(0.0);}\n";
  const char* fs = es ? "#version 300 es\nprecision mediump float;out vec4 c;void main(){c=vec4(1.0);}\n"
                      : "#version 330 core\nout vec4 c;void main(){c=vec4(1.0);}\n";
  const GLuint program = host_gl::build_program("host program", vs, fs);
  EXPECT_NE(program, 0u);
  return program;
}

sss_frame frame_of(GLuint color, GLuint depth, GLuint output) {
  sss_frame f = {};
  f.struct_size = sizeof f;
  f.color_texture = color;
  f.depth_texture = depth;
  f.output_texture = output;
  return f;
}

void describe_frame(sss_frame* f, uint32_t color_format, uint32_t output_format, uint32_t depth_format, int width,
                    int height) {
  f->color_format = color_format;
  f->output_format = f->output_texture != 0 ? output_format : 0u;
  f->depth_format = depth_format;
  f->texture_width = width;
  f->texture_height = height;
}

void* es30_get_proc_address(const char* name, void* user) {
  // llvmpipe gives OpenGL ES 3.2 for a 3.0 request; hiding the one ES 3.1 function the module
  // would use (the texture level query) makes it run exactly its ES 3.0 path.
  if (std::strcmp(name, "glGetTexLevelParameteriv") == 0) return nullptr;
  return sss_headless_get_proc_address(name, user);
}

int LogRecord::count(int level, const std::string& part) const {
  int n = 0;
  for (const auto& m : messages) n += m.first == level && m.second.find(part) != std::string::npos ? 1 : 0;
  return n;
}

void record_log(int level, const char* message, void* user) {
  static_cast<LogRecord*>(user)->messages.emplace_back(level, message);
}

sss_settings expect_settings_refused(sss_context* ctx, const sss_settings& bad, const std::string& field) {
  EXPECT_EQ(sss_set_settings(ctx, &bad), SSS_ERROR_INVALID_ARGUMENT) << field;
  EXPECT_NE(std::string(sss_last_error(ctx)).find(field), std::string::npos) << sss_last_error(ctx);
  sss_settings now = {};
  now.struct_size = sizeof now;
  EXPECT_EQ(sss_get_settings(ctx, &now), SSS_OK);
  return now;
}

namespace {
using GetStringFn = const GLubyte* (*)(GLenum);
struct Told {
  GLenum name = 0;
  const char* value = nullptr;
  sss_get_proc_address_fn base = nullptr;
  GetStringFn real_get_string = nullptr;
} g_told;

const GLubyte* get_string_told(GLenum name) {
  if (name == g_told.name) return reinterpret_cast<const GLubyte*>(g_told.value);
  return g_told.real_get_string(name);
}

void* told_get_proc_address(const char* name, void* user) {
  if (std::strcmp(name, "glGetString") == 0) {
    g_told.real_get_string = reinterpret_cast<GetStringFn>(g_told.base(name, user));
    return reinterpret_cast<void*>(&get_string_told);
  }
  return g_told.base(name, user);
}
}  // namespace

sss_get_proc_address_fn loader_telling(GLenum name, const char* value, sss_get_proc_address_fn base) {
  g_told = {name, value, base, nullptr};
  return told_get_proc_address;
}

void GlTest::fresh_sss(const sss_settings& s, const float* projection) {
  if (sss_ != nullptr) sss_destroy(sss_);
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
  ASSERT_EQ(sss_set_camera(sss_, projection), SSS_OK) << sss_last_error(sss_);
}

sss_context* GlTest::create_sss(uint32_t flags) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = loader_override_ != nullptr ? loader_override_
                          : is_gles()                  ? es30_get_proc_address
                                                       : sss_headless_get_proc_address;
  desc.get_proc_address_user = headless_;
  desc.flags = flags;
  if (log_ != nullptr) {
    desc.log = record_log;
    desc.log_user = log_;
  }
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
  if (is_gles()) {
    read_rgba_es(texture, width, height, out.data());
  } else {
    read_level0(texture, GL_RGBA, out.data());
  }
  return out;
}

std::vector<float> GlTest::read_depth(GLuint texture, int width, int height) {
  std::vector<float> out(static_cast<std::size_t>(width) * height);
  if (is_gles()) {
    ADD_FAILURE() << "read_depth: OpenGL ES cannot read depth back (no glGetTexImage, no depth glReadPixels)";
  } else {
    read_level0(texture, GL_DEPTH_COMPONENT, out.data());
  }
  return out;
}

bool GlTest::is_gles() const { return sss_headless_backend_is_gles(test_backend()) != 0; }

}  // namespace sss_test
