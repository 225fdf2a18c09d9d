// gltf_mesh: a glTF 2.0 file (.gltf or .glb) flattened into one CPU-side triangle mesh with its
// materials and decoded images, for the project's host programs (the demo renders it, the
// benchmark's head scenes take the head scan from it). Not part of the library.
//
// What is read: the default scene's node tree (matrix or TRS transforms, applied to the vertices),
// every TRIANGLES primitive of its meshes with POSITION (required), NORMAL, TEXCOORD_0 (float or
// normalised unsigned byte/short) and TANGENT, 8/16/32-bit indices; per material the base colour
// factor and texture, the normal texture and its scale, the roughness factor and doubleSided.
// What is made up when missing (glTF 2.0 §3.7.2.1): flat normals (the triangles of such a primitive
// get their own vertices), tangents from the texture coordinates (per-vertex sums of the triangles'
// dP/du, orthogonalised; w = handedness), indices 0..n-1. Skins, morph targets, cameras, lights,
// animations and other primitive modes are ignored (counted in `warnings`). Sparse accessors are an
// error.
//
// Debian's libtinygltf-dev is a shared library that holds the implementation (and its stb_image),
// so no TINYGLTF_IMPLEMENTATION anywhere in the project.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gltf_mesh {

// An 8-bit image as decoded from the file (16-bit images are reduced to 8): rows top first (the
// first row is glTF's v = 0, so rows uploaded in this order let a shader sample at the glTF texcoord
// unchanged).
struct Image {
  int width = 0, height = 0, components = 0;  // components: 1..4
  std::vector<uint8_t> pixels;
  std::string name;
};

struct Material {
  std::string name;
  float base_color[4] = {1, 1, 1, 1};  // linear factor
  int base_color_image = -1;           // index into Model::images (sRGB-encoded), or -1
  int normal_image = -1;               // index into Model::images (tangent space, linear), or -1
  float normal_scale = 1.0f;
  float roughness = 1.0f;              // pbrMetallicRoughness.roughnessFactor
  bool double_sided = false;
};

// A run of triangles with one material.
struct Primitive {
  uint32_t first_index = 0;  // into Model::indices
  uint32_t index_count = 0;  // a multiple of 3
  int material = -1;         // index into Model::materials; -1: the default material
  std::string mesh_name;
};

struct Model {
  // position xyz (world: node transforms applied; glTF's unit is the metre), normal xyz,
  // texcoord uv, tangent xyzw (w = +-1: bitangent = cross(normal, tangent.xyz) * w)
  static constexpr int kFloatsPerVertex = 12;
  std::vector<float> vertices;
  std::vector<uint32_t> indices;  // triangles, counter-clockwise front faces
  std::vector<Primitive> primitives;
  std::vector<Material> materials;
  std::vector<Image> images;
  float bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};

  // Whether every primitive brought the attribute (false: some were made up as described above).
  bool file_normals = true, file_texcoords = true, file_tangents = true;
  int transformed_nodes = 0;  // nodes on the drawn paths with a transform other than the identity
  std::string path;
  std::string copyright;  // asset.copyright, often the licence and attribution
  std::string generator;  // asset.generator
  std::vector<std::string> warnings;  // the loader's warnings and what was ignored

  size_t vertex_count() const { return vertices.size() / kFloatsPerVertex; }
};

// Loads the file (binary when it starts with "glTF", else JSON with its external files resolved
// next to it). Throws std::runtime_error with a message that starts with "glTF <path>: " when the
// file cannot be read or decoded, holds no triangles, or breaks the rules above.
Model load_gltf(const std::string& path);

}  // namespace gltf_mesh
