// The head scan of the head scenes, decoded once per process.
//
// "Infinite, 3D Head Scan" by Lee Perry-Smith is licensed under a Creative Commons Attribution 3.0
// Unported License. Based on a work at www.triplegangers.com. Permissions beyond the scope of this
// license may be available at http://www.ir-ltd.net/
// (assets/lee-perry-smith-head/README.md; any image of it must carry this attribution.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gltf_mesh.hpp"

namespace sss_bench::detail {

// An 8-bit image as decoded from the .glb (integration/gltf_mesh): rows top first (the first row is
// glTF's v = 0, so uploading rows in this order lets a shader sample at the glTF texcoord
// unchanged); components 3 (RGB) or 4 (RGBA) for the head's two maps.
using HeadImage = gltf_mesh::Image;

struct HeadAsset {
  static constexpr int kFloatsPerVertex = gltf_mesh::Model::kFloatsPerVertex;  // position xyz, normal xyz, texcoord uv, tangent xyzw
  std::vector<float> vertices;                 // metres, Y up, face towards +Z
  std::vector<uint32_t> indices;               // triangles
  float bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};
  HeadImage albedo;  // sRGB
  HeadImage normal;  // tangent space, linear
  std::string path;
};

// <asset_dir()>/lee-perry-smith-head/head.glb
std::string head_asset_path();

// Loads and decodes the asset on the first call (thread-safe) and keeps it for the process.
// Throws std::runtime_error naming the file when it is missing or not the expected mesh.
const HeadAsset& head_asset();

}  // namespace sss_bench::detail
