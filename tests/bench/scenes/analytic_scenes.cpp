#include "analytic_scenes.hpp"
#include "math/preintegrated_lut.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "scene_math.hpp"

namespace sss_bench::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNear = 0.05, kFar = 2.0;

// An empty scene (nothing translucent, zero everywhere) of the camera's size and projection.
Scene scene_for_camera(const std::string& name, const PinholeCamera& camera) {
  Scene s;
  s.name = name;
  s.width = camera.width;
  s.height = camera.height;
  s.projection = to_float(camera.projection);
  const size_t n = static_cast<size_t>(camera.width) * static_cast<size_t>(camera.height);
  s.irradiance.assign(n * 4, 0.0f);
  s.distance.assign(n, 0.0f);
  s.window_depth.assign(n, 0.0f);
  s.mask.assign(n, 0);
  return s;
}

Scene blank_scene(const std::string& name, int width, int height, PinholeCamera* camera) {
  *camera = make_pinhole(width, height, kFovyDegrees * kPi / 180.0, kNear, kFar);
  return scene_for_camera(name, *camera);
}

void set_pixel(Scene& s, const PinholeCamera& camera, int i, int j, double r, double g, double b, bool translucent,
               double distance) {
  const size_t p = static_cast<size_t>(j) * static_cast<size_t>(s.width) + static_cast<size_t>(i);
  s.irradiance[p * 4 + 0] = static_cast<float>(r);
  s.irradiance[p * 4 + 1] = static_cast<float>(g);
  s.irradiance[p * 4 + 2] = static_cast<float>(b);
  s.irradiance[p * 4 + 3] = translucent ? 1.0f : 0.0f;
  s.mask[p] = translucent ? 1 : 0;
  s.distance[p] = static_cast<float>(distance);
  s.window_depth[p] = window_depth(camera.projection, distance);
}

// The area of the unit pixel square [x0, x0+1] x [y0, y0+1] where nx*x + ny*y <= 0 (exact: the
// square clipped by the half-plane, then the shoelace formula).
double half_plane_coverage(double x0, double y0, double nx, double ny) {
  const double square[4][2] = {{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}};
  double clipped[8][2];
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    const double* a = square[k];
    const double* b = square[(k + 1) % 4];
    const double fa = nx * a[0] + ny * a[1], fb = nx * b[0] + ny * b[1];
    if (fa <= 0) {
      clipped[count][0] = a[0];
      clipped[count][1] = a[1];
      ++count;
    }
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const double t = fa / (fa - fb);
      clipped[count][0] = a[0] + t * (b[0] - a[0]);
      clipped[count][1] = a[1] + t * (b[1] - a[1]);
      ++count;
    }
  }
  double area = 0;
  for (int k = 0; k < count; ++k) {
    const double* a = clipped[k];
    const double* b = clipped[(k + 1) % count];
    area += a[0] * b[1] - b[0] * a[1];
  }
  return std::clamp(0.5 * std::fabs(area), 0.0, 1.0);
}

// The fraction of the unit pixel square at (x0, y0) inside the disk of radius r at the origin:
// exact when the pixel is wholly in or out, else the disk's chords clipped to the pixel integrated
// over x (1024 midpoints; the chord length is exact, so the error is far below 0.1 %).
double disk_coverage(double x0, double y0, double r) {
  const double nearest_x = std::clamp(0.0, x0, x0 + 1), nearest_y = std::clamp(0.0, y0, y0 + 1);
  if (nearest_x * nearest_x + nearest_y * nearest_y >= r * r) return 0.0;
  const double far_x = std::max(std::fabs(x0), std::fabs(x0 + 1)), far_y = std::max(std::fabs(y0), std::fabs(y0 + 1));
  if (far_x * far_x + far_y * far_y <= r * r) return 1.0;
  constexpr int kSteps = 1024;
  double area = 0;
  for (int a = 0; a < kSteps; ++a) {
    const double x = x0 + (a + 0.5) / kSteps;
    if (std::fabs(x) >= r) continue;
    const double half = std::sqrt(r * r - x * x);
    area += std::max(0.0, std::min(half, y0 + 1) - std::max(-half, y0));
  }
  return area / kSteps;
}

}  // namespace

Scene make_dot_scene(int width, int height) {
  PinholeCamera camera;
  Scene s = blank_scene("dot", width, height, &camera);
  const double r = kDotRadius * camera.pixels_per_unit(kPlaneDistance);  // in pixels
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double c = disk_coverage(i - 0.5 * width, j - 0.5 * height, r);
      const double e = kDark + (kLit - kDark) * c;
      set_pixel(s, camera, i, j, e, e, e, true, kPlaneDistance);
    }
  return s;
}

