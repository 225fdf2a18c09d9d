#include "gltf_mesh.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace gltf_mesh {

namespace {

using Mat4 = std::array<double, 16>;  // column-major, element (row r, column c) at [c * 4 + r]

constexpr Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("glTF " + path + ": " + what);
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += a[static_cast<size_t>(k * 4 + r)] * b[static_cast<size_t>(c * 4 + k)];
      out[static_cast<size_t>(c * 4 + r)] = sum;
    }
  return out;
}

// The node's local transform: its matrix, or T * R * S.
Mat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Mat4 m{};
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  Mat4 m = kIdentity;
  if (node.rotation.size() == 4) {
    const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
    m = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),     0,
         2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),     0,
         2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y), 0,
         0,                       0,                       0,                       1};
  }
  if (node.scale.size() == 3)
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) m[static_cast<size_t>(c * 4 + r)] *= node.scale[static_cast<size_t>(c)];
  if (node.translation.size() == 3)
    for (int r = 0; r < 3; ++r) m[static_cast<size_t>(12 + r)] = node.translation[static_cast<size_t>(r)];
  return m;
}

bool is_identity(const Mat4& m) {
  for (size_t i = 0; i < 16; ++i)
    if (m[i] != kIdentity[i]) return false;
  return true;
}

// The attribute as `components` floats per element: FLOAT, or (normalised) UNSIGNED_BYTE/SHORT.
std::vector<float> read_accessor(const tinygltf::Model& model, int index, int components, const std::string& path,
                                 const std::string& what) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) fail(path, "no accessor for " + what);
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  if (tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) != components)
    fail(path, what + " has " + std::to_string(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type))) +
                   " components, expected " + std::to_string(components));
  if (a.sparse.isSparse) fail(path, what + " is a sparse accessor (not supported)");
  size_t size = 0;
  double scale = 1.0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: size = 4; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; scale = 1.0 / 255.0; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; scale = 1.0 / 65535.0; break;
    default: fail(path, what + " has an unsupported component type " + std::to_string(a.componentType));
  }
  if (size != 4 && !a.normalized) fail(path, what + " holds integers that are not normalised");
  std::vector<float> out(a.count * static_cast<size_t>(components), 0.0f);
  if (a.count == 0) return out;
  if (a.bufferView < 0) return out;  // all zeros (glTF 2.0: an accessor without a buffer view)
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(a.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<size_t>(view.buffer));
  const size_t element = size * static_cast<size_t>(components);
  const size_t stride = view.byteStride != 0 ? view.byteStride : element;
  const size_t start = view.byteOffset + a.byteOffset;
  if (start + stride * (a.count - 1) + element > buffer.data.size() ||
      a.byteOffset + stride * (a.count - 1) + element > view.byteLength)
    fail(path, what + " runs past its buffer");
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = buffer.data.data() + start + i * stride;
    for (size_t c = 0; c < static_cast<size_t>(components); ++c) {
      float value = 0.0f;
      if (size == 4) {
        std::memcpy(&value, p + 4 * c, 4);
      } else if (size == 1) {
        value = static_cast<float>(p[c] * scale);
      } else {
        uint16_t v = 0;
        std::memcpy(&v, p + 2 * c, 2);
        value = static_cast<float>(v * scale);
      }
      if (!std::isfinite(value)) fail(path, what + " holds a value that is not finite");
      out[i * static_cast<size_t>(components) + c] = value;
    }
  }
  return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index, size_t vertex_count, const std::string& path) {
  if (index < 0) {  // non-indexed: 0..n-1
    std::vector<uint32_t> out(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) out[i] = static_cast<uint32_t>(i);
    return out;
  }
  if (static_cast<size_t>(index) >= model.accessors.size()) fail(path, "no accessor for the indices");
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  if (a.sparse.isSparse) fail(path, "the indices are a sparse accessor (not supported)");
  size_t size = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
    default: fail(path, "indices of an unexpected type " + std::to_string(a.componentType));
  }
  std::vector<uint32_t> out(a.count);
  if (a.count == 0) return out;
  if (a.bufferView < 0) fail(path, "indices without a buffer view");
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(a.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<size_t>(view.buffer));
  const size_t stride = view.byteStride != 0 ? view.byteStride : size;
  const size_t start = view.byteOffset + a.byteOffset;
  if (start + stride * (a.count - 1) + size > buffer.data.size()) fail(path, "indices run past their buffer");
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = buffer.data.data() + start + i * stride;
    if (size == 1) {
      out[i] = p[0];
    } else if (size == 2) {
      uint16_t v = 0;
      std::memcpy(&v, p, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], p, 4);
    }
    if (out[i] >= vertex_count) fail(path, "an index is out of range");
  }
  return out;
}

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 normalize_or(V3 a, V3 fallback) {
  const double l = std::sqrt(dot(a, a));
  return l > 1e-20 ? a * (1.0 / l) : fallback;
}
V3 any_perpendicular(V3 n) {
  const V3 axis = std::fabs(n.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  return normalize_or(cross(axis, n), V3{1, 0, 0});
}

// One primitive's vertices before they join the model.
struct Part {
  std::vector<V3> position, normal;
  std::vector<std::array<double, 2>> texcoord;
  std::vector<std::array<double, 4>> tangent;
  std::vector<uint32_t> indices;
};

// Flat normals: every triangle gets its own three vertices.
void make_flat(Part* part) {
  Part flat;
  const size_t n = part->indices.size();
  flat.position.reserve(n);
  for (size_t t = 0; t + 2 < n; t += 3) {
    const V3 a = part->position[part->indices[t]], b = part->position[part->indices[t + 1]],
             c = part->position[part->indices[t + 2]];
    const V3 face = normalize_or(cross(b - a, c - a), V3{0, 0, 1});
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t i = part->indices[t + k];
      flat.position.push_back(part->position[i]);
      flat.normal.push_back(face);
      if (!part->texcoord.empty()) flat.texcoord.push_back(part->texcoord[i]);
      if (!part->tangent.empty()) flat.tangent.push_back(part->tangent[i]);
      flat.indices.push_back(static_cast<uint32_t>(flat.position.size() - 1));
    }
  }
  *part = std::move(flat);
}

