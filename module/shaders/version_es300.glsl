#version 300 es
// GLSL ES 3.00 (OpenGL ES 3.x). highp everywhere: the weights and depths need float precision
// (mediump may be fp16), and samplers default to lowp. Depth is only ever fetched (texelFetch),
// never filtered, which ES cannot do for depth textures.
precision highp float;
precision highp int;
precision highp sampler2D;
#define SSS_BINDING(unit)
// GLSL ES 3.00 has no explicit uniform locations: a pass struct is one array (one location), each
// field read from its part (gl/pass_uniforms.hpp).
#define SSS_UNIFORM_ARRAYS
#define SSS_UNIFORM_AT(n)
