#version 330 core
// GLSL 3.30 (OpenGL 3.3 to 4.1, or a later context without GL_ARB_explicit_uniform_location):
// sampler units set with glUniform1i, a pass struct's field locations looked up at link.
#define SSS_BINDING(unit)
#define SSS_UNIFORM_AT(n)
