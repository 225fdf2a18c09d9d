#include "projection.hpp"

#include <cmath>
#include <cstdio>

namespace sss::math {

double depth_map_determinant(const Matrix4& m) {
  return static_cast<double>(m[10]) * m[15] - static_cast<double>(m[14]) * m[11];
}

ProjectionCheck check_projection(const Matrix4& m, std::string* why) {
  char buffer[160];
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(m[static_cast<std::size_t>(i)])) {
      std::snprintf(buffer, sizeof buffer, "projection[%d] = %g is not finite", i,
                    static_cast<double>(m[static_cast<std::size_t>(i)]));
      if (why) *why = buffer;
      return ProjectionCheck::invalid;
    }
  }
  // x and y scales (m[0], m[5]) turn world offsets into screen offsets; zero means a flat frustum.
  if (m[0] == 0.0f || m[5] == 0.0f) {
    std::snprintf(buffer, sizeof buffer, "projection is singular: x scale m[0] = %g, y scale m[5] = %g",
                  static_cast<double>(m[0]), static_cast<double>(m[5]));
    if (why) *why = buffer;
    return ProjectionCheck::invalid;
  }
  const double det = depth_map_determinant(m);
  const double magnitude = std::fabs(static_cast<double>(m[10]) * m[15]) + std::fabs(static_cast<double>(m[14]) * m[11]);
  if (!(std::fabs(det) > 1e-12 * magnitude) || det == 0.0) {
    std::snprintf(buffer, sizeof buffer,
                  "projection is singular: depth cannot be linearised (m[10]*m[15] - m[14]*m[11] = %g)", det);
    if (why) *why = buffer;
    return ProjectionCheck::invalid;
  }
  if (m[3] != 0.0f || m[7] != 0.0f) {
    std::snprintf(buffer, sizeof buffer, "projection w depends on x or y (m[3] = %g, m[7] = %g)",
                  static_cast<double>(m[3]), static_cast<double>(m[7]));
    if (why) *why = buffer;
    return ProjectionCheck::unsupported;
  }
  if (m[1] != 0.0f || m[4] != 0.0f) {
    std::snprintf(buffer, sizeof buffer, "projection rotates or shears x/y (m[1] = %g, m[4] = %g)",
                  static_cast<double>(m[1]), static_cast<double>(m[4]));
    if (why) *why = buffer;
    return ProjectionCheck::unsupported;
  }
  return ProjectionCheck::ok;
}

double distance_from_ndc_z(const Matrix4& m, double ndc_z) {
  const double z_view = (m[14] - ndc_z * m[15]) / (ndc_z * m[11] - m[10]);
  return -z_view;
}

ProjectionReading read_projection(const Matrix4& m, bool zero_to_one) {
  ProjectionReading r;
  r.orthographic = m[11] == 0.0f;
  // d(NDC z)/d(distance) = -det / w²: the depth grows with the distance where det < 0.
  r.reversed = depth_map_determinant(m) > 0.0;
  const double low = zero_to_one ? 0.0 : -1.0;
  const double near_ndc = r.reversed ? 1.0 : low, far_ndc = r.reversed ? low : 1.0;
  r.near_distance = distance_from_ndc_z(m, near_ndc);
  // The far end at infinity: the denominator of distance_from_ndc_z vanishes there, to float
  // precision (an infinite projection built in float keeps an ulp or so of it).
  const double denominator = far_ndc * m[11] - m[10];
  const double scale = std::fabs(static_cast<double>(m[11])) + std::fabs(static_cast<double>(m[10]));
  const double far = distance_from_ndc_z(m, far_ndc);
  r.infinite_far = std::fabs(denominator) <= 1e-6 * scale || !std::isfinite(far) || far <= r.near_distance;
  r.far_distance = r.infinite_far ? HUGE_VAL : far;
  return r;
}

double world_per_pixel(const Matrix4& m, int axis, int pixels, double distance) {
  const double scale = std::fabs(static_cast<double>(m[axis == 0 ? 0 : 5]));
  return 2.0 * clip_w_from_distance(m, distance) / (scale * pixels);
}

double clip_w_from_distance(const Matrix4& m, double distance) {
  return -static_cast<double>(m[11]) * distance + m[15];
}

}  // namespace sss::math
