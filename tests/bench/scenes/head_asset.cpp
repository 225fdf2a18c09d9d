// Loader of the head scan (glTF 2.0 binary) with tinygltf. Debian's libtinygltf-dev ships the
// implementation as a shared library (libtinygltf.so, with stb_image and nlohmann-json inside), so
// this file includes the header without TINYGLTF_IMPLEMENTATION and links TinyGLTF::TinyGLTF.
//
// The asset: "Infinite, 3D Head Scan" by Lee Perry-Smith is licensed under a Creative Commons
// Attribution 3.0 Unported License. Based on a work at www.triplegangers.com. Permissions beyond the
// scope of this license may be available at http://www.ir-ltd.net/
#include "head_asset.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "scenes.hpp"

#ifndef SSS_ASSET_DIR
#error "SSS_ASSET_DIR must be defined by the build (CMake cache variable SSS_ASSET_DIR)"
#endif

namespace sss_bench {

std::string asset_dir() {
  const char* env = std::getenv("SSS_ASSET_DIR");
  if (env != nullptr && env[0] != '\0') return env;
  return SSS_ASSET_DIR;
}

const char* head_attribution() {
  return "\"Infinite, 3D Head Scan\" by Lee Perry-Smith is licensed under a Creative Commons "
         "Attribution 3.0 Unported License. Based on a work at www.triplegangers.com. Permissions "
         "beyond the scope of this license may be available at http://www.ir-ltd.net/";
}

}  // namespace sss_bench

namespace sss_bench::detail {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("head asset " + path + ": " + what);
}

// The accessor's elements as floats (FLOAT components only), `components` per element.
std::vector<float> read_float_accessor(const tinygltf::Model& model, int index, int components,
                                       const std::string& path, const char* what) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) fail(path, std::string("no ") + what);
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) != components)
    fail(path, std::string(what) + " is not a float vector of the expected size");
  if (a.sparse.isSparse) fail(path, std::string(what) + " is sparse");
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(a.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<size_t>(view.buffer));
  const size_t element = sizeof(float) * static_cast<size_t>(components);
  const size_t stride = view.byteStride != 0 ? view.byteStride : element;
  const size_t start = view.byteOffset + a.byteOffset;
  if (a.count > 0 && (start + stride * (a.count - 1) + element > buffer.data.size() ||
                      a.byteOffset + stride * (a.count - 1) + element > view.byteLength))
    fail(path, std::string(what) + " runs past its buffer");
  std::vector<float> out(a.count * static_cast<size_t>(components));
  for (size_t i = 0; i < a.count; ++i)
    std::memcpy(&out[i * static_cast<size_t>(components)], buffer.data.data() + start + i * stride, element);
  return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& path) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) fail(path, "no indices");
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  size_t size = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
    default: fail(path, "indices of an unexpected type");
  }
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(a.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<size_t>(view.buffer));
  const size_t stride = view.byteStride != 0 ? view.byteStride : size;
  const size_t start = view.byteOffset + a.byteOffset;
  if (a.count > 0 && start + stride * (a.count - 1) + size > buffer.data.size()) fail(path, "indices run past their buffer");
  std::vector<uint32_t> out(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = buffer.data.data() + start + i * stride;
    if (size == 1) {
      out[i] = p[0];
    } else if (size == 2) {
      uint16_t v;
      std::memcpy(&v, p, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], p, 4);
    }
  }
  return out;
}

HeadImage read_texture(const tinygltf::Model& model, int texture, const std::string& path, const char* what) {
  if (texture < 0 || static_cast<size_t>(texture) >= model.textures.size()) fail(path, std::string("no ") + what + " texture");
  const int source = model.textures[static_cast<size_t>(texture)].source;
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) fail(path, std::string("no ") + what + " image");
  const tinygltf::Image& image = model.images[static_cast<size_t>(source)];
  if (image.bits != 8 || (image.component != 3 && image.component != 4) || image.width <= 0 || image.height <= 0 ||
      image.image.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * static_cast<size_t>(image.component))
    fail(path, std::string(what) + " image was not decoded to 8-bit RGB(A)");
  HeadImage out;
  out.width = image.width;
  out.height = image.height;
  out.components = image.component;
  out.pixels = image.image;
  return out;
}

