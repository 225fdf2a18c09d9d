#include "scene_math.hpp"

namespace sss_bench::detail {

Mat4 identity() {
  Mat4 m{};
  m[0] = m[5] = m[10] = m[15] = 1.0;
  return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
  return r;
}

Mat4 perspective(double fovy, double aspect, double near_plane, double far_plane) {
  const double f = 1.0 / std::tan(fovy / 2);
  Mat4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = -(far_plane + near_plane) / (far_plane - near_plane);
  m[11] = -1;
  m[14] = -2 * far_plane * near_plane / (far_plane - near_plane);
  return m;
}

Mat4 orthographic(double left, double right, double bottom, double top, double near_plane, double far_plane) {
  Mat4 m{};
  m[0] = 2 / (right - left);
  m[5] = 2 / (top - bottom);
  m[10] = -2 / (far_plane - near_plane);
  m[12] = -(right + left) / (right - left);
  m[13] = -(top + bottom) / (top - bottom);
  m[14] = -(far_plane + near_plane) / (far_plane - near_plane);
  m[15] = 1;
  return m;
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  const Vec3 back = normalize(eye - target);  // view +z
  const Vec3 right = normalize(cross(up, back));
  const Vec3 true_up = cross(back, right);
  Mat4 m = identity();
  const Vec3 axes[3] = {right, true_up, back};
  for (int r = 0; r < 3; ++r) {
    m[0 * 4 + r] = axes[r].x;
    m[1 * 4 + r] = axes[r].y;
    m[2 * 4 + r] = axes[r].z;
    m[3 * 4 + r] = -dot(axes[r], eye);
  }
  return m;
}

Vec3 transform_point(const Mat4& m, Vec3 p) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

std::array<float, 16> to_float(const Mat4& m) {
  std::array<float, 16> r{};
  for (int i = 0; i < 16; ++i) r[i] = static_cast<float>(m[i]);
  return r;
}

Mat4 to_double(const std::array<float, 16>& m) {
  Mat4 r{};
  for (int i = 0; i < 16; ++i) r[i] = m[i];
  return r;
}

float window_depth(const Mat4& p, double distance) {
  const double z = -distance;
  const double clip_z = p[10] * z + p[14];
  const double clip_w = p[11] * z + p[15];
  return static_cast<float>(0.5 * (clip_z / clip_w) + 0.5);
}

Vec3 PinholeCamera::ray(int i, int j) const {
  const double ndc_x = 2.0 * (i + 0.5) / width - 1.0;
  const double ndc_y = 2.0 * (j + 0.5) / height - 1.0;
  return {ndc_x / projection[0], ndc_y / projection[5], -1.0};
}

double PinholeCamera::pixels_per_unit(double distance) const { return 0.5 * height * projection[5] / distance; }

PinholeCamera make_pinhole(int width, int height, double fovy, double near_plane, double far_plane) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.projection = to_double(to_float(perspective(fovy, static_cast<double>(width) / height, near_plane, far_plane)));
  return c;
}

}  // namespace sss_bench::detail
