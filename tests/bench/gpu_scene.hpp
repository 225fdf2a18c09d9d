// A canonical scene uploaded as a host renderer would hold it: RGBA16F irradiance (alpha =
// strength), hardware depth, and, for the baselines that want it, the linear view distance.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "host_gl.hpp"
#include "scenes/scene.hpp"

namespace sss_bench {

struct GpuScene {
  int width = 0, height = 0;
  GLuint irradiance = 0;  // GL_RGBA16F
  GLuint depth = 0;       // GL_DEPTH_COMPONENT32F, hardware depth for `projection`
  GLuint distance = 0;    // GL_R32F, view distance
  // GL_R8UI, profile | object << 4 per pixel as a host's G-buffer holds it (sss_frame.profile_texture):
  // the scene's own (Scene::profile), or, for a scene of one material, profile 0 of object 1 on every
  // translucent pixel and 0 elsewhere. profile_materials: the sss_profile of each profile index (the
  // scene's; {SSS_PROFILE_SKIN_DEON} for one material).
  GLuint profile = 0;
  std::vector<int> profile_materials;
  std::array<float, 16> projection{};
  float world_units_per_mm = 0.001f;
  float nearest_translucent_distance = 0.0f;  // smallest view distance of a translucent pixel
  // The irradiance exactly as the GPU holds it (rounded to half), so the CPU references and the
  // GPU methods start from the same numbers.
  std::vector<float> irradiance_half;
};

GpuScene upload_scene(const Scene& scene);
void destroy_scene(GpuScene* scene);

// A GL_RGBA32F texture of the scene's size for a method's output (exact read-back).
GLuint make_output_texture(int width, int height);
// Every texel of a colour texture as RGBA floats.
std::vector<float> read_texture_rgba(GLuint texture, int width, int height);

}  // namespace sss_bench