// Tangents from the texture coordinates: per vertex, the sums of the adjacent triangles' dP/du
// and dP/dv; tangent = dP/du orthogonalised against the normal; w makes cross(N, T) * w point
// towards -v (up the image), the glTF convention (+green up in the normal map).
void make_tangents(Part* part) {
  const size_t count = part->position.size();
  std::vector<V3> du_sum(count), dv_sum(count);
  if (!part->texcoord.empty()) {
    for (size_t t = 0; t + 2 < part->indices.size(); t += 3) {
      const uint32_t i0 = part->indices[t], i1 = part->indices[t + 1], i2 = part->indices[t + 2];
      const V3 e1 = part->position[i1] - part->position[i0], e2 = part->position[i2] - part->position[i0];
      const double du1 = part->texcoord[i1][0] - part->texcoord[i0][0], dv1 = part->texcoord[i1][1] - part->texcoord[i0][1];
      const double du2 = part->texcoord[i2][0] - part->texcoord[i0][0], dv2 = part->texcoord[i2][1] - part->texcoord[i0][1];
      const double det = du1 * dv2 - du2 * dv1;
      if (std::fabs(det) < 1e-20) continue;
      const V3 dpdu = (e1 * dv2 - e2 * dv1) * (1.0 / det);
      const V3 dpdv = (e2 * du1 - e1 * du2) * (1.0 / det);
      for (uint32_t i : {i0, i1, i2}) {
        du_sum[i] = du_sum[i] + dpdu;
        dv_sum[i] = dv_sum[i] + dpdv;
      }
    }
  }
  part->tangent.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const V3 n = part->normal[i];
    const V3 t = normalize_or(du_sum[i] - n * dot(n, du_sum[i]), any_perpendicular(n));
    const double w = dot(cross(n, t), dv_sum[i]) > 0.0 ? -1.0 : 1.0;
    part->tangent[i] = {t.x, t.y, t.z, w};
  }
}

