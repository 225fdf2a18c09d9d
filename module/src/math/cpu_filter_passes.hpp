// What the CPU models of the two passes (cpu_separable_filter.cpp, cpu_cbf_filter.cpp) share: the
// clamped texel reads, the viewport's clamp rectangle, and the walk over the pixels a pass blurs
// (inside the rectangle and the mask). Math layer: no GL; not shipped (sss_math only).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "cpu_separable_filter.hpp"
#include "filter_constants.hpp"
#include "half_float.hpp"

namespace sss::math::cpu_passes {

using Rgba = std::array<float, 4>;

// A texture as the shader reads it with clamp-to-edge: `channels` floats a texel, row 0 first.
struct Plane {
  int width, height, channels;
  const float* data;
  float at(int x, int y, int c) const {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return data[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
  Rgba rgba(int x, int y) const { return {at(x, y, 0), at(x, y, 1), at(x, y, 2), at(x, y, 3)}; }
};

// The colours the passes blur: finite and within +-2^125, the shaders' bound
// (module/shaders/colour_range.glsl: past it the float arithmetic could overflow). A colour outside
// keeps its value, and as a tap counts as the centre's colour.
constexpr float kColourLimit = 0x1p125f;
// What the fragment passes' inputs hold for a colour past the limit (colour_range.glsl's
// kSssUnusableColour): finite and past the limit.
constexpr float kUnusableColour = -0x1p126f;

inline bool in_colour_range(const float* v, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(v[i]) || std::fabs(v[i]) > kColourLimit) return false;
  }
  return true;
}

// The pixel's centre lies in the clamp rectangle (the viewport, or the region).
inline bool inside(const PassConstants& k, int x, int y) {
  const float px = static_cast<float>(x) + 0.5f, py = static_cast<float>(y) + 0.5f;
  return px >= k.clamp_min[0] && px <= k.clamp_max[0] && py >= k.clamp_min[1] && py <= k.clamp_max[1];
}

inline bool masked_in(const CpuFilterImage& image, std::size_t i) { return image.mask == nullptr || image.mask[i] != 0; }

// The horizontal pass into the intermediate (`intermediate`: width·height·4 floats, rounded to half
// float unless image.intermediate_is_half is false): each
// pixel inside the rectangle and the mask blurred by `pixel(x, y, &rgba)` where it returns true,
// the rest copied (with alpha 0 where the mask leaves them out and `clear_masked_alpha`).
template <typename Pixel>
void horizontal_into_intermediate(const CpuFilterImage& image, const PassConstants& k, bool clear_masked_alpha,
                          const Pixel& pixel, float* intermediate) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      Rgba value = {image.color[i * 4], image.color[i * 4 + 1], image.color[i * 4 + 2], image.color[i * 4 + 3]};
      const bool in = masked_in(image, i);
      if (!in && clear_masked_alpha) value[3] = 0.0f;
      if (inside(k, x, y) && in) {
        Rgba blurred;
        if (pixel(x, y, &blurred)) value = blurred;
      }
      for (int c = 0; c < 4; ++c) {
        const float v = value[static_cast<std::size_t>(c)];
        intermediate[i * 4 + c] = image.intermediate_is_half ? round_to_half(v) : v;
      }
    }
  }
}

// The vertical pass: `store(i, rgba)` for each pixel i inside the rectangle and the mask that
// `pixel(x, y, &rgba)` blurs (returns true for).
template <typename Pixel, typename Store>
void vertical(const CpuFilterImage& image, const PassConstants& k, const Pixel& pixel, const Store& store) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (!inside(k, x, y) || !masked_in(image, i)) continue;
      Rgba blurred;
      if (pixel(x, y, &blurred)) store(i, blurred);
    }
  }
}

}  // namespace sss::math::cpu_passes