Scene make_edge_scene(const std::string& name, double degrees_from_vertical, int width, int height) {
  PinholeCamera camera;
  Scene s = blank_scene(name, width, height, &camera);
  // The line runs along (sin t, cos t) through the image centre (its top leans right for t > 0);
  // the lit side is where (cos t, -sin t) . p <= 0, left of it. Pixels are square, so the angle
  // in pixels is the angle on the plane.
  const double t = degrees_from_vertical * kPi / 180.0;
  const double nx = std::cos(t), ny = -std::sin(t);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double c = half_plane_coverage(i - 0.5 * width, j - 0.5 * height, nx, ny);
      const double e = kDark + (kLit - kDark) * c;
      set_pixel(s, camera, i, j, e, e, e, true, kPlaneDistance);
    }
  return s;
}

// A plane facing the camera at the view distance where one pixel measures `footprint_mm`, with the
// same 30-degree camera as the other scenes (near and far planes at half and twice the distance).
static Scene blank_plane_scene(const std::string& name, double footprint_mm, int width, int height,
                               PinholeCamera* camera, double* distance) {
  const double tan_half = std::tan(0.5 * kFovyDegrees * kPi / 180.0);
  *distance = footprint_mm * 1e-3 * height / (2.0 * tan_half);  // metres
  *camera = make_pinhole(width, height, kFovyDegrees * kPi / 180.0, 0.5 * *distance, 2.0 * *distance);
  Scene s = scene_for_camera(name, *camera);
  s.footprint_mm = footprint_mm;
  return s;
}

// A deterministic value in [0, 1) per pixel (an integer hash: no pattern at any scale).
static double pixel_hash(int i, int j) {
  uint32_t h = static_cast<uint32_t>(i) * 0x8da6b343u ^ static_cast<uint32_t>(j) * 0xd8163841u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return static_cast<double>(h) / 4294967296.0;
}

Scene make_footprint_plane_scene(const std::string& name, double footprint_mm, int width, int height) {
  PinholeCamera camera;
  double distance = 0.0;
  Scene s = blank_plane_scene(name, footprint_mm, width, height, &camera, &distance);
  // The content is placed in millimetres on the plane (the same light at every footprint), centred
  // on the pixel nearest the image centre; the albedo detail is per pixel (a texture at the mip
  // level a renderer samples it at: always about one texel per pixel).
  const double cx = std::floor(0.5 * width) + 0.5, cy = std::floor(0.5 * height) + 0.5;
  double edge_degrees = -1.0, disk_mm = 0.0;
  if (name == "plane-edge-0") edge_degrees = 0.0;
  else if (name == "plane-edge-20") edge_degrees = 20.0;
  else if (name == "plane-edge-45") edge_degrees = 45.0;
  else if (name == "plane-spot") disk_mm = kSpotRadiusMm;
  else if (name == "plane-disk") disk_mm = kDiskRadiusMm;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      double e = kLit;
      if (edge_degrees >= 0.0) {
        const double t = edge_degrees * kPi / 180.0;
        e = kDark + (kLit - kDark) * half_plane_coverage(i - cx, j - cy, std::cos(t), -std::sin(t));
      } else if (disk_mm > 0.0) {
        e = kDark + (kLit - kDark) * disk_coverage(i - cx, j - cy, disk_mm / footprint_mm);
      } else {
        e = kLit * (kAlbedoLow + (1.0 - kAlbedoLow) * pixel_hash(i, j));
      }
      set_pixel(s, camera, i, j, e, e, e, true, distance);
    }
  return s;
}

static Scene sphere_scene(const std::string& name, int width, int height, bool preintegrated, double radius,
                          double distance) {
  PinholeCamera camera;
  Scene s = blank_scene(name, width, height, &camera);
  const Vec3 centre{0, 0, -distance};
  const Vec3 light = normalize(Vec3{0.8, 0.45, 0.4});  // view space, towards the light
  const double albedo[3] = {0.85, 0.6, 0.5}, ambient = 0.03, backdrop = 0.3;
  const double curvature = 1.0 / (radius * 1000.0);  // 1/mm (the scene is in metres)
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 ray = camera.ray(i, j);  // z = -1: the hit's distance is its parameter
      const double a = dot(ray, ray), b = -2 * dot(ray, centre), c = dot(centre, centre) - radius * radius;
      const double disc = b * b - 4 * a * c;
      if (disc < 0) {
        set_pixel(s, camera, i, j, backdrop, backdrop, backdrop, false, kSphereBackdropDistance);
        continue;
      }
      const double hit = (-b - std::sqrt(disc)) / (2 * a);
      const Vec3 normal = (ray * hit - centre) * (1.0 / radius);
      const double ndotl = dot(normalize(normal), light);
      std::array<double, 3> e{std::max(0.0, ndotl), std::max(0.0, ndotl), std::max(0.0, ndotl)};
      if (preintegrated) e = sss::math::preintegrated_diffuse(sss::math::deon_skin_profile(), ndotl, curvature);
      set_pixel(s, camera, i, j, albedo[0] * (e[0] + ambient), albedo[1] * (e[1] + ambient),
                albedo[2] * (e[2] + ambient), true, hit);
    }
  return s;
}

