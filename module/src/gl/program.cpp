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

const char* stage_name(GLenum type) {
  return type == VERTEX_SHADER ? "vertex shader: " : type == COMPUTE_SHADER ? "compute shader: " : "fragment shader: ";
}

GLuint compile(const Functions& gl, GLenum type, const AssembledShader& source, std::string* log) {
  const GLuint shader = gl.CreateShader(type);
  const GLchar* text = source.text.c_str();
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, COMPILE_STATUS, &ok);
  if (!ok) {
    // The parts' #line numbers make the log's locations "source string:line"; name the strings.
    if (log) *log = stage_name(type) + name_log_sources(shader_log(gl, shader), source.files);
    gl.DeleteShader(shader);
    return 0;
  }
  return shader;
}

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

bool assemble(const ShaderRecipe& recipe, AssembledShader* out, std::string* log) {
  std::string error;
  if (assemble_shader(recipe, out, &error)) return true;
  if (log) *log = "assembling " + recipe.top + ": " + error;
  return false;
}

}  // namespace

GLuint build_compute_program(const Functions& gl, const AssembledShader& compute_source, std::string* log) {
  const GLuint compute = compile(gl, COMPUTE_SHADER, compute_source, log);
  if (compute == 0) return 0;
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, compute);
  gl.DeleteShader(compute);  // flagged; goes away with the program
  return link(gl, program, log);
}

GLuint build_program(const Functions& gl, const AssembledShader& vertex_source, const AssembledShader& fragment_source,
                     std::string* log) {
  const GLuint vertex = compile(gl, VERTEX_SHADER, vertex_source, log);
  if (vertex == 0) return 0;
  const GLuint fragment = compile(gl, FRAGMENT_SHADER, fragment_source, log);
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

GLuint build_program(const Functions& gl, const ShaderRecipe& vertex, const ShaderRecipe& fragment,
                     std::string* log) {
  AssembledShader vertex_source, fragment_source;
  if (!assemble(vertex, &vertex_source, log) || !assemble(fragment, &fragment_source, log)) return 0;
  return build_program(gl, vertex_source, fragment_source, log);
}

GLuint build_compute_program(const Functions& gl, const ShaderRecipe& compute, std::string* log) {
  AssembledShader source;
  if (!assemble(compute, &source, log)) return 0;
  return build_compute_program(gl, source, log);
}

}  // namespace sss::gl
