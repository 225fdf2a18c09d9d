#version 430 core
// GLSL 4.30 (OpenGL 4.3+): the compute path's blur (separable_blur.comp) only; its bindings are
// fixed in the shader with layout(binding), its struct's fields at their table's locations.
#define SSS_BINDING(unit) layout(binding = unit)
#define SSS_UNIFORM_AT(n) layout(location = n)
