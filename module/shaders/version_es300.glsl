#version 300 es
// GLSL ES 3.00 (OpenGL ES 3.x). highp everywhere: the weights and depths need float precision
// (mediump may be fp16), and samplers default to lowp. ES cannot filter depth textures, so the
// shader filters depth itself (SSS_MANUAL_DEPTH_FILTER).
precision highp float;
precision highp int;
precision highp sampler2D;
#define SSS_BINDING(unit)
#define SSS_MANUAL_DEPTH_FILTER 1
