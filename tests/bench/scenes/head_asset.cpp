// The head scan (glTF 2.0 binary), loaded with the project's glTF loader (integration/gltf_mesh,
// tinygltf inside) and checked to be the mesh the head scenes expect.
//
// The asset: "Infinite, 3D Head Scan" by Lee Perry-Smith is licensed under a Creative Commons
// Attribution 3.0 Unported License. Based on a work at www.triplegangers.com. Permissions beyond the
// scope of this license may be available at http://www.ir-ltd.net/
#include "head_asset.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "scenes.hpp"
#include "shared_assets.hpp"

namespace sss_bench {

std::string asset_dir() { return sss_assets::asset_dir(); }

const char* head_attribution() { return sss_assets::head_attribution(); }

}  // namespace sss_bench

namespace sss_bench::detail {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("head asset " + path + ": " + what);
}

std::unique_ptr<HeadAsset> load(const std::string& path) {
  gltf_mesh::Model model;
  try {
    model = gltf_mesh::load_gltf(path);
  } catch (const std::runtime_error& e) {
    fail(path, std::string(e.what()) + "; set SSS_ASSET_DIR to the folder holding lee-perry-smith-head/");
  }
  if (model.primitives.size() != 1) fail(path, "expected one mesh with one primitive");
  if (!model.file_normals || !model.file_texcoords || !model.file_tangents)
    fail(path, "expected NORMAL, TEXCOORD_0 and TANGENT in the file");
  if (model.transformed_nodes != 0)
    fail(path, "node transforms are not expected (the scan is expected in metres at the origin)");
  const int material = model.primitives[0].material;
  if (material < 0) fail(path, "the primitive has no material");
  const gltf_mesh::Material& m = model.materials[static_cast<size_t>(material)];
  if (m.base_color_image < 0) fail(path, "no base colour texture");
  if (m.normal_image < 0) fail(path, "no normal texture");

  auto asset = std::make_unique<HeadAsset>();
  asset->path = path;
  asset->albedo = model.images[static_cast<size_t>(m.base_color_image)];
  asset->normal = model.images[static_cast<size_t>(m.normal_image)];
  for (const HeadImage* image : {&asset->albedo, &asset->normal})
    if (image->components != 3 && image->components != 4) fail(path, "a texture is not 8-bit RGB(A)");
  asset->vertices = std::move(model.vertices);
  asset->indices = std::move(model.indices);
  for (int k = 0; k < 3; ++k) {
    asset->bounds_min[k] = model.bounds_min[k];
    asset->bounds_max[k] = model.bounds_max[k];
  }
  return asset;
}

}  // namespace

std::string head_asset_path() { return sss_assets::head_path(); }

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
