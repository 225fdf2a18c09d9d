// Compiling and linking the embedded shaders, with the driver's log kept for the error message.
#pragma once

#include <string>

#include "gl_functions.hpp"

namespace sss::gl {

// Links a program from a vertex and a fragment source, each preceded by `header` (the #version
// line and the variant's #defines). Returns 0 and fills `log` on failure; leaves no shader behind.
GLuint build_program(const Functions& gl, const std::string& header, const char* vertex_source,
                     const char* fragment_source, std::string* log);

// Links a program from one compute shader source preceded by `header`; the same contract.
GLuint build_compute_program(const Functions& gl, const std::string& header, const char* compute_source,
                             std::string* log);

}  // namespace sss::gl
