#include "cpu_cbf_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cpu_filter_passes.hpp"
#include "half_float.hpp"

namespace sss::math {

namespace {

using cpu_passes::Plane;
using cpu_passes::Rgba;

bool finite4(const Rgba& v) { return cpu_passes::in_colour_range(v.data(), 4); }

struct ViewPoint {
  float x, y, z;
};

// The view-space point under pixel position (px, py) at view distance d (as the shader does it).
ViewPoint view_point(const PassConstants& k, const CbfConstants& c, float px, float py, float d) {
  const float nx = (px - c.viewport[0]) / c.viewport[2] * 2.0f - 1.0f;
  const float ny = (py - c.viewport[1]) / c.viewport[3] * 2.0f - 1.0f;
  const float w = clip_w(k, d);
  const float z = -d;
  return {(nx * w - c.xy_terms[2] * z - c.xy_offset[0]) / c.xy_terms[0],
          (ny * w - c.xy_terms[3] * z - c.xy_offset[1]) / c.xy_terms[1], z};
}

struct Pass {
  const CbfKernel& kernel;
  const PassConstants& k;
  const CbfConstants& c;
  const Plane& source;
  const Plane& depth;
  const uint8_t* mask;
  int axis;
  const float* normals;

  int clamp_axis(int v, int a) const {
    const int lo = static_cast<int>(std::floor(a == 0 ? k.clamp_min[0] : k.clamp_min[1]));
    const int hi = static_cast<int>(std::floor(a == 0 ? k.clamp_max[0] : k.clamp_max[1]));
    return std::clamp(v, lo, hi);
  }

  // The in-plane tangent from the neighbour (one texel along the axis) whose depth is closer (one
  // side of a depth step is the other surface).
  void tangent(int x, int y, float d0, const ViewPoint& p0, float* ta, float* tz) const {
    const int ax = axis == 0 ? 1 : 0, ay = axis == 0 ? 0 : 1;
    const int xp = clamp_axis(x + ax, 0), yp = clamp_axis(y + ay, 1);
    const int xm = clamp_axis(x - ax, 0), ym = clamp_axis(y - ay, 1);
    const float dp = linearise_depth(k, depth.at(xp, yp, 0));
    const float dm = linearise_depth(k, depth.at(xm, ym, 0));
    // At the viewport's edge the clamped neighbour on one side is the pixel itself: take the other.
    const bool plus_is_self = xp == x && yp == y, minus_is_self = xm == x && ym == y;
    const bool plus = minus_is_self || (!plus_is_self && !(std::fabs(dm - d0) < std::fabs(dp - d0)));
    const int xn = plus ? xp : xm, yn = plus ? yp : ym;
    const ViewPoint pn = view_point(k, c, static_cast<float>(xn) + 0.5f, static_cast<float>(yn) + 0.5f, plus ? dp : dm);
    *ta = axis == 0 ? pn.x - p0.x : pn.y - p0.y;
    *tz = pn.z - p0.z;
  }

  bool pixel(int x, int y, Rgba* result) const {
    const Rgba centre = source.rgba(x, y);
    if (!(centre[3] > 0.0f) || !finite4(centre)) return false;
    const float strength = std::min(centre[3], 1.0f);
    const float d0 = linearise_depth(k, depth.at(x, y, 0));
    const float w0 = clip_w(k, d0);
    if (!(w0 > 0.0f) || std::isinf(w0)) return false;
    const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
    const ViewPoint p0 = view_point(k, c, cx, cy, d0);

    float ta = 0.0f, tz = 0.0f;
    if (normals != nullptr) {
      // The in-plane tangent is the normal's in-plane projection turned by 90°.
      const float* n = normals + (static_cast<std::size_t>(y) * source.width + x) * 4;
      ta = n[2];
      tz = -(axis == 0 ? n[0] : n[1]);
    } else {
      tangent(x, y, d0, p0, &ta, &tz);
    }
    const float ea = c.orthographic ? 0.0f : -(axis == 0 ? p0.x : p0.y);
    const float ez = c.orthographic ? 1.0f : -p0.z;
    const float cosine = footprint_cosine(ta, tz, ea, ez);
    const float sine2 = 1.0f - cosine * cosine;

    const float step = k.pixels_per_mm[static_cast<std::size_t>(axis)] * strength / w0 * cosine;
    const float mm_per_world = 1.0f / (c.world_per_mm * strength);
    std::array<float, 3> sum, weight_sum;
    for (int ch = 0; ch < 3; ++ch) {
      weight_sum[ch] = kernel.taps[0].weight[ch];
      sum[ch] = centre[ch] * weight_sum[ch];
    }
    for (std::size_t i = 1; i < kernel.taps.size(); ++i) {
      const float offset = kernel.taps[i].offset_mm;
      float px = cx, py = cy;
      (axis == 0 ? px : py) += offset * step;
      px = std::clamp(px, k.clamp_min[0], k.clamp_max[0]);
      py = std::clamp(py, k.clamp_min[1], k.clamp_max[1]);
      const int tx = static_cast<int>(std::floor(px)), ty = static_cast<int>(std::floor(py));
      if (mask != nullptr && mask[static_cast<std::size_t>(ty) * source.width + tx] == 0) continue;
      const Rgba tap = source.rgba(tx, ty);
      if (!(tap[3] > 0.0f) || !finite4(tap)) continue;
      const float dz = (linearise_depth(k, depth.at(tx, ty, 0)) - d0) * mm_per_world;
      if (!std::isfinite(dz)) continue;
      const float spread = offset * offset * sine2 - dz * dz;
      for (int ch = 0; ch < 3; ++ch) {
        const float w = kernel.taps[i].weight[ch] * std::exp(std::min(spread * kernel.inv_two_variance[ch], 0.0f));
        sum[ch] += w * tap[ch];
        weight_sum[ch] += w;
      }
    }
    for (int ch = 0; ch < 3; ++ch) {
      const float b = kernel.spike_blend[ch];
      (*result)[ch] = b * centre[ch] + (1.0f - b) * (sum[ch] / weight_sum[ch]);
    }
    (*result)[3] = centre[3];
    return true;
  }
};

}  // namespace

void cpu_cbf_filter(const CbfKernel& kernel, const PassConstants& constants, const CbfConstants& cbf,
                    const CpuFilterImage& image, float* out, const float* normals) {
  const int w = image.width, h = image.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const Plane color{w, h, 4, image.color};
  const Plane depth{w, h, 1, image.depth};

  // Horizontal pass into the intermediate; pixels the mask excludes get alpha 0 there, so
  // the vertical pass gives them no weight either.
  std::vector<float> intermediate(count * 4);
  const Pass horizontal{kernel, constants, cbf, color, depth, image.mask, 0, normals};
  cpu_passes::horizontal_into_intermediate(
      image, constants, true, [&](int x, int y, Rgba* blurred) { return horizontal.pixel(x, y, blurred); },
      intermediate.data());

  const Plane half_plane{w, h, 4, intermediate.data()};
  const Pass vertical{kernel, constants, cbf, half_plane, depth, image.mask, 1, normals};
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
