// A canonical scene uploaded as a host renderer would hold it: RGBA16F irradiance (alpha =
// strength), hardware depth, and, for the baselines that want it, the linear view distance.
#pragma once

#include <array>
#include <vector>

#include "host_gl.hpp"
#include "scenes/scene.hpp"

namespace sss_bench {

struct GpuScene {
  int width = 0, height = 0;
  GLuint irradiance = 0;  // GL_RGBA16F
  GLuint depth = 0;       // GL_DEPTH_COMPONENT32F, hardware depth for `projection`
  GLuint distance = 0;    // GL_R32F, view distance
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
