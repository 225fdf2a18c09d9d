#version 420 core
// GLSL 4.20 (OpenGL 4.2+): sampler units fixed in the shader, so no glUniform1i per sampler.
#define SSS_BINDING(unit) layout(binding = unit)