Scene make_sphere_scene(int width, int height) {
  return sphere_scene("sphere", width, height, false, kSphereRadius, kSphereDistance);
}
Scene make_preintegrated_sphere_scene(int width, int height) {
  return sphere_scene("sphere", width, height, true, kSphereRadius, kSphereDistance);
}
Scene make_small_sphere_scene(const std::string& name, double radius, int width, int height, bool preintegrated) {
  // As far as frames it as the big sphere is framed (0.16 of the distance): the same picture, with
  // curvature 1/radius, where scattering bends the terminator visibly.
  return sphere_scene(name, width, height, preintegrated, radius, radius * (kSphereDistance / kSphereRadius));
}

Scene make_depth_step_scene(int width, int height) {
  PinholeCamera camera;
  Scene s = blank_scene("depth-step", width, height, &camera);
  const double near_irradiance = 0.6, far_irradiance = 4.0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 ray = camera.ray(i, j);
      const bool inside = std::fabs(ray.x * kStepNearDistance) < kStepHalfSize &&
                          std::fabs(ray.y * kStepNearDistance) < kStepHalfSize;
      if (inside)
        set_pixel(s, camera, i, j, near_irradiance, near_irradiance, near_irradiance, true, kStepNearDistance);
      else
        set_pixel(s, camera, i, j, far_irradiance, far_irradiance, far_irradiance, false, kStepFarDistance);
    }
  return s;
}

Scene make_tilted_plane_scene(const std::string& name, double degrees, int width, int height) {
  PinholeCamera camera;
  Scene s = blank_scene(name, width, height, &camera);
  const double t = degrees * kPi / 180.0;
  const Vec3 normal{std::sin(t), 0.0, std::cos(t)}, along{std::cos(t), 0.0, -std::sin(t)};
  const double anchor_z = -kPlaneDistance;  // the plane holds (0, 0, -kPlaneDistance)
  constexpr int kSub = 4;                   // 4x4 sub-pixel rays for the edge's coverage
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 centre = camera.ray(i, j);
      // Pinhole rays are linear in the pixel coordinates: one pixel's step from the neighbours.
      const double step_x = camera.ray(i + 1, j).x - centre.x, step_y = camera.ray(i, j + 1).y - centre.y;
      auto hit = [&](double x, double y, double* distance, double* u) {
        const double denominator = normal.x * x + normal.y * y - normal.z;  // n · (x, y, -1)
        const double numerator = normal.z * anchor_z;                       // n · anchor
        if (!(denominator < -1e-9)) return false;                           // parallel or behind
        *distance = numerator / denominator;
        *u = along.x * x * *distance + along.z * (-*distance - anchor_z);
        return *distance > 0.0;
      };
      double distance = 0.0, u = 0.0;
      if (!hit(centre.x, centre.y, &distance, &u) || distance > 0.5 * kFar) {
        set_pixel(s, camera, i, j, 0.3, 0.3, 0.3, false, 0.5 * kFar);
        continue;
      }
      double lit = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          double d = 0.0, v = 0.0;
          const double x = centre.x + ((a + 0.5) / kSub - 0.5) * step_x, y = centre.y + ((b + 0.5) / kSub - 0.5) * step_y;
          if (hit(x, y, &d, &v) && v <= 0.0) lit += 1.0;
        }
      const double e = kDark + (kLit - kDark) * lit / (kSub * kSub);
      set_pixel(s, camera, i, j, e, e, e, true, distance);
    }
  return s;
}

Scene make_empty_scene(int width, int height) {
  PinholeCamera camera;
  Scene s = blank_scene("empty", width, height, &camera);
  const double e = 0.2;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) set_pixel(s, camera, i, j, e, e, e, false, kEmptyDistance);
  return s;
}

}  // namespace sss_bench::detail
