// The scene's mesh and textures in GL: one interleaved vertex buffer (attributes 0 position,
// 1 normal, 2 texcoord, 3 tangent), 32-bit indices, and per material its base-colour texture
// (SRGB8(_ALPHA8), mipmapped) and normal texture (RGB8/RGBA8, mipmapped); materials without one
// get a 1x1 white / flat-normal texture.
#pragma once

#include "gl_functions.hpp"
#include "scene.hpp"

#include <vector>

namespace demo {

struct GpuMaterial {
  GLuint albedo = 0;  // sampled as sRGB
  GLuint normal = 0;
};

struct GpuScene {
  GLuint vao = 0;
  GLuint vertex_buffer = 0;
  GLuint index_buffer = 0;
  std::vector<GLuint> textures;  // owned: images, then the two 1x1 defaults
  std::vector<GpuMaterial> materials;
};

// Needs a current context. Returns false (after printing why) on a GL error.
bool create_gpu_scene(const DemoScene &scene, GpuScene *gpu);
void destroy_gpu_scene(GpuScene *gpu);

// Draws one primitive; the scene's VAO must be bound.
void draw_primitive(const gltf_mesh::Primitive &primitive);

}  // namespace demo