void transform(Part* part, const Mat4& m) {
  // Normals by the inverse transpose of the upper 3x3 (its cofactor matrix / det).
  const double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], k = m[10];
  const double det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
  const double cof[9] = {e * k - f * h, -(d * k - f * g), d * h - e * g,   //
                         -(b * k - c * h), a * k - c * g, -(a * h - b * g),  //
                         b * f - c * e, -(a * f - c * d), a * e - b * d};
  const double inv_det = det != 0.0 ? 1.0 / det : 0.0;
  auto apply = [&](V3 p, double w) {
    return V3{m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12] * w, m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13] * w,
              m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14] * w};
  };
  for (V3& p : part->position) p = apply(p, 1.0);
  for (V3& n : part->normal) {
    // row i of the inverse transpose = cofactor row i / det
    const V3 t{(cof[0] * n.x + cof[1] * n.y + cof[2] * n.z) * inv_det, (cof[3] * n.x + cof[4] * n.y + cof[5] * n.z) * inv_det,
               (cof[6] * n.x + cof[7] * n.y + cof[8] * n.z) * inv_det};
    n = normalize_or(t, V3{0, 0, 1});
  }
  for (auto& t : part->tangent) {
    const V3 v = normalize_or(apply(V3{t[0], t[1], t[2]}, 0.0), V3{1, 0, 0});
    t = {v.x, v.y, v.z, det < 0.0 ? -t[3] : t[3]};  // a mirror flips the handedness
  }
  if (det < 0.0)  // a mirror turns the winding around
    for (size_t i = 0; i + 2 < part->indices.size(); i += 3) std::swap(part->indices[i + 1], part->indices[i + 2]);
}

int attribute(const tinygltf::Primitive& primitive, const char* name) {
  auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? -1 : it->second;
}

// Image index of a texture, or -1.
int texture_image(const tinygltf::Model& model, int texture) {
  if (texture < 0 || static_cast<size_t>(texture) >= model.textures.size()) return -1;
  const int source = model.textures[static_cast<size_t>(texture)].source;
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) return -1;
  return source;
}

Image convert_image(const tinygltf::Image& image, const std::string& path, size_t index) {
  const std::string what = "image " + std::to_string(index) + (image.name.empty() ? "" : " '" + image.name + "'");
  if (image.width <= 0 || image.height <= 0 || image.component < 1 || image.component > 4 ||
      (image.bits != 8 && image.bits != 16))
    fail(path, what + " was not decoded to 8- or 16-bit pixels");
  const size_t values = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                        static_cast<size_t>(image.component);
  if (image.image.size() != values * static_cast<size_t>(image.bits / 8)) fail(path, what + " has the wrong size");
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.components = image.component;
  out.name = image.name;
  if (image.bits == 8) {
    out.pixels = image.image;
  } else {
    out.pixels.resize(values);
    for (size_t i = 0; i < values; ++i) {
      uint16_t v = 0;
      std::memcpy(&v, &image.image[2 * i], 2);
      out.pixels[i] = static_cast<uint8_t>(v >> 8);
    }
  }
  return out;
}

bool starts_with_gltf_magic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {0, 0, 0, 0};
  in.read(magic, 4);
  return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

class Flattener {
 public:
  Flattener(const tinygltf::Model& source, Model* out) : source_(source), out_(out) {}

  void node(int index, const Mat4& parent, int depth) {
    if (index < 0 || static_cast<size_t>(index) >= source_.nodes.size()) fail(out_->path, "a node index is out of range");
    if (depth > 64) fail(out_->path, "the node tree is deeper than 64 (a cycle?)");
    const tinygltf::Node& n = source_.nodes[static_cast<size_t>(index)];
    const Mat4 local = local_transform(n);
    if (!is_identity(local)) ++out_->transformed_nodes;
    const Mat4 world = multiply(parent, local);
    if (n.mesh >= 0) mesh(n.mesh, world);
    if (n.skin >= 0) ++skins_;
    for (int child : n.children) node(child, world, depth + 1);
  }

