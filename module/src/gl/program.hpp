// Compiling and linking the module's shaders, assembled from their parts (shader_source.hpp), with
// the driver's log kept for the error message, its locations named by file.
#pragma once

#include <string>

#include "gl_functions.hpp"
#include "shader_source.hpp"

namespace sss::gl {

// Links a program from an assembled vertex and fragment stage. Returns 0 and fills `log` on
// failure ("fragment shader: separable_blur.frag:12:3: error: ..."); leaves no shader behind.
GLuint build_program(const Functions& gl, const AssembledShader& vertex, const AssembledShader& fragment,
                     std::string* log);
// Links a program from one assembled compute stage; the same contract.
GLuint build_compute_program(const Functions& gl, const AssembledShader& compute, std::string* log);

// The same from recipes of the embedded pieces; an assembly error (an unknown piece) fills `log` too.
GLuint build_program(const Functions& gl, const ShaderRecipe& vertex, const ShaderRecipe& fragment,
                     std::string* log);
GLuint build_compute_program(const Functions& gl, const ShaderRecipe& compute, std::string* log);

}  // namespace sss::gl
