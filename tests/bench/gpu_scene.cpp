#include "gpu_scene.hpp"

#include <algorithm>
#include <limits>

#include "host_gl_util.hpp"
#include "math/half_float.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

GLuint upload(GLint internal_format, int width, int height, GLenum format, GLenum type, const void* data) {
  const GLuint texture = make_texture(internal_format, width, height, format, type);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format, type, data);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

}  // namespace

GpuScene upload_scene(const Scene& scene) {
  GpuScene g;
  g.width = scene.width;
  g.height = scene.height;
  g.projection = scene.projection;
  g.world_units_per_mm = scene.world_units_per_mm;
  g.nearest_translucent_distance = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < scene.mask.size(); ++i) {
    if (scene.mask[i] != 0) g.nearest_translucent_distance = std::min(g.nearest_translucent_distance, scene.distance[i]);
  }
  g.irradiance_half.resize(scene.irradiance.size());
  for (std::size_t i = 0; i < scene.irradiance.size(); ++i) {
    g.irradiance_half[i] = sss::math::round_to_half(scene.irradiance[i]);
  }
  g.irradiance = upload(GL_RGBA16F, g.width, g.height, GL_RGBA, GL_FLOAT, g.irradiance_half.data());
  g.depth = upload(GL_DEPTH_COMPONENT32F, g.width, g.height, GL_DEPTH_COMPONENT, GL_FLOAT, scene.window_depth.data());
  g.distance = upload(GL_R32F, g.width, g.height, GL_RED, GL_FLOAT, scene.distance.data());
  std::vector<uint8_t> profile = scene.profile;
  if (profile.empty()) {
    profile.resize(scene.mask.size());
    for (std::size_t i = 0; i < profile.size(); ++i) profile[i] = scene.mask[i] != 0 ? 1u << 4 : 0u;
  }
  g.profile = upload(GL_R8UI, g.width, g.height, GL_RED_INTEGER, GL_UNSIGNED_BYTE, profile.data());
  g.profile_materials = scene.profile_materials.empty() ? std::vector<int>{0} : scene.profile_materials;
  return g;
}

void destroy_scene(GpuScene* scene) {
  const GLuint textures[4] = {scene->irradiance, scene->depth, scene->distance, scene->profile};
  glDeleteTextures(4, textures);
  *scene = GpuScene{};
}

GLuint make_output_texture(int width, int height) { return make_texture(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT); }

std::vector<float> read_texture_rgba(GLuint texture, int width, int height) {
  std::vector<float> out(static_cast<std::size_t>(width) * height * 4);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return out;
}

}  // namespace sss_bench
