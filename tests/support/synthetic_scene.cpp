#include "synthetic_scene.hpp"

#include <cmath>
#include <random>

namespace sss_test {

sss::math::Matrix4 perspective_matrix(float fovy_degrees, float aspect, float near_plane, float far_plane) {
  const float f = 1.0f / std::tan(fovy_degrees * 3.14159265358979f / 360.0f);
  sss::math::Matrix4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far_plane + near_plane) / (near_plane - far_plane);
  m[11] = -1.0f;
  m[14] = 2.0f * far_plane * near_plane / (near_plane - far_plane);
  return m;
}

sss::math::Matrix4 orthographic_matrix(float half_width, float half_height, float near_plane, float far_plane) {
  sss::math::Matrix4 m{};
  m[0] = 1.0f / half_width;
  m[5] = 1.0f / half_height;
  m[10] = -2.0f / (far_plane - near_plane);
  m[14] = -(far_plane + near_plane) / (far_plane - near_plane);
  m[15] = 1.0f;
  return m;
}

void compute_window_depth(SyntheticScene* scene) {
  const auto& m = scene->projection;
  scene->window_depth.resize(scene->distance.size());
  for (std::size_t i = 0; i < scene->distance.size(); ++i) {
    const double z = -static_cast<double>(scene->distance[i]);
    const double ndc = (m[10] * z + m[14]) / (m[11] * z + m[15]);
    scene->window_depth[i] = static_cast<float>(0.5 * ndc + 0.5);
  }
}

namespace {
// A width x height scene of `projection`: colour, distance and stencil all zero (window depth empty).
SyntheticScene sized_scene(int width, int height, const sss::math::Matrix4& projection) {
  SyntheticScene s;
  s.width = width;
  s.height = height;
  s.projection = projection;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  s.color.assign(n * 4, 0.0f);
  s.distance.assign(n, 0.0f);
  s.stencil.assign(n, 0);
  return s;
}
}  // namespace

SyntheticScene make_turned_plane_scene(int width, int height, double turn_degrees, double axis_degrees,
                                       double distance, const sss::math::Matrix4& projection, unsigned seed,
                                       std::vector<double>* distance_f64) {
  SyntheticScene s = sized_scene(width, height, projection);
  if (distance_f64 != nullptr) distance_f64->assign(s.distance.size(), 0.0);
  const double pi = 3.14159265358979323846;
  const double turn = turn_degrees * pi / 180.0, axis = axis_degrees * pi / 180.0;
  // The axis a, the normal n = (0, 0, 1) turned about it, and the in-plane direction across the
  // axis e = n × a (the light changes along e).
  const double ax = std::cos(axis), ay = std::sin(axis);
  const double nx = ay * std::sin(turn), ny = -ax * std::sin(turn), nz = std::cos(turn);
  const double ex = -nz * ay, ey = nz * ax, ez = nx * ay - ny * ax;
  const auto& m = projection;
  const bool orthographic = m[11] == 0.0f;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> albedo(0.4f, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const double ndc_x = 2.0 * (x + 0.5) / width - 1.0, ndc_y = 2.0 * (y + 0.5) / height - 1.0;
      // The ray's point at view distance d: P = d · (rx, ry, -1) + (ox, oy, 0); on the plane
      // n · (P - (0, 0, -distance)) = 0.
      const double rx = orthographic ? m[8] / m[0] : (ndc_x + m[8]) / m[0];
      const double ry = orthographic ? m[9] / m[5] : (ndc_y + m[9]) / m[5];
      const double ox = orthographic ? (ndc_x - m[12]) / m[0] : 0.0;
      const double oy = orthographic ? (ndc_y - m[13]) / m[5] : 0.0;
      const double d = (-nz * distance - nx * ox - ny * oy) / (nx * rx + ny * ry - nz);
      const double px = d * rx + ox, py = d * ry + oy, pz = -d + distance;  // relative to the centre point
      const double across_mm = 1000.0 * (px * ex + py * ey + pz * ez);
      const float light = across_mm < 0.0 ? 1.0f : 0.05f;
      const float a = albedo(rng);
      for (int c = 0; c < 3; ++c) s.color[i * 4 + static_cast<std::size_t>(c)] = light * a;
      s.color[i * 4 + 3] = 1.0f;
      s.distance[i] = static_cast<float>(d);
      if (distance_f64 != nullptr) (*distance_f64)[i] = d;
      s.stencil[i] = 1;
    }
  }
  compute_window_depth(&s);
  return s;
}

