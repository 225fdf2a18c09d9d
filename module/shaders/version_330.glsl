#version 330 core
// GLSL 3.30 (OpenGL 3.3 to 4.1): sampler units set with glUniform1i, depth filtered by the GL.
#define SSS_BINDING(unit)
#define SSS_MANUAL_DEPTH_FILTER 0
