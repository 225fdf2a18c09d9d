#include "program.hpp"

#include <vector>

namespace sss::gl {

namespace {

std::string shader_log(const Functions& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, INFO_LOG_LENGTH, &length);
  std::vector<GLchar> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  gl.GetShaderInfoLog(shader, static_cast<GLsizei>(text.size()), nullptr, text.data());
  return text.data();
}

GLuint compile(const Functions& gl, GLenum type, const std::string& header, const char* body, std::string* log) {
  const GLuint shader = gl.CreateShader(type);
  const GLchar* parts[2] = {header.c_str(), body};
  gl.ShaderSource(shader, 2, parts, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, COMPILE_STATUS, &ok);
  if (!ok) {
    const char* stage = type == VERTEX_SHADER    ? "vertex shader: "
                        : type == COMPUTE_SHADER ? "compute shader: "
                                                 : "fragment shader: ";
    if (log) *log = stage + shader_log(gl, shader);
    gl.DeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

namespace {
GLuint link(const Functions& gl, GLuint program, std::string* log) {
  gl.LinkProgram(program);
  GLint ok = 0;
  gl.GetProgramiv(program, LINK_STATUS, &ok);
  if (ok) return program;
  if (log) {
    GLint length = 0;
    gl.GetProgramiv(program, INFO_LOG_LENGTH, &length);
    std::vector<GLchar> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    gl.GetProgramInfoLog(program, static_cast<GLsizei>(text.size()), nullptr, text.data());
    *log = std::string("link: ") + text.data();
  }
  gl.DeleteProgram(program);
  return 0;
}
}  // namespace

GLuint build_compute_program(const Functions& gl, const std::string& header, const char* compute_source,
                             std::string* log) {
  const GLuint compute = compile(gl, COMPUTE_SHADER, header, compute_source, log);
  if (compute == 0) return 0;
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, compute);
  gl.DeleteShader(compute);  // flagged; goes away with the program
  return link(gl, program, log);
}

GLuint build_program(const Functions& gl, const std::string& header, const char* vertex_source,
                     const char* fragment_source, std::string* log) {
  const GLuint vertex = compile(gl, VERTEX_SHADER, header, vertex_source, log);
  if (vertex == 0) return 0;
  const GLuint fragment = compile(gl, FRAGMENT_SHADER, header, fragment_source, log);
  if (fragment == 0) {
    gl.DeleteShader(vertex);
    return 0;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  // Flagged for deletion; they go away with the program.
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  return link(gl, program, log);
}

}  // namespace sss::gl
