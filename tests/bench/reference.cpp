#include "reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "math/exact_reference.hpp"
#include "calibration.hpp"
#include "method.hpp"
#include "material_terms.hpp"

namespace sss_bench {

namespace {

sss::math::ExactInput exact_input(const Scene& scene, const GpuScene& gpu) {
  sss::math::ExactInput in;
  in.width = scene.width;
  in.height = scene.height;
  in.irradiance = gpu.irradiance_half.data();
  in.distance = scene.distance.data();
  in.mask = scene.mask.data();
  in.projection = scene.projection;
  in.world_units_per_mm = scene.world_units_per_mm;
  return in;
}

// Several materials (Scene::profile): each profile/object pair's pixels convolved with its own
// profile over its own pixels only (no light crosses between materials or objects), CPU, every pixel.
Reference per_material_reference(const Scene& scene, const GpuScene& gpu) {
  const int w = scene.width, h = scene.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  Reference r;
  r.rgba = gpu.irradiance_half;
  std::vector<uint8_t> values(scene.profile.begin(), scene.profile.end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<double> rgb(n * 3);
  for (uint8_t value : values) {
    if (value == 0) continue;  // the background
    std::vector<uint8_t> mask(n);
    for (std::size_t i = 0; i < n; ++i) mask[i] = scene.mask[i] != 0 && scene.profile[i] == value ? 1 : 0;
    sss::math::ExactInput in = exact_input(scene, gpu);
    in.mask = mask.data();
    const std::size_t profile = value & 15u;
    if (profile >= scene.profile_materials.size()) throw std::runtime_error("reference: a pixel's profile has no material");
    sss::math::ExactSurfaceConvolution(in, material_profile_terms(scene.profile_materials[profile])).convolve({0, 0, w, h}, rgb.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (mask[i] == 0) continue;
      for (std::size_t c = 0; c < 3; ++c) r.rgba[i * 4 + c] = static_cast<float>(rgb[i * 3 + c]);
    }
  }
  r.source = "CPU exact per material (double)";
  return r;
}

}  // namespace

Reference make_plane_reference(const Scene& scene, const GpuScene& gpu) {
  if (!(scene.footprint_mm > 0.0)) throw std::invalid_argument("make_plane_reference: " + scene.name + " is not a sweep plane");
  const std::size_t n = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  const std::vector<double> rgb = exact_plane_rgb(scene, gpu.irradiance_half.data());
  Reference r;
  r.rgba = gpu.irradiance_half;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c) r.rgba[i * 4 + c] = static_cast<float>(rgb[i * 3 + c]);
  }
  r.source = "plane exact (double, separable)";
  return r;
}

std::vector<float> make_patch_reference(const Scene& scene, const GpuScene& gpu, int x, int y, int width, int height) {
  if (!scene.profile.empty()) throw std::invalid_argument("make_patch_reference: " + scene.name + " has several materials");
  const sss::math::ExactSurfaceConvolution cpu(exact_input(scene, gpu), sss::math::skin_profile_terms());
  const std::size_t n = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  std::vector<double> rgb(n * 3, 0.0);
  cpu.convolve({x, y, width, height}, rgb.data());
  std::vector<float> rgba = gpu.irradiance_half;
  for (int py = y; py < y + height; ++py) {
    for (int px = x; px < x + width; ++px) {
      const std::size_t i = static_cast<std::size_t>(py) * static_cast<std::size_t>(scene.width) + static_cast<std::size_t>(px);
      for (std::size_t c = 0; c < 3; ++c) rgba[i * 4 + c] = static_cast<float>(rgb[i * 3 + c]);
    }
  }
  return rgba;
}

bool on_grid(int x, int y, int stride) { return x % stride == stride / 2 && y % stride == stride / 2; }

