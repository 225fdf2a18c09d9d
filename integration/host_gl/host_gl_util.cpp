#include "host_gl_util.hpp"

#include <chrono>
#include <cstdio>
#include <initializer_list>
#include <vector>

namespace host_gl {

namespace {

const char *gl_error_name(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

GLuint compile(const char *program_name, GLenum kind, const char *source) {
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    std::fprintf(stderr, "%s: %s shader failed to compile:\n%s\n", program_name,
                 kind == GL_VERTEX_SHADER ? "vertex" : "fragment", log.data());
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

bool check_gl(const char *stage) {
  bool ok = true;
  for (int i = 0; i < 16; ++i) {  // bounded: a lost context may report errors forever
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    std::fprintf(stderr, "GL error after %s: %s (0x%04x)\n", stage, gl_error_name(e), e);
    ok = false;
  }
  return ok;
}

namespace {
// Links the compiled shaders (deleting them); 0 and the log on stderr when linking fails.
GLuint link_program(const char *name, std::initializer_list<GLuint> shaders) {
  GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  for (GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    std::fprintf(stderr, "%s: program failed to link:\n%s\n", name, log.data());
    glDeleteProgram(program);
    return 0;
  }
  return program;
}
}  // namespace

GLuint build_program(const char *name, const char *vertex_source, const char *fragment_source) {
  GLuint vs = compile(name, GL_VERTEX_SHADER, vertex_source);
  GLuint fs = vs != 0 ? compile(name, GL_FRAGMENT_SHADER, fragment_source) : 0;
  if (vs == 0 || fs == 0) {
    if (vs != 0) glDeleteShader(vs);
    return 0;
  }
  return link_program(name, {vs, fs});
}

bool has_compute_shaders() {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return major * 10 + minor >= 43;
}

GLuint build_compute_program(const char *name, const char *source) {
  GLuint cs = compile(name, GL_COMPUTE_SHADER, source);
  return cs != 0 ? link_program(name, {cs}) : 0;
}

GLuint make_texture(GLint internal_format, GLsizei width, GLsizei height, GLenum format, GLenum type) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

bool check_framebuffer(const char *name) {
  GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    std::fprintf(stderr, "framebuffer '%s' is incomplete (status 0x%04x)\n", name, status);
    return false;
  }
  return true;
}

const char *const kFullscreenVertexShader = R"(#version 330 core
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

double now_ms() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
}

}  // namespace host_gl
