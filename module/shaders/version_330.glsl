#version 330 core
// GLSL 3.30 (OpenGL 3.3 to 4.1): sampler units set with glUniform1i.
#define SSS_BINDING(unit)
