#include "plane_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "surface.hpp"

namespace sss::math {

namespace {

// ½ [erf(b) - erf(a)] for a <= b, through erfc on the side of 0 where both lie so that a far tail
// is not the difference of two numbers near 1.
double half_erf_difference(double a, double b) {
  if (a >= 0.0) return 0.5 * (std::erfc(a) - std::erfc(b));
  if (b <= 0.0) return 0.5 * (std::erfc(-b) - std::erfc(-a));
  return 0.5 * (std::erf(b) - std::erf(a));
}

// Taps lighter than this are skipped: the kernel is symmetric and decreasing away from its centre,
// so the skipped ones (at most a few thousand per pass) hold less than 1e-14 of the light together,
// below what the double sums round away (the comparison with the 2D reference in
// plane_reference_test.cpp reads the same 2.3e-13 and 3.1e-15 with or without them).
constexpr double kNegligibleWeight = 1e-18;

// The half-width beyond which every value of k (centred, 2·radius + 1 values) is negligible.
int significant_radius(const std::vector<double>& k) {
  const int radius = static_cast<int>(k.size() / 2);
  int r = radius;
  while (r > 0 && k[static_cast<std::size_t>(radius + r)] < kNegligibleWeight &&
         k[static_cast<std::size_t>(radius - r)] < kNegligibleWeight) {
    --r;
  }
  return r;
}

// One axis of one term on a width x height plane (row-major): out = k * in along x (axis 0) or y
// (axis 1). Written as one scaled row or run added per tap offset, so every inner loop walks memory
// in order and vectorises; k is centred with at least (the axis length - 1) values on each side.
void convolve_axis(const std::vector<double>& k, int axis, int width, int height, const std::vector<double>& in,
                   std::vector<double>* out) {
  const int centre = static_cast<int>(k.size() / 2);
  const int count = axis == 0 ? width : height;
  const int reach = std::min(significant_radius(k), count - 1);
  std::fill(out->begin(), out->end(), 0.0);
  const auto w = static_cast<std::size_t>(width);
  for (int d = -reach; d <= reach; ++d) {
    const double weight = k[static_cast<std::size_t>(centre + d)];
    if (weight < kNegligibleWeight) continue;
    // Receivers i with a source i + d inside [0, count).
    const int i0 = std::max(0, -d), i1 = std::min(count, count - d);
    if (axis == 0) {
      const auto n = static_cast<std::size_t>(i1 - i0);
      for (int y = 0; y < height; ++y) {
        // Receivers i0 .. i1 - 1 of row y and their sources i0 + d .. i1 - 1 + d, all inside the row.
        const double* src = in.data() + static_cast<std::size_t>(y) * w + static_cast<std::size_t>(i0 + d);
        double* dst = out->data() + static_cast<std::size_t>(y) * w + static_cast<std::size_t>(i0);
        for (std::size_t x = 0; x < n; ++x) dst[x] += weight * src[x];
      }
    } else {
      for (int y = i0; y < i1; ++y) {
        const double* src = in.data() + static_cast<std::size_t>(y + d) * w;
        double* dst = out->data() + static_cast<std::size_t>(y) * w;
        for (std::size_t x = 0; x < w; ++x) dst[x] += weight * src[x];
      }
    }
  }
}

}  // namespace

std::vector<double> pixel_integrated_gaussian(double variance_mm2, double pixel_mm, int radius) {
  if (!(variance_mm2 > 0.0) || !std::isfinite(variance_mm2)) {
    throw std::invalid_argument("pixel_integrated_gaussian: variance_mm2 must be > 0, got " + std::to_string(variance_mm2));
  }
  if (!(pixel_mm > 0.0) || !std::isfinite(pixel_mm)) {
    throw std::invalid_argument("pixel_integrated_gaussian: pixel_mm must be > 0, got " + std::to_string(pixel_mm));
  }
  if (radius < 0) throw std::invalid_argument("pixel_integrated_gaussian: radius must be >= 0, got " + std::to_string(radius));
  const double scale = pixel_mm / std::sqrt(2.0 * variance_mm2);
  std::vector<double> k(static_cast<std::size_t>(2 * radius + 1));
  for (int d = -radius; d <= radius; ++d) {
    k[static_cast<std::size_t>(d + radius)] = half_erf_difference((d - 0.5) * scale, (d + 0.5) * scale);
  }
  return k;
}

void convolve_fronto_parallel_plane(const PlaneInput& input, const GaussianProfile& profile, double* out_rgb) {
  if (input.width < 1 || input.height < 1) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: bad size " + std::to_string(input.width) + "x" +
                                std::to_string(input.height));
  }
  if (input.irradiance == nullptr || out_rgb == nullptr) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: irradiance and out_rgb must not be null");
  }
  if (!(input.pixel_x_mm > 0.0) || !(input.pixel_y_mm > 0.0)) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: pixel sides must be > 0, got " +
                                std::to_string(input.pixel_x_mm) + " x " + std::to_string(input.pixel_y_mm) + " mm");
  }
  const int w = input.width, h = input.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  for (std::size_t i = 0; i < n * 3; ++i) out_rgb[i] = 0.0;
  std::vector<double> channel(n), rows(n), both(n);
  for (const GaussianTerm& term : profile) {
    if (term.weight[0] == 0.0 && term.weight[1] == 0.0 && term.weight[2] == 0.0) continue;
    const std::vector<double> kx = pixel_integrated_gaussian(term.variance_mm2, input.pixel_x_mm, w - 1);
    const std::vector<double> ky = pixel_integrated_gaussian(term.variance_mm2, input.pixel_y_mm, h - 1);
    for (std::size_t c = 0; c < 3; ++c) {
      if (term.weight[c] == 0.0) continue;
      for (std::size_t i = 0; i < n; ++i) channel[i] = static_cast<double>(input.irradiance[i * 4 + c]);
      convolve_axis(kx, 0, w, h, channel, &rows);  // along x
      convolve_axis(ky, 1, w, h, rows, &both);     // along y
      for (std::size_t i = 0; i < n; ++i) out_rgb[i * 3 + c] += term.weight[c] * both[i];
    }
  }
}

double plane_pixel_mm_x(const Matrix4& m, int width, double distance, double world_units_per_mm) {
  return std::fabs(2.0 * clip_w_from_distance(m, distance) / (static_cast<double>(m[0]) * width)) / world_units_per_mm;
}

double plane_pixel_mm_y(const Matrix4& m, int height, double distance, double world_units_per_mm) {
  return std::fabs(2.0 * clip_w_from_distance(m, distance) / (static_cast<double>(m[5]) * height)) / world_units_per_mm;
}

}  // namespace sss::math
