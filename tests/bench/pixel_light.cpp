#include "pixel_light.hpp"

#include <algorithm>
#include <cmath>

namespace sss_bench {

namespace {

// World to view of a look_at matrix (rotation and translation, column-major).
Point3 to_view(const detail::Mat4& m, const Point3& p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12], m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

// The one-sided depth change per pixel along an axis that is smaller (a slope that does not
// straddle a silhouette or step); 0 where no translucent neighbour exists.
double smaller_step(const Scene& s, int x, int y, int dx, int dy) {
  const double d = s.distance[pixel_index(s, x, y)];
  double best = -1.0;
  for (int sign : {-1, 1}) {
    const int nx = x + sign * dx, ny = y + sign * dy;
    if (nx < 0 || ny < 0 || nx >= s.width || ny >= s.height || s.mask[pixel_index(s, nx, ny)] == 0) continue;
    const double step = std::fabs(s.distance[pixel_index(s, nx, ny)] - d);
    best = best < 0.0 ? step : std::min(best, step);
  }
  return best < 0.0 ? 0.0 : best;
}

// How far behind the frame's depth at a point's nearest pixel the point may lie and still count as
// what that pixel shows (the header says how much).
double visibility_tolerance(const Scene& s, int x, int y) {
  return 0.25 * s.world_units_per_mm + smaller_step(s, x, y, 1, 0) + smaller_step(s, x, y, 0, 1);
}

// Catmull-Rom's weights of the samples at -1, 0, 1 and 2 for a point t in [0, 1) past sample 0.
std::array<double, 4> catmull_rom_weights(double t) {
  const double t2 = t * t, t3 = t2 * t;
  return {0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0), 0.5 * (-3.0 * t3 + 4.0 * t2 + t),
          0.5 * (t3 - t2)};
}

// Catmull-Rom's bicubic of the 4x4 pixels round the point (x0, y0 the pixel before it on each axis,
// tx, ty its offsets past them) into *light, when all sixteen are translucent and within
// `tolerance` of its depth; false, *light untouched, where any is not (light_from_pixels falls back
// to bilinear there).
bool catmull_rom_light(const Scene& s, int x0, int y0, double tx, double ty, double distance, double tolerance,
                       std::array<float, 3>* light) {
  if (x0 < 1 || y0 < 1 || x0 + 2 >= s.width || y0 + 2 >= s.height) return false;
  const std::array<double, 4> wx = catmull_rom_weights(tx), wy = catmull_rom_weights(ty);
  std::array<double, 3> sum{};
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const std::size_t p = pixel_index(s, x0 - 1 + i, y0 - 1 + j);
      if (s.mask[p] == 0 || std::fabs(s.distance[p] - distance) > tolerance) return false;
      const double w = wx[static_cast<std::size_t>(i)] * wy[static_cast<std::size_t>(j)];
      for (std::size_t c = 0; c < 3; ++c) sum[c] += w * s.irradiance[p * 4 + c];
    }
  }
  for (std::size_t c = 0; c < 3; ++c) (*light)[c] = static_cast<float>(sum[c]);
  return true;
}

}  // namespace

PixelLight light_from_pixels(const Scene& s, const detail::Mat4& view, const Point3& world) {
  PixelLight out;
  const Point3 v = to_view(view, world);
  const double distance = -v[2];
  if (!(distance > 0.0)) return out;
  const double fx = (s.projection[0] * v[0] / distance + 1.0) * 0.5 * s.width - 0.5;
  const double fy = (s.projection[5] * v[1] / distance + 1.0) * 0.5 * s.height - 0.5;
  const int nx = static_cast<int>(std::lround(fx)), ny = static_cast<int>(std::lround(fy));
  if (nx < 0 || ny < 0 || nx >= s.width || ny >= s.height) return out;
  const std::size_t nearest = pixel_index(s, nx, ny);
  if (s.mask[nearest] == 0) return out;
  const double tolerance = visibility_tolerance(s, nx, ny);
  if (distance > s.distance[nearest] + tolerance) return out;
  out.visible = true;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  if (catmull_rom_light(s, x0, y0, tx, ty, distance, 2.0 * tolerance, &out.light)) return out;
  double weight = 0.0;
  std::array<double, 3> sum{};
  for (int k = 0; k < 4; ++k) {
    const int x = x0 + (k & 1), y = y0 + (k >> 1);
    if (x < 0 || y < 0 || x >= s.width || y >= s.height) continue;
    const std::size_t i = pixel_index(s, x, y);
    if (s.mask[i] == 0 || std::fabs(s.distance[i] - distance) > tolerance) continue;
    const double w = ((k & 1) ? tx : 1.0 - tx) * ((k >> 1) ? ty : 1.0 - ty);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += w * s.irradiance[i * 4 + c];
    weight += w;
  }
  for (std::size_t c = 0; c < 3; ++c) {
    out.light[c] = weight > 0.0 ? static_cast<float>(sum[c] / weight) : s.irradiance[nearest * 4 + c];
  }
  return out;
}

}  // namespace sss_bench
