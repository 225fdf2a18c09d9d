#include "surface.hpp"

#include <cstddef>

namespace sss::math {

Vec3 view_position(const Matrix4& m, int width, int height, double wx, double wy, double distance) {
  const double x_ndc = 2.0 * wx / width - 1.0;
  const double y_ndc = 2.0 * wy / height - 1.0;
  const double z = -distance;
  const double w = static_cast<double>(m[11]) * z + m[15];
  Vec3 p;
  p.x = (x_ndc * w - static_cast<double>(m[8]) * z - m[12]) / m[0];
  p.y = (y_ndc * w - static_cast<double>(m[9]) * z - m[13]) / m[5];
  p.z = z;
  return p;
}

Vec3 pixel_position(const Matrix4& m, int width, int height, int x, int y, double distance) {
  return view_position(m, width, height, x + 0.5, y + 0.5, distance);
}

double SurfaceImage::distance_at(int x, int y) const {
  const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  return distance_f64 ? distance_f64[i] : static_cast<double>(distance[i]);
}

bool SurfaceImage::usable(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height) return false;
  const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  if (mask && mask[i] == 0) return false;
  const double d = distance_at(x, y);
  if (!std::isfinite(d)) return false;
  return clip_w_from_distance(projection, d) > 0.0;
}

void set_footprint_rectangle(const Vec3& tx, const Vec3& ty, PixelFootprint* f) {
  f->tx = tx;
  f->ty = ty;
  f->area = length(cross(tx, ty));
  f->a = length(tx);
  f->t1 = Vec3{};
  f->t2 = Vec3{};
  f->b = 0.0;
  if (!(f->a > 0.0) || !(f->area > 0.0)) {
    f->area = 0.0;
    return;
  }
  f->t1 = (1.0 / f->a) * tx;
  const Vec3 ty_perp = ty - dot(ty, f->t1) * f->t1;
  const double ty_perp_length = length(ty_perp);
  if (!(ty_perp_length > 0.0)) {
    f->area = 0.0;
    return;
  }
  f->t2 = (1.0 / ty_perp_length) * ty_perp;
  f->b = f->area / f->a;
}

namespace {

// One tangent: `axis` 0 is x (left/right neighbours), 1 is y (down/up).
Vec3 tangent(const SurfaceImage& image, int x, int y, int axis, double d, const Vec3& p,
             FootprintRule rule, TangentSource* source) {
  const Matrix4& m = image.projection;
  const int dx = axis == 0 ? 1 : 0;
  const int dy = axis == 0 ? 0 : 1;
  const bool plus_ok = image.usable(x + dx, y + dy);
  const bool minus_ok = image.usable(x - dx, y - dy);
  const double w = clip_w_from_distance(m, d);
  const double facing = axis == 0 ? 2.0 * w / (static_cast<double>(m[0]) * image.width)
                                  : 2.0 * w / (static_cast<double>(m[5]) * image.height);
  if (!plus_ok && !minus_ok) {
    *source = TangentSource::facing_plane;
    return axis == 0 ? Vec3{facing, 0.0, 0.0} : Vec3{0.0, facing, 0.0};
  }
  const double d_plus = plus_ok ? image.distance_at(x + dx, y + dy) : 0.0;
  const double d_minus = minus_ok ? image.distance_at(x - dx, y - dy) : 0.0;
  const auto position = [&](int px, int py, double pd) {
    return pixel_position(m, image.width, image.height, px, py, pd);
  };
  if (rule == FootprintRule::central_where_smooth && plus_ok && minus_ok &&
      std::fabs(d_plus - 2.0 * d + d_minus) <= std::fabs(facing)) {
    *source = TangentSource::central;
    return 0.5 * (position(x + dx, y + dy, d_plus) - position(x - dx, y - dy, d_minus));
  }
  const bool use_plus = plus_ok && (!minus_ok || std::fabs(d_plus - d) <= std::fabs(d_minus - d));
  if (use_plus) {
    *source = TangentSource::forward;
    return position(x + dx, y + dy, d_plus) - p;
  }
  *source = TangentSource::backward;
  return p - position(x - dx, y - dy, d_minus);
}

}  // namespace

PixelFootprint pixel_footprint(const SurfaceImage& image, int x, int y, FootprintRule rule) {
  PixelFootprint f;
  const double d = image.distance_at(x, y);
  f.position = pixel_position(image.projection, image.width, image.height, x, y, d);
  const Vec3 tx = tangent(image, x, y, 0, d, f.position, rule, &f.x_source);
  const Vec3 ty = tangent(image, x, y, 1, d, f.position, rule, &f.y_source);
  set_footprint_rectangle(tx, ty, &f);
  return f;
}

}  // namespace sss::math
