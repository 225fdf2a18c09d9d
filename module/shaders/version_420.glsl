#version 420 core
#extension GL_ARB_explicit_uniform_location : require
// GLSL 4.20 (OpenGL 4.2+ with GL_ARB_explicit_uniform_location, core in 4.3): sampler units fixed in
// the shader with layout(binding), so no glUniform1i per sampler, and each pass struct's fields at
// the locations of their table (gl/pass_uniforms.hpp), so no glGetUniformLocation per field.
#define SSS_BINDING(unit) layout(binding = unit)
#define SSS_UNIFORM_AT(n) layout(location = n)