std::unique_ptr<HeadAsset> load(const std::string& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  if (!loader.LoadBinaryFromFile(&model, &error, &warning, path))
    fail(path, "cannot be loaded (" + (error.empty() ? std::string("unknown error") : error) +
                   "); set SSS_ASSET_DIR to the folder holding lee-perry-smith-head/");
  if (model.meshes.size() != 1 || model.meshes[0].primitives.size() != 1)
    fail(path, "expected one mesh with one primitive");
  const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES) fail(path, "the primitive is not a triangle list");
  for (const tinygltf::Node& node : model.nodes)
    if (!node.matrix.empty() || !node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
      fail(path, "node transforms are not supported (the scan is expected in metres at the origin)");
  auto attribute = [&](const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  const std::vector<float> position = read_float_accessor(model, attribute("POSITION"), 3, path, "POSITION");
  const std::vector<float> normal = read_float_accessor(model, attribute("NORMAL"), 3, path, "NORMAL");
  const std::vector<float> texcoord = read_float_accessor(model, attribute("TEXCOORD_0"), 2, path, "TEXCOORD_0");
  const std::vector<float> tangent = read_float_accessor(model, attribute("TANGENT"), 4, path, "TANGENT");
  const size_t count = position.size() / 3;
  if (normal.size() / 3 != count || texcoord.size() / 2 != count || tangent.size() / 4 != count || count == 0)
    fail(path, "attribute counts differ");

  auto asset = std::make_unique<HeadAsset>();
  asset->path = path;
  asset->indices = read_indices(model, primitive.indices, path);
  if (asset->indices.empty() || asset->indices.size() % 3 != 0) fail(path, "index count is not a multiple of 3");
  for (uint32_t i : asset->indices)
    if (i >= count) fail(path, "an index is out of range");

  asset->vertices.resize(count * HeadAsset::kFloatsPerVertex);
  for (int k = 0; k < 3; ++k) {
    asset->bounds_min[k] = position[static_cast<size_t>(k)];
    asset->bounds_max[k] = position[static_cast<size_t>(k)];
  }
  for (size_t v = 0; v < count; ++v) {
    float* out = &asset->vertices[v * HeadAsset::kFloatsPerVertex];
    std::memcpy(out + 0, &position[v * 3], 3 * sizeof(float));
    std::memcpy(out + 3, &normal[v * 3], 3 * sizeof(float));
    std::memcpy(out + 6, &texcoord[v * 2], 2 * sizeof(float));
    std::memcpy(out + 8, &tangent[v * 4], 4 * sizeof(float));
    for (int k = 0; k < 12; ++k)
      if (!std::isfinite(out[k])) fail(path, "a vertex attribute is not finite");
    for (int k = 0; k < 3; ++k) {
      asset->bounds_min[k] = std::min(asset->bounds_min[k], out[k]);
      asset->bounds_max[k] = std::max(asset->bounds_max[k], out[k]);
    }
  }

  if (primitive.material < 0 || static_cast<size_t>(primitive.material) >= model.materials.size())
    fail(path, "the primitive has no material");
  const tinygltf::Material& material = model.materials[static_cast<size_t>(primitive.material)];
  asset->albedo = read_texture(model, material.pbrMetallicRoughness.baseColorTexture.index, path, "base colour");
  asset->normal = read_texture(model, material.normalTexture.index, path, "normal");
  return asset;
}

}  // namespace

std::string head_asset_path() { return asset_dir() + "/lee-perry-smith-head/head.glb"; }

const HeadAsset& head_asset() {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<HeadAsset>> cache;  // by path: SSS_ASSET_DIR may change
  std::lock_guard<std::mutex> lock(mutex);
  const std::string path = head_asset_path();
  std::unique_ptr<HeadAsset>& entry = cache[path];
  if (!entry) entry = load(path);
  return *entry;
}

}  // namespace sss_bench::detail
