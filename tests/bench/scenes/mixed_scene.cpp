// head-mixed: the head scan (skin) with a marble bust and a wax candle beside it, the demo's mixed
// scene (demo/scene_objects.cpp) for the benchmark: three profiles and three objects in one frame.
// The head is rendered as the other head scenes are (render_head_scene); the bust (a box pedestal,
// an ellipsoid of shoulders, an ellipsoid head) and the candle (a cylinder under a half-ellipsoid
// top) are ray-cast here on the CPU, exactly, at each pixel's centre, and drawn where they are nearer
// than the head. They are lit by the head scenes' key (shadowed by themselves, not by the head),
// fill and ambient; the demo's flame and its light are left out (no emission in a benchmark's
// irradiance).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "head_asset.hpp"
#include "head_scene.hpp"
#include "sss/sss.h"

namespace sss_bench::detail {

namespace {

struct Shape {
  enum Kind { kBox, kEllipsoid, kCylinder } kind;
  Vec3 a, b;  // box: min, max; ellipsoid: centre, radii; cylinder: base centre, (radius, height, 0)
  int part;   // 0 bust, 1 candle
};

constexpr double kNone = std::numeric_limits<double>::infinity();

// The nearest t > 1e-9 with origin + t · dir on the shape, and the outward normal there.
double intersect(const Shape& s, Vec3 o, Vec3 d, Vec3* normal) {
  if (s.kind == Shape::kEllipsoid) {
    const Vec3 r = s.b;
    const Vec3 oo{(o.x - s.a.x) / r.x, (o.y - s.a.y) / r.y, (o.z - s.a.z) / r.z}, dd{d.x / r.x, d.y / r.y, d.z / r.z};
    const double qa = dot(dd, dd), qb = dot(oo, dd), qc = dot(oo, oo) - 1.0;
    const double disc = qb * qb - qa * qc;
    if (disc < 0.0) return kNone;
    double t = (-qb - std::sqrt(disc)) / qa;
    if (t <= 1e-9) t = (-qb + std::sqrt(disc)) / qa;
    if (t <= 1e-9) return kNone;
    const Vec3 p = oo + dd * t;
    *normal = normalize(Vec3{p.x / r.x, p.y / r.y, p.z / r.z});
    return t;
  }
  if (s.kind == Shape::kBox) {
    double t0 = -kNone, t1 = kNone;
    int axis = 0;
    const double lo[3] = {s.a.x, s.a.y, s.a.z}, hi[3] = {s.b.x, s.b.y, s.b.z}, oc[3] = {o.x, o.y, o.z}, dc[3] = {d.x, d.y, d.z};
    double sign = 1.0;
    for (int k = 0; k < 3; ++k) {
      if (std::fabs(dc[k]) < 1e-15) {
        if (oc[k] < lo[k] || oc[k] > hi[k]) return kNone;
        continue;
      }
      double ta = (lo[k] - oc[k]) / dc[k], tb = (hi[k] - oc[k]) / dc[k];
      const double entering_sign = ta < tb ? -1.0 : 1.0;  // entering through lo faces -axis
      if (ta > tb) std::swap(ta, tb);
      if (ta > t0) {
        t0 = ta;
        axis = k;
        sign = entering_sign;
      }
      t1 = std::min(t1, tb);
    }
    if (t0 > t1 || t0 <= 1e-9) return kNone;
    *normal = Vec3{axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0};
    return t0;
  }
  // The cylinder's side (open at both ends: its top is the ellipsoid, its foot never seen).
  const double radius = s.b.x, height = s.b.y;
  const double ox = o.x - s.a.x, oz = o.z - s.a.z;
  const double qa = d.x * d.x + d.z * d.z, qb = ox * d.x + oz * d.z, qc = ox * ox + oz * oz - radius * radius;
  const double disc = qb * qb - qa * qc;
  if (qa < 1e-15 || disc < 0.0) return kNone;
  for (double t : {(-qb - std::sqrt(disc)) / qa, (-qb + std::sqrt(disc)) / qa}) {
    const double y = o.y + t * d.y - s.a.y;
    if (t > 1e-9 && y >= 0.0 && y <= height) {
      *normal = normalize(Vec3{ox + t * d.x, 0.0, oz + t * d.z});
      return t;
    }
  }
  return kNone;
}

// The demo's layout (demo/scene_objects.cpp), standing on the scan's lowest point.
std::vector<Shape> mixed_shapes(double floor_y) {
  const Vec3 bust{-0.37, floor_y, -0.03}, candle{0.33, floor_y, 0.0};
  const double candle_height = 0.21, cap = 0.012, radius = 0.035;
  return {{Shape::kBox, bust + Vec3{-0.065, 0.0, -0.065}, bust + Vec3{0.065, 0.10, 0.065}, 0},
          {Shape::kEllipsoid, bust + Vec3{0.0, 0.14, 0.0}, Vec3{0.10, 0.045, 0.06}, 0},
          {Shape::kEllipsoid, bust + Vec3{0.0, 0.245, 0.005}, Vec3{0.058, 0.078, 0.065}, 0},
          {Shape::kCylinder, candle, Vec3{radius, candle_height - cap, 0.0}, 1},
          {Shape::kEllipsoid, candle + Vec3{0.0, candle_height - cap, 0.0}, Vec3{radius, cap, radius}, 1}};
}

double nearest(const std::vector<Shape>& shapes, Vec3 o, Vec3 d, Vec3* normal, int* part) {
  double best = kNone;
  for (const Shape& s : shapes) {
    Vec3 n;
    const double t = intersect(s, o, d, &n);
    if (t < best) {
      best = t;
      *normal = n;
      *part = s.part;
    }
  }
  return best;
}

}  // namespace

Scene render_mixed_scene(const std::string& name, int width, int height, const HeadView& view) {
  Scene scene = render_head_scene(name, width, height, view);
  const HeadAsset& asset = head_asset();
  const std::vector<Shape> shapes = mixed_shapes(asset.bounds_min[1]);
  const HeadLights lights = head_lights();
  Mat4 projection{}, v{};
  head_camera(view, width, height, &projection, &v);
  // The view matrix's rotation R (world to view) and the eye (-Rᵀ t).
  auto to_world = [&v](Vec3 d) {
    return Vec3{v[0] * d.x + v[1] * d.y + v[2] * d.z, v[4] * d.x + v[5] * d.y + v[6] * d.z,
                v[8] * d.x + v[9] * d.y + v[10] * d.z};
  };
  const Vec3 eye = to_world(Vec3{-v[12], -v[13], -v[14]});
  // Profiles: 0 skin (the head, object 1), 1 marble (the bust, object 2), 2 wax (the candle, object 3;
  // Jensen's cream: no measured wax, the nearest).
  scene.profile_materials = {SSS_PROFILE_SKIN_DEON, SSS_PROFILE_MARBLE, SSS_PROFILE_CREAM};
  const float albedo[2][3] = {{0.83f, 0.82f, 0.79f}, {0.93f, 0.86f, 0.70f}};
  const uint8_t bytes[2] = {1 | 2 << 4, 2 | 3 << 4};
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  scene.profile.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) scene.profile[i] = scene.mask[i] != 0 ? static_cast<uint8_t>(0 | 1 << 4) : 0;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double ndc_x = (i + 0.5) / width * 2.0 - 1.0, ndc_y = (j + 0.5) / height * 2.0 - 1.0;
      // View-space direction with z = -1: a hit at t lies at view distance t.
      const Vec3 dir = to_world(Vec3{ndc_x / projection[0], ndc_y / projection[5], -1.0});
      Vec3 normal;
      int part = 0;
      const double t = nearest(shapes, eye, dir, &normal, &part);
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i);
      if (!(t < scene.distance[k])) continue;
      const Vec3 p = eye + dir * t;
      Vec3 unused;
      int unused_part = 0;
      const double key_dot = dot(normal, lights.key_direction);
      const bool lit = key_dot > 0.0 && !(nearest(shapes, p + normal * 1e-6, lights.key_direction, &unused, &unused_part) < kNone);
      const double fill_dot = std::max(dot(normal, lights.fill_direction), 0.0);
      for (int c = 0; c < 3; ++c) {
        const double e = lights.key[c] * (lit ? key_dot : 0.0) + lights.fill[c] * fill_dot + lights.ambient[c];
        scene.irradiance[k * 4 + static_cast<std::size_t>(c)] = static_cast<float>(albedo[part][c] * e);
      }
      scene.irradiance[k * 4 + 3] = 1.0f;
      scene.distance[k] = static_cast<float>(t);
      scene.window_depth[k] = window_depth(projection, t);
      scene.mask[k] = 1;
      scene.profile[k] = bytes[part];
    }
  }
  return scene;
}

}  // namespace sss_bench::detail
