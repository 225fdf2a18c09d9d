#include "normal_blur.hpp"

#include <algorithm>
#include <cmath>

namespace sss::math {

namespace {

// One separable Gaussian pass along x (horizontal) or y, clamped at the edges.
void gaussian_pass(const std::vector<float>& in, std::vector<float>& out, int w, int h, double sigma_texels,
                   bool horizontal) {
  const int radius = std::max(1, static_cast<int>(std::ceil(4.0 * sigma_texels)));
  std::vector<double> k(static_cast<std::size_t>(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    k[static_cast<std::size_t>(i + radius)] = std::exp(-0.5 * i * i / (sigma_texels * sigma_texels));
    sum += k[static_cast<std::size_t>(i + radius)];
  }
  for (double& v : k) v /= sum;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double acc[3] = {0, 0, 0};
      for (int i = -radius; i <= radius; ++i) {
        const int sx = horizontal ? std::clamp(x + i, 0, w - 1) : x;
        const int sy = horizontal ? y : std::clamp(y + i, 0, h - 1);
        const float* p = &in[3 * static_cast<std::size_t>(sy * w + sx)];
        for (int c = 0; c < 3; ++c) acc[c] += k[static_cast<std::size_t>(i + radius)] * p[c];
      }
      for (int c = 0; c < 3; ++c) out[3 * static_cast<std::size_t>(y * w + x) + c] = static_cast<float>(acc[c]);
    }
  }
}

double rms_radius_sq(const std::vector<GaussianTerm>& terms, std::size_t c) {
  double s = 0.0, total = 0.0;
  for (const auto& t : terms) {
    s += t.weight[c] * 2.0 * t.variance_mm2;  // a 2D Gaussian's mean r² is 2v
    total += t.weight[c];
  }
  return total > 0.0 ? s / total : 0.0;
}

}  // namespace

std::vector<std::uint8_t> blur_normal_map(const std::vector<std::uint8_t>& rgb, int width, int height,
                                          double texel_mm, const RadialProfile& profile, int channel) {
  const std::vector<GaussianTerm>* terms = profile.gaussian_terms();
  if (terms == nullptr) return {};
  const std::size_t c_index = static_cast<std::size_t>(std::clamp(channel, 0, 2));
  std::vector<float> normals(rgb.size()), sum(rgb.size(), 0.0f), tmp(rgb.size()), blurred(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) normals[i] = rgb[i] / 255.0f * 2.0f - 1.0f;
  double weight_total = 0.0;
  for (const auto& t : *terms) weight_total += t.weight[c_index];
  for (const auto& t : *terms) {
    const double wgt = t.weight[c_index] / weight_total;
    if (wgt == 0.0) continue;
    const double sigma = std::sqrt(t.variance_mm2) / texel_mm;
    if (sigma < 0.05) {  // far below a texel: the identity
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += static_cast<float>(wgt) * normals[i];
      continue;
    }
    gaussian_pass(normals, tmp, width, height, sigma, true);
    gaussian_pass(tmp, blurred, width, height, sigma, false);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += static_cast<float>(wgt) * blurred[i];
  }
  std::vector<std::uint8_t> encoded(rgb.size());
  for (std::size_t p = 0; p + 2 < rgb.size(); p += 3) {
    const double len = std::sqrt(static_cast<double>(sum[p]) * sum[p] + static_cast<double>(sum[p + 1]) * sum[p + 1] +
                                 static_cast<double>(sum[p + 2]) * sum[p + 2]);
    for (std::size_t c = 0; c < 3; ++c) {
      const double n = len > 1e-12 ? sum[p + c] / len : (c == 2 ? 1.0 : 0.0);
      encoded[p + c] = static_cast<std::uint8_t>(std::lround((n * 0.5 + 0.5) * 255.0));
    }
  }
  return encoded;
}

std::array<double, 3> normal_blend_factors(const RadialProfile& profile, int channel) {
  std::array<double, 3> out{1.0, 1.0, 1.0};
  const std::vector<GaussianTerm>* terms = profile.gaussian_terms();
  if (terms == nullptr) return out;
  const double base = rms_radius_sq(*terms, static_cast<std::size_t>(std::clamp(channel, 0, 2)));
  for (std::size_t c = 0; c < 3; ++c) out[c] = base > 0.0 ? std::min(1.0, std::sqrt(rms_radius_sq(*terms, c) / base)) : 1.0;
  return out;
}

}  // namespace sss::math
