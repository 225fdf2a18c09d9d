#include "cpu_separable_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "cpu_filter_passes.hpp"
#include "half_float.hpp"

namespace sss::math {

namespace {

using cpu_passes::in_colour_range;
using cpu_passes::Plane;
using cpu_passes::Rgba;

// The follow-surface blend of one tap towards the centre colour (GLSL mix()).
void follow_surface_blend(std::array<float, 3>* tap, const Rgba& centre, float d, bool gaussian_depth,
                          float inv_two_variance) {
  float s = gaussian_depth ? 1.0f - std::exp(-d * d * inv_two_variance) : d;
  if (!(s < 1.0f)) s = 1.0f;  // also catches NaN
  for (int c = 0; c < 3; ++c) (*tap)[static_cast<std::size_t>(c)] = (*tap)[static_cast<std::size_t>(c)] * (1.0f - s) + centre[static_cast<std::size_t>(c)] * s;
}

// Per-pixel profiles: each pixel's index (nullptr: none, every pixel the one kernel).
struct Indices {
  const std::uint16_t* ids = nullptr;
  int width = 0;
  std::uint16_t at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

// One pass at pixel (x, y) along axis `axis` (0: x, 1: y), with the look `k` (pixels per mm and the
// follow-surface numbers) and the frame's `shared` constants (depth linearisation, clamp). Returns
// false when the pixel is left as it is (not translucent or no usable depth).
bool filter_pixel(const PassTaps& pass, const PassKernel& kernel, float depth_variance_mm2, const PassConstants& k,
                  const PassConstants& shared, const Plane& source, const Plane& depth, const Indices& indices,
                  int axis, int x, int y, Rgba* result) {
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  const Rgba centre = source.rgba(x, y);
  if (!(centre[3] > 0.0f) || !in_colour_range(centre.data(), 4)) return false;
  const float strength = std::min(centre[3], 1.0f);
  const float centre_distance = linearise_depth(shared, depth.at(x, y, 0));
  const float w = clip_w(shared, centre_distance);
  if (!(w > 0.0f) || std::isinf(w)) return false;

  const float step = k.pixels_per_mm[static_cast<std::size_t>(axis)] * strength / w;
  const bool gaussian_depth = depth_variance_mm2 > 0.0f;
  const float follow_surface = (gaussian_depth ? k.mm_per_world : k.follow_surface_factor) / strength;
  const float inv_two_variance = gaussian_depth ? 0.5f / depth_variance_mm2 : 0.0f;
  Rgba sum = {0.0f, 0.0f, 0.0f, centre[3]};

  // Whole-pixel taps (footprint_kernel.hpp), read without filtering.
  const int jitter_from = kernel.jitter_from;
  const float noise = kernel.jittered() ? jitter_noise(x, y, axis) : 0.0f;
  const FootprintTaps taps = footprint_taps(pass.footprint, kernel.spacing, step, jitter_from, noise);
  for (std::size_t c = 0; c < 3; ++c) sum[c] = centre[c] * taps.weight[0][c];
  for (int i = 0; i < taps.count; ++i) {
    const float p = static_cast<float>(taps.position[static_cast<std::size_t>(i)]);
    std::array<float, 3> pair = {0.0f, 0.0f, 0.0f};
    for (int side = 0; side < 2; ++side) {
      float px = cx, py = cy;
      (axis == 0 ? px : py) += side == 0 ? p : -p;
      px = std::clamp(px, shared.clamp_min[0], shared.clamp_max[0]);
      py = std::clamp(py, shared.clamp_min[1], shared.clamp_max[1]);
      const int tx = static_cast<int>(px), ty = static_cast<int>(py);
      std::array<float, 3> tap = {source.at(tx, ty, 0), source.at(tx, ty, 1), source.at(tx, ty, 2)};
      if (!in_colour_range(tap.data(), 3)) tap = {centre[0], centre[1], centre[2]};
      if (k.follow_surface_factor > 0.0f) {
        const float d = follow_surface * std::fabs(centre_distance - linearise_depth(shared, depth.at(tx, ty, 0)));
        follow_surface_blend(&tap, centre, d, gaussian_depth, inv_two_variance);
      }
      if (indices.ids != nullptr && indices.at(tx, ty) != indices.at(x, y)) tap = {centre[0], centre[1], centre[2]};
      for (std::size_t c = 0; c < 3; ++c) pair[c] += tap[c];
    }
    for (std::size_t c = 0; c < 3; ++c) sum[c] += taps.weight[static_cast<std::size_t>(i + 1)][c] * pair[c];
  }
  *result = sum;
  return true;
}

}  // namespace

void cpu_pass_kernel_filter(const PassKernel& kernel, const PassConstants& constants, const CpuFilterImage& image,
                            float* out) {
  const int w = image.width, h = image.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const Plane color{w, h, 4, image.color};
  const Plane depth{w, h, 1, image.depth};
  std::copy(image.color, image.color + count * 4, out);
  std::vector<float> intermediate(count * 4);
  std::vector<float> accumulated(count * 3, 0.0f);  // the earlier terms' vertical sums
  const std::size_t terms = kernel.terms.size();
  for (std::size_t t = 0; t < terms; ++t) {
    const PassTerm& term = kernel.terms[t];
    const bool last = t + 1 == terms;
    // Horizontal pass into the intermediate: translucent pixels blurred, the rest copied.
    cpu_passes::horizontal_into_intermediate(
        image, constants, false,
        [&](int x, int y, Rgba* blurred) {
          return filter_pixel(term.horizontal, kernel, term.depth_variance_mm2, constants, constants, color, depth,
                              Indices{}, 0, x, y, blurred);
        },
        intermediate.data());
    // Vertical pass from the intermediate, plus the earlier terms: into the module's sum target,
    // or (the last term) into the output, where alpha keeps its input value.
    const Plane half_plane{w, h, 4, intermediate.data()};
    cpu_passes::vertical(
        image, constants,
        [&](int x, int y, Rgba* blurred) {
          return filter_pixel(term.vertical, kernel, term.depth_variance_mm2, constants, constants, half_plane, depth,
                              Indices{}, 1, x, y, blurred);
        },
        [&](std::size_t i, const Rgba& blurred) {
          for (int c = 0; c < 3; ++c) {
            const float v = blurred[static_cast<std::size_t>(c)] + accumulated[i * 3 + c];
            if (last) {
              out[i * 4 + c] = image.output_is_half ? round_to_half(v) : v;
            } else {
              accumulated[i * 3 + c] = image.accumulator_is_half ? round_to_half(v) : v;
            }
          }
        });
  }
}

void cpu_profile_filter(const std::vector<const PassKernel*>& kernels, const std::vector<PassConstants>& constants,
                        const std::uint16_t* ids, const CpuFilterImage& image, float* out, bool index_in_distance) {
  const int w = image.width, h = image.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const Plane color{w, h, 4, image.color};
  // With the index in the distance's low byte, the passes read distances without those 8 bits: the
  // model linearises first and reads the result as linear depth.
  PassConstants shared = constants.front();
  std::vector<float> distances;
  if (index_in_distance) {
    distances.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      std::uint32_t bits = 0;
      const float d = linearise_depth(shared, image.depth[i]);
      std::memcpy(&bits, &d, sizeof bits);
      bits &= 0xFFFFFF00u;
      std::memcpy(&distances[i], &bits, sizeof bits);
    }
    shared.linear_depth = true;
  }
  const Plane depth{w, h, 1, index_in_distance ? distances.data() : image.depth};
  const Indices indices{ids, w};
  std::copy(image.color, image.color + count * 4, out);
  std::vector<float> intermediate(count * 4);
  // The pixel's profile, or -1 where its index has none (the pixel is left alone).
  const auto profile_of = [&](int x, int y) {
    const auto p = static_cast<std::size_t>(indices.at(x, y) & kProfileIndexMask);
    return p < kernels.size() ? static_cast<int>(p) : -1;
  };
  const auto pass = [&](int axis, const Plane& source, int x, int y, Rgba* blurred) {
    const int p = profile_of(x, y);
    if (p < 0) return false;
    const PassKernel& kernel = *kernels[static_cast<std::size_t>(p)];
    const PassTerm& term = kernel.terms.front();
    return filter_pixel(axis == 0 ? term.horizontal : term.vertical, kernel, term.depth_variance_mm2,
                        constants[static_cast<std::size_t>(p)], shared, source, depth, indices, axis, x, y, blurred);
  };
  cpu_passes::horizontal_into_intermediate(
      image, constants.front(), false, [&](int x, int y, Rgba* blurred) { return pass(0, color, x, y, blurred); },
      intermediate.data());
  const Plane half_plane{w, h, 4, intermediate.data()};
  cpu_passes::vertical(
      image, constants.front(), [&](int x, int y, Rgba* blurred) { return pass(1, half_plane, x, y, blurred); },
      [&](std::size_t i, const Rgba& blurred) {
        for (std::size_t c = 0; c < 3; ++c) out[i * 4 + c] = image.output_is_half ? round_to_half(blurred[c]) : blurred[c];
      });
}

}  // namespace sss::math
