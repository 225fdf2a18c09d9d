#include "cpu_cbf_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cpu_filter_passes.hpp"
#include "half_float.hpp"
#include "pass_surface.hpp"

namespace sss::math {

namespace {

using cpu_passes::Plane;
using cpu_passes::Rgba;

bool finite4(const Rgba& v) { return cpu_passes::in_colour_range(v.data(), 4); }

// The tangent along `axis` at a centre at distance d0 whose surface has view-space normal `n`: the
// central difference of the steps of one window pixel either way along the axis to the plane
// through the centre with that normal (pass_surface.hpp's ΔP with the depth change that keeps the
// step on the plane), as the tangent from depth takes it on a plane. A facing plane's where a step
// is not finite (a zero normal, a plane seen edge-on).
Float3 tangent_from_normal(const PassConstants& k, const std::array<float, 2>& g, int axis, float d0, const float* n) {
  const std::size_t a = axis == 0 ? 0 : 1;
  const float w0 = clip_w(k, d0);
  const float span = k.pixel_span[a];
  const float n_along = n[a] * span;
  const float n_ray = n[0] * g[0] + n[1] * g[1] - n[2];
  float plus = -w0 * n_along / (n_ray - k.depth_terms[1] * n_along);   // the depth change one pixel on
  float minus = w0 * n_along / (n_ray + k.depth_terms[1] * n_along);   // and one pixel back
  if (!(std::fabs(plus) < 1e30f && std::fabs(minus) < 1e30f)) plus = minus = 0.0f;  // also NaN
  // ½ (T+ - T-) with T± = (±span · w(d0 + Δ±) + Δ± g, -Δ±): pass_surface.cpp's blend at a = ½.
  const float depth = 0.5f * plus - 0.5f * minus;
  const float w = w0 - k.depth_terms[1] * (0.5f * plus + 0.5f * minus);
  Float3 t = {depth * g[0], depth * g[1], -depth};
  (axis == 0 ? t.x : t.y) += span * w;
  return t;
}

struct Pass {
  const CbfKernel& kernel;
  const PassConstants& k;
  const Plane& source;
  const std::vector<float>& distance;  // the view distance per pixel (linearised depth)
  int width;
  const uint8_t* mask;
  int axis;
  const float* normals;

  float distance_at(int x, int y) const { return distance[static_cast<std::size_t>(y) * width + x]; }

  // A neighbour on `axis` for the tangent from depth (pass_surface.hpp's rule; the separable passes'
  // neighbour_at without indices).
  Neighbour neighbour(int x, int y) const {
    Neighbour n;
    if (!cpu_passes::inside(k, x, y)) return n;
    n.distance = distance_at(x, y);
    const float w = clip_w(k, n.distance);
    n.usable = w > 0.0f && w < 1e30f;
    return n;
  }

  Float3 tangent(int t_axis, int x, int y, float d0, const std::array<float, 2>& g) const {
    if (normals != nullptr) {
      return tangent_from_normal(k, g, t_axis, d0, normals + (static_cast<std::size_t>(y) * width + x) * 4);
    }
    const int ox = t_axis == 0 ? 1 : 0, oy = t_axis == 0 ? 0 : 1;
    return surface_tangent(k, g, t_axis, d0, neighbour(x - ox, y - oy), neighbour(x + ox, y + oy));
  }