Reference make_reference(const Scene& scene, const GpuScene& gpu, long max_cpu_pixels, int spot_checks, int stride) {
  Reference r;
  const int w = scene.width, h = scene.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  if (!scene.profile.empty()) return per_material_reference(scene, gpu);
  const sss::math::ExactSurfaceConvolution cpu(exact_input(scene, gpu), sss::math::skin_profile_terms());
  r.rgba = gpu.irradiance_half;
  if (static_cast<long>(n) <= max_cpu_pixels) {
    std::vector<double> rgb(n * 3);
    cpu.convolve({0, 0, w, h}, rgb.data());
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t c = 0; c < 3; ++c) r.rgba[i * 4 + c] = static_cast<float>(rgb[i * 3 + c]);
    }
    r.source = "CPU exact (double)";
    return r;
  }
  auto exact = make_exact_method(stride);
  const GLuint output = make_output_texture(w, h);
  std::string error;
  host_gl::glFinish();
  const auto start = std::chrono::steady_clock::now();
  if (!exact->run(gpu, output, &error)) throw std::runtime_error("GL exact reference: " + error);
  host_gl::glFinish();
  r.gl_time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r.rgba = read_texture_rgba(output, w, h);
  host_gl::glDeleteTextures(1, &output);
  r.source = "GL exact (fp32)";
  r.stride = stride;

  // Spot checks at translucent receivers of the grid, spread evenly through the image.
  std::vector<std::size_t> translucent;
  for (std::size_t i = 0; i < n; ++i) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(w)), y = static_cast<int>(i / static_cast<std::size_t>(w));
    if (scene.mask[i] != 0 && on_grid(x, y, stride)) translucent.push_back(i);
  }
  r.check.scene = scene.name;
  r.check.width = w;
  r.check.height = h;
  const std::size_t count = std::min<std::size_t>(translucent.size(), static_cast<std::size_t>(std::max(spot_checks, 0)));
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = translucent[(k * translucent.size()) / count + translucent.size() / (2 * count)];
    const auto expected = cpu.at(static_cast<int>(i % static_cast<std::size_t>(w)), static_cast<int>(i / static_cast<std::size_t>(w)));
    for (std::size_t c = 0; c < 3; ++c) {
      // Relative to the value, with a floor that keeps dark pixels from dominating.
      const double d = std::fabs(r.rgba[i * 4 + c] - expected[c]) / std::max(std::fabs(expected[c]), 1e-3);
      r.check.max_relative_difference = std::max(r.check.max_relative_difference, d);
    }
    ++r.check.checked;
  }
  return r;
}

Reference make_mass_reference(const Scene& scene, long max_cpu_pixels, int stride) {
  if (!scene.profile.empty()) throw std::invalid_argument("make_mass_reference: " + scene.name + " has several materials");
  Scene uniform = scene;
  for (std::size_t i = 0; i < uniform.mask.size(); ++i) {
    if (uniform.mask[i] == 0) continue;
    for (std::size_t c = 0; c < 3; ++c) uniform.irradiance[i * 4 + c] = 1.0f;
  }
  GpuScene gpu = upload_scene(uniform);
  try {
    Reference mass = make_reference(uniform, gpu, max_cpu_pixels, 0, stride);
    destroy_scene(&gpu);
    return mass;
  } catch (...) {
    destroy_scene(&gpu);
    throw;
  }
}

std::vector<float> divide_by_mass(const Reference& reference, const Reference& mass, const Scene& scene) {
  std::vector<float> out = reference.rgba;
  const auto w = static_cast<std::size_t>(scene.width);
  for (std::size_t i = 0; i < scene.mask.size(); ++i) {
    // Off the receivers' grid both hold the input; a receiver that is not usable holds it in both.
    if (scene.mask[i] == 0 || !on_grid(static_cast<int>(i % w), static_cast<int>(i / w), reference.stride)) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const float m = mass.rgba[i * 4 + c];
      if (m > 0.0f) out[i * 4 + c] = static_cast<float>(static_cast<double>(reference.rgba[i * 4 + c]) / m);
    }
  }
  return out;
}

}  // namespace sss_bench