  void mesh(int index, const Mat4& world) {
    if (static_cast<size_t>(index) >= source_.meshes.size()) fail(out_->path, "a mesh index is out of range");
    const tinygltf::Mesh& m = source_.meshes[static_cast<size_t>(index)];
    for (const tinygltf::Primitive& p : m.primitives) {
      if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) {
        ++skipped_primitives_;
        continue;
      }
      if (!p.targets.empty()) ++morphs_;
      primitive(p, m.name, world);
    }
  }

  void finish() {
    if (skipped_primitives_ > 0)
      out_->warnings.push_back(std::to_string(skipped_primitives_) + " primitive(s) that are not triangle lists were skipped");
    if (skins_ > 0) out_->warnings.push_back("skins are ignored (the bind pose is drawn)");
    if (morphs_ > 0) out_->warnings.push_back("morph targets are ignored");
  }

 private:
  void primitive(const tinygltf::Primitive& p, const std::string& mesh_name, const Mat4& world) {
    const std::string& path = out_->path;
    const std::string name = "mesh '" + mesh_name + "' ";
    const std::vector<float> pos = read_accessor(source_, attribute(p, "POSITION"), 3, path, name + "POSITION");
    const size_t count = pos.size() / 3;
    Part part;
    part.position.resize(count);
    for (size_t i = 0; i < count; ++i) part.position[i] = {pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]};
    part.indices = read_indices(source_, p.indices, count, path);
    if (part.indices.size() % 3 != 0) fail(path, name + "has an index count that is not a multiple of 3");
    if (attribute(p, "TEXCOORD_0") >= 0) {
      const std::vector<float> uv = read_accessor(source_, attribute(p, "TEXCOORD_0"), 2, path, name + "TEXCOORD_0");
      if (uv.size() / 2 != count) fail(path, name + "TEXCOORD_0 and POSITION counts differ");
      part.texcoord.resize(count);
      for (size_t i = 0; i < count; ++i) part.texcoord[i] = {uv[2 * i], uv[2 * i + 1]};
    } else {
      out_->file_texcoords = false;
    }
    const bool has_normals = attribute(p, "NORMAL") >= 0;
    if (has_normals) {
      const std::vector<float> nrm = read_accessor(source_, attribute(p, "NORMAL"), 3, path, name + "NORMAL");
      if (nrm.size() / 3 != count) fail(path, name + "NORMAL and POSITION counts differ");
      part.normal.resize(count);
      for (size_t i = 0; i < count; ++i)
        part.normal[i] = normalize_or(V3{nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]}, V3{0, 0, 1});
    }
    const bool has_tangents = has_normals && attribute(p, "TANGENT") >= 0;  // tangents need the file's normals
    if (has_tangents) {
      const std::vector<float> tan = read_accessor(source_, attribute(p, "TANGENT"), 4, path, name + "TANGENT");
      if (tan.size() / 4 != count) fail(path, name + "TANGENT and POSITION counts differ");
      part.tangent.resize(count);
      for (size_t i = 0; i < count; ++i)
        part.tangent[i] = {tan[4 * i], tan[4 * i + 1], tan[4 * i + 2], tan[4 * i + 3] < 0.0f ? -1.0 : 1.0};
    }
    if (!has_normals) {
      out_->file_normals = false;
      make_flat(&part);
    }
    if (!has_tangents) out_->file_tangents = false;
    transform(&part, world);
    if (!has_tangents) make_tangents(&part);
    if (part.texcoord.empty()) part.texcoord.assign(part.position.size(), {0.0, 0.0});

    const size_t base = out_->vertex_count();
    if (base + part.position.size() > 0xFFFFFFFFu) fail(path, "more than 2^32 vertices");
    for (size_t i = 0; i < part.position.size(); ++i) {
      const double v[12] = {part.position[i].x, part.position[i].y, part.position[i].z, part.normal[i].x,
                            part.normal[i].y,   part.normal[i].z,   part.texcoord[i][0], part.texcoord[i][1],
                            part.tangent[i][0], part.tangent[i][1], part.tangent[i][2],  part.tangent[i][3]};
      for (double x : v) out_->vertices.push_back(static_cast<float>(x));
    }
    Primitive prim;
    prim.first_index = static_cast<uint32_t>(out_->indices.size());
    prim.index_count = static_cast<uint32_t>(part.indices.size());
    prim.material = p.material >= 0 && static_cast<size_t>(p.material) < source_.materials.size() ? p.material : -1;
    prim.mesh_name = mesh_name;
    for (uint32_t i : part.indices) out_->indices.push_back(static_cast<uint32_t>(base) + i);
    if (prim.index_count > 0) out_->primitives.push_back(prim);
  }

  const tinygltf::Model& source_;
  Model* out_;
  int skipped_primitives_ = 0, skins_ = 0, morphs_ = 0;
};

}  // namespace

