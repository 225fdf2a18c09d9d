#include "plane_reference.hpp"

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

// The half-width beyond which every value of k (centred, 2·radius + 1 values) is exactly 0.0 in
// double (erfc underflows past ~27): skipping those taps changes no bit of the sum.
int nonzero_radius(const std::vector<double>& k) {
  const int radius = static_cast<int>(k.size() / 2);
  int r = radius;
  while (r > 0 && k[static_cast<std::size_t>(radius + r)] == 0.0 && k[static_cast<std::size_t>(radius - r)] == 0.0) --r;
  return r;
}

// One axis of one term: out[i] = Σ_j k[j - i] · in[j] along lines of `count` values `stride` apart,
// `lines` lines whose first values are `line_stride` apart. k is centred, with at least count - 1
// values on each side.
void convolve_axis(const std::vector<double>& k, int count, std::size_t stride, int lines, std::size_t line_stride,
                   const std::vector<double>& in, std::vector<double>* out) {
  const int centre = static_cast<int>(k.size() / 2);
  const int reach = nonzero_radius(k);
  for (int line = 0; line < lines; ++line) {
    const std::size_t base = static_cast<std::size_t>(line) * line_stride;
    for (int i = 0; i < count; ++i) {
      double sum = 0.0;
      const int j0 = i - reach < 0 ? 0 : i - reach, j1 = i + reach >= count ? count - 1 : i + reach;
      for (int j = j0; j <= j1; ++j) sum += k[static_cast<std::size_t>(j - i + centre)] * in[base + static_cast<std::size_t>(j) * stride];
      (*out)[base + static_cast<std::size_t>(i) * stride] = sum;
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
      convolve_axis(kx, w, 1, h, static_cast<std::size_t>(w), channel, &rows);               // along x, each row
      convolve_axis(ky, h, static_cast<std::size_t>(w), w, 1, rows, &both);                  // along y, each column
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