  PassGeometry walk(int x, int y, float d0) const {
    const std::array<float, 2> g = ray_slope(k, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const Float3 tx = tangent(0, x, y, d0, g);
    if (axis == 0) return horizontal_geometry(k, g, d0, tx);
    return vertical_geometry(k, g, d0, tx, tangent(1, x, y, d0, g));
  }

  // One tap `offset` steps along the line: its weight per channel (0 where it is not translucent,
  // not usable or outside the mask; else the cell's mass times the range Gaussian of its distance
  // off the centre's surface) added to `weight_sum`, its colour times that to `sum`.
  void add_tap(int x, int y, float offset, const std::array<float, 3>& cell, const PassGeometry& walk, float d0,
               float mm_per_world, std::array<float, 3>* sum, std::array<float, 3>* weight_sum) const {
    const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
    float px = cx, py = cy;
    if (axis == 0) {
      px += offset;
    } else {
      py += offset;
      px += walk.shear * offset;
    }
    px = std::clamp(px, k.clamp_min[0], k.clamp_max[0]);
    py = std::clamp(py, k.clamp_min[1], k.clamp_max[1]);
    const int tx = static_cast<int>(px), ty = static_cast<int>(py);
    if (mask != nullptr && mask[static_cast<std::size_t>(ty) * width + tx] == 0) return;
    const Rgba tap = source.rgba(tx, ty);
    if (!(tap[3] > 0.0f) || !finite4(tap)) return;
    const float ox = static_cast<float>(tx) + 0.5f - cx, oy = static_cast<float>(ty) + 0.5f - cy;
    const float h = off_surface_distance(k, walk, mm_per_world, offset, ox, oy, distance_at(tx, ty), d0, false);
    if (!std::isfinite(h)) return;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const float w = cell[ch] * std::exp(-h * h * kernel.inv_two_variance[ch]);
      (*sum)[ch] += w * tap[ch];
      (*weight_sum)[ch] += w;
    }
  }

  bool pixel(int x, int y, Rgba* result) const {
    const Rgba centre = source.rgba(x, y);
    if (!(centre[3] > 0.0f) || !finite4(centre)) return false;
    const float strength = std::min(centre[3], 1.0f);
    const float d0 = distance_at(x, y);
    const float w0 = clip_w(k, d0);
    if (!(w0 > 0.0f) || std::isinf(w0)) return false;
    const PassGeometry g = walk(x, y, d0);
    const float step = k.pixels_per_mm[static_cast<std::size_t>(axis)] * strength / w0 * g.ratio;
    const float mm_per_world = k.mm_per_world / strength;
    const FootprintTaps taps = footprint_taps(kernel.table, kernel.spacing, step);
    std::array<float, 3> sum{}, weight_sum{};
    for (std::size_t ch = 0; ch < 3; ++ch) {
      weight_sum[ch] = taps.weight[0][ch];
      sum[ch] = centre[ch] * weight_sum[ch];
    }
    for (int i = 0; i < taps.count; ++i) {
      const float p = static_cast<float>(taps.position[static_cast<std::size_t>(i)]);
      const std::array<float, 3>& cell = taps.weight[static_cast<std::size_t>(i + 1)];
      add_tap(x, y, p, cell, g, d0, mm_per_world, &sum, &weight_sum);
      add_tap(x, y, -p, cell, g, d0, mm_per_world, &sum, &weight_sum);
    }
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const float b = kernel.spike_blend[ch];
      (*result)[ch] = b * centre[ch] + (1.0f - b) * (sum[ch] / weight_sum[ch]);
    }
    (*result)[3] = centre[3];
    return true;
  }
};

}  // namespace

void cpu_cbf_filter(const CbfKernel& kernel, const PassConstants& constants, const CpuFilterImage& image, float* out,
                    const float* normals) {
  const int w = image.width, h = image.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const Plane color{w, h, 4, image.color};
  std::vector<float> distance(count);
  for (std::size_t i = 0; i < count; ++i) distance[i] = linearise_depth(constants, image.depth[i]);

  // Horizontal pass into the intermediate; pixels the mask excludes get alpha 0 there, so
  // the vertical pass gives them no weight either.
  std::vector<float> intermediate(count * 4);
  const Pass horizontal{kernel, constants, color, distance, w, image.mask, 0, normals};
  cpu_passes::horizontal_into_intermediate(
      image, constants, true, [&](int x, int y, Rgba* blurred) { return horizontal.pixel(x, y, blurred); },
      intermediate.data());

  const Plane half_plane{w, h, 4, intermediate.data()};
  const Pass vertical{kernel, constants, half_plane, distance, w, image.mask, 1, normals};
  std::copy(image.color, image.color + count * 4, out);
  cpu_passes::vertical(
      image, constants, [&](int x, int y, Rgba* blurred) { return vertical.pixel(x, y, blurred); },
      [&](std::size_t i, const Rgba& blurred) {
        for (int c = 0; c < 3; ++c) {
          const float v = blurred[static_cast<std::size_t>(c)];
          out[i * 4 + c] = image.output_is_half ? round_to_half(v) : v;
        }
      });
}

}  // namespace sss::math