Model load_gltf(const std::string& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model source;
  std::string error, warning;
  bool ok = false;
  if (starts_with_gltf_magic(path))
    ok = loader.LoadBinaryFromFile(&source, &error, &warning, path);
  else
    ok = loader.LoadASCIIFromFile(&source, &error, &warning, path);
  if (!ok) fail(path, "cannot be loaded (" + (error.empty() ? std::string("unknown error") : error) + ")");

  Model out;
  out.path = path;
  out.copyright = source.asset.copyright;
  out.generator = source.asset.generator;
  if (!warning.empty()) out.warnings.push_back(warning);

  for (size_t i = 0; i < source.images.size(); ++i) out.images.push_back(convert_image(source.images[i], path, i));
  for (const tinygltf::Material& m : source.materials) {
    Material material;
    material.name = m.name;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
    for (size_t c = 0; c < 4 && c < f.size(); ++c) material.base_color[c] = static_cast<float>(f[c]);
    material.base_color_image = texture_image(source, m.pbrMetallicRoughness.baseColorTexture.index);
    material.normal_image = texture_image(source, m.normalTexture.index);
    material.normal_scale = static_cast<float>(m.normalTexture.scale);
    material.roughness = static_cast<float>(m.pbrMetallicRoughness.roughnessFactor);
    material.double_sided = m.doubleSided;
    out.materials.push_back(material);
  }

  Flattener flattener(source, &out);
  if (!source.scenes.empty()) {
    const size_t scene = source.defaultScene >= 0 && static_cast<size_t>(source.defaultScene) < source.scenes.size()
                             ? static_cast<size_t>(source.defaultScene)
                             : 0;
    for (int root : source.scenes[scene].nodes) flattener.node(root, kIdentity, 0);
  } else {  // no scene: every mesh once, untransformed
    for (size_t m = 0; m < source.meshes.size(); ++m) flattener.mesh(static_cast<int>(m), kIdentity);
  }
  flattener.finish();
  if (out.indices.empty()) fail(path, "holds no triangles to draw");

  for (int k = 0; k < 3; ++k) {
    out.bounds_min[k] = out.vertices[static_cast<size_t>(k)];
    out.bounds_max[k] = out.vertices[static_cast<size_t>(k)];
  }
  for (size_t v = 0; v < out.vertex_count(); ++v)
    for (size_t k = 0; k < 3; ++k) {
      const float x = out.vertices[v * Model::kFloatsPerVertex + k];
      if (!std::isfinite(x)) fail(path, "a transformed position is not finite");
      out.bounds_min[k] = std::min(out.bounds_min[k], x);
      out.bounds_max[k] = std::max(out.bounds_max[k], x);
    }
  return out;
}

}  // namespace gltf_mesh