SyntheticScene make_relief_scene(int width, int height, unsigned seed, const sss::math::Matrix4& projection) {
  SyntheticScene s = sized_scene(width, height, projection);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(0.0f, 0.4f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
      float distance = 1.0f + 0.3f * u + 0.1f * v;  // tilted plane
      const float du = u - 0.35f, dv = v - 0.55f;
      const float r2 = (du * du + dv * dv) / (0.15f * 0.15f);
      if (r2 < 1.0f) distance -= 0.12f * std::sqrt(1.0f - r2);  // spherical bump
      if (u < 0.3f && v < 0.35f) distance = 0.7f;               // nearer box: a depth step
      s.distance[i] = distance;
      s.color[i * 4 + 0] = 0.6f + 0.4f * std::sin(9.0f * u) + noise(rng);
      s.color[i * 4 + 1] = 0.3f + 0.2f * std::cos(7.0f * v) + noise(rng);
      s.color[i * 4 + 2] = 0.2f + 0.15f * std::sin(5.0f * (u + v)) + noise(rng);
      float alpha = 1.0f;
      if (v > 0.75f && v < 0.85f) alpha = 0.5f;
      if (u > 0.85f && v > 0.85f) alpha = 0.0f;
      s.color[i * 4 + 3] = alpha;
      s.stencil[i] = u < 0.75f ? 1 : 0;
    }
  }
  compute_window_depth(&s);
  return s;
}

SyntheticScene make_flat_scene(int width, int height, std::array<float, 4> rgba, float distance,
                               const sss::math::Matrix4& projection) {
  SyntheticScene s = sized_scene(width, height, projection);
  const std::size_t n = static_cast<std::size_t>(width) * height;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 4; ++c) s.color[i * 4 + c] = rgba[c];
  }
  s.distance.assign(n, distance);
  s.stencil.assign(n, 1);
  compute_window_depth(&s);
  return s;
}

}  // namespace sss_test

namespace sss_test {

SyntheticScene downsample_2x2(const SyntheticScene& fine) {
  SyntheticScene s = sized_scene(fine.width / 2, fine.height / 2, fine.projection);
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(x);
      double c[4] = {0, 0, 0, 0}, d = 0;
      for (int i = 0; i < 4; ++i) {  // sample order 0..3, as the resolve shader sums
        const std::size_t q = static_cast<std::size_t>(2 * y + i / 2) * static_cast<std::size_t>(fine.width) +
                              static_cast<std::size_t>(2 * x + i % 2);
        for (int k = 0; k < 4; ++k) c[k] += fine.color[q * 4 + static_cast<std::size_t>(k)];
        d += fine.distance[q];
      }
      for (int k = 0; k < 4; ++k) s.color[p * 4 + static_cast<std::size_t>(k)] = static_cast<float>(c[k] / 4.0);
      s.distance[p] = static_cast<float>(d / 4.0);
      if (!fine.stencil.empty()) {
        s.stencil[p] = fine.stencil[static_cast<std::size_t>(2 * y) * static_cast<std::size_t>(fine.width) +
                                    static_cast<std::size_t>(2 * x)];
      }
    }
  }
  compute_window_depth(&s);
  return s;
}

SyntheticScene upsample_2x2(const SyntheticScene& coarse) {
  SyntheticScene s = sized_scene(coarse.width * 2, coarse.height * 2, coarse.projection);
  s.window_depth.resize(s.distance.size());
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(x);
      const std::size_t q = static_cast<std::size_t>(y / 2) * static_cast<std::size_t>(coarse.width) +
                            static_cast<std::size_t>(x / 2);
      for (std::size_t k = 0; k < 4; ++k) s.color[p * 4 + k] = coarse.color[q * 4 + k];
      s.distance[p] = coarse.distance[q];
      s.window_depth[p] = coarse.window_depth[q];
      s.stencil[p] = coarse.stencil.empty() ? 0 : coarse.stencil[q];
    }
  }
  return s;
}

}  // namespace sss_test
