#include "analytic_scenes.hpp"
#include "math/preintegrated_lut.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "scene_math.hpp"

namespace sss_bench::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNear = 0.05, kFar = 2.0;
const Vec3 kSphereLight = normalize(Vec3{0.8, 0.45, 0.4});  // the sphere scenes' light: view space, towards it

// The view-space ray through window position (wx, wy) for any projection surface.hpp takes: the
// point at view distance d is origin + direction · d (direction.z = -1; surface.hpp's position
// formulas, which are linear in d).
void window_ray(const Mat4& m, int width, int height, double wx, double wy, Vec3* origin, Vec3* direction) {
  const double nx = 2.0 * wx / width - 1.0, ny = 2.0 * wy / height - 1.0;
  *origin = {(nx * m[15] - m[12]) / m[0], (ny * m[15] - m[13]) / m[5], 0.0};
  *direction = {(m[8] - nx * m[11]) / m[0], (m[9] - ny * m[11]) / m[5], -1.0};
}

// An empty scene (nothing translucent, zero everywhere) of a size and projection.
Scene scene_for_projection(const std::string& name, int width, int height, const Mat4& projection) {
  Scene s;
  s.name = name;
  s.width = width;
  s.height = height;
  s.projection = to_float(projection);
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  s.irradiance.assign(n * 4, 0.0f);
  s.distance.assign(n, 0.0f);
  s.window_depth.assign(n, 0.0f);
  s.mask.assign(n, 0);
  return s;
}

// The same of the camera's size and projection.
Scene scene_for_camera(const std::string& name, const PinholeCamera& camera) {
  return scene_for_projection(name, camera.width, camera.height, camera.projection);
}

Scene blank_scene(const std::string& name, int width, int height, PinholeCamera* camera) {
  *camera = make_pinhole(width, height, kFovyDegrees * kPi / 180.0, kNear, kFar);
  return scene_for_camera(name, *camera);
}

void set_pixel(Scene& s, const Mat4& projection, int i, int j, double r, double g, double b, bool translucent,
               double distance) {
  const size_t p = static_cast<size_t>(j) * static_cast<size_t>(s.width) + static_cast<size_t>(i);
  s.irradiance[p * 4 + 0] = static_cast<float>(r);
  s.irradiance[p * 4 + 1] = static_cast<float>(g);
  s.irradiance[p * 4 + 2] = static_cast<float>(b);
  s.irradiance[p * 4 + 3] = translucent ? 1.0f : 0.0f;
  s.mask[p] = translucent ? 1 : 0;
  s.distance[p] = static_cast<float>(distance);
  s.window_depth[p] = window_depth(projection, distance);
}

void set_pixel(Scene& s, const PinholeCamera& camera, int i, int j, double r, double g, double b, bool translucent,
               double distance) {
  set_pixel(s, camera.projection, i, j, r, g, b, translucent, distance);
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

// The per-pixel albedo of plane-albedo, the turned planes and the turn sweep's curved scenes, in
// [kAlbedoLow, 1): a texture at the mip level a renderer samples it at, about one texel a pixel.
static double texture_albedo(int i, int j) { return kAlbedoLow + (1.0 - kAlbedoLow) * pixel_hash(i, j); }

namespace {

// The cast shadow across the turn sweep's curved scenes: the shadow of a straight occluder's edge
// under a directional light is a plane holding the light's direction and the edge's; the surface is
// shadowed on the side `normal` points to.
struct CastShadow {
  Vec3 point, normal;
};

// The shadow plane through `point` (on the surface, where it faces the camera) holding the light's
// direction and `edge` (a direction in the screen plane), so that there the edge runs along `edge`
// on screen; shadowed on the side of cross(edge, light).
CastShadow cast_shadow(const Vec3& point, const Vec3& light, const Vec3& edge) {
  return {point, normalize(cross(edge, light))};
}

// The share of pixel (i, j)'s 4x4 rays (a pinhole camera's: from the eye, z = -1) that meet the
// surface outside the shadow, where hit(ray) is the view distance of the surface along it (<= 0:
// none); 1 where no ray meets it. The hard edge anti-aliased as the planes' edges are.
template <typename Hit>
double unshadowed_share(const Mat4& projection, int width, int height, int i, int j, const Hit& hit,
                        const CastShadow& shadow) {
  constexpr int kSub = 4;
  int hits = 0, lit = 0;
  for (int a = 0; a < kSub; ++a) {
    for (int b = 0; b < kSub; ++b) {
      Vec3 origin, direction;
      window_ray(projection, width, height, i + (a + 0.5) / kSub, j + (b + 0.5) / kSub, &origin, &direction);
      const double d = hit(direction);
      if (d <= 0.0) continue;
      ++hits;
      lit += dot(direction * d - shadow.point, shadow.normal) > 0.0 ? 0 : 1;
    }
  }
  return hits > 0 ? static_cast<double>(lit) / hits : 1.0;
}

// The view distance where the ray t · ray (from the eye) first meets the sphere; -1 where it misses.
double sphere_hit(const Vec3& ray, const Vec3& centre, double radius) {
  const double a = dot(ray, ray), b = -2 * dot(ray, centre), c = dot(centre, centre) - radius * radius;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return -1.0;
  return (-b - std::sqrt(disc)) / (2 * a);
}

}  // namespace

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
        e = kLit * texture_albedo(i, j);
      }
      set_pixel(s, camera, i, j, e, e, e, true, distance);
    }
  return s;
}

// near_plane: the camera's (the other scenes'; the turn sweep's sphere comes nearer at fine footprints).
// shadow: the turn sweep's detail (make_footprint_sphere_scene): the per-pixel albedo and the cast
// shadow on the light; none for the canonical spheres.
static Scene sphere_scene(const std::string& name, int width, int height, bool preintegrated, double radius,
                          double distance, double near_plane = kNear, const CastShadow* shadow = nullptr) {
  const PinholeCamera camera = make_pinhole(width, height, kFovyDegrees * kPi / 180.0, near_plane, kFar);
  Scene s = scene_for_camera(name, camera);
  const Vec3 centre{0, 0, -distance};
  const double albedo[3] = {0.85, 0.6, 0.5}, ambient = 0.03, backdrop = 0.3;
  const double curvature = 1.0 / (radius * 1000.0);  // 1/mm (the scene is in metres)
  const auto hit_of = [&](const Vec3& ray) { return sphere_hit(ray, centre, radius); };
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3 ray = camera.ray(i, j);  // z = -1: the hit's distance is its parameter
      const double hit = hit_of(ray);
      if (hit < 0.0) {
        set_pixel(s, camera, i, j, backdrop, backdrop, backdrop, false, kSphereBackdropDistance);
        continue;
      }
      const Vec3 normal = (ray * hit - centre) * (1.0 / radius);
      const double ndotl = dot(normalize(normal), kSphereLight);
      std::array<double, 3> e{std::max(0.0, ndotl), std::max(0.0, ndotl), std::max(0.0, ndotl)};
      if (preintegrated) e = sss::math::preintegrated_diffuse(sss::math::deon_skin_profile(), ndotl, curvature);
      const double texture = shadow != nullptr ? texture_albedo(i, j) : 1.0;
      const double key =
          shadow != nullptr ? unshadowed_share(camera.projection, width, height, i, j, hit_of, *shadow) : 1.0;
      set_pixel(s, camera, i, j, albedo[0] * texture * (e[0] * key + ambient),
                albedo[1] * texture * (e[1] * key + ambient), albedo[2] * texture * (e[2] * key + ambient), true, hit);
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

// ---- The turn sweep ----

namespace {

// The view distance where the ray meets the plane through `point` with normal `normal`; -1 where it
// does not, in front of the camera.
double plane_hit(const Vec3& origin, const Vec3& direction, const Vec3& point, const Vec3& normal) {
  const double along = dot(normal, direction);
  if (std::fabs(along) < 1e-12) return -1.0;
  const double d = dot(normal, point - origin) / along;
  return d > 0.0 ? d : -1.0;
}

// The view distance where a pixel of a camera of vertical field of view fovy_degrees (the 30-degree
// camera by default) measures footprint_mm on a facing plane.
double footprint_distance(double footprint_mm, int height, double fovy_degrees = kFovyDegrees) {
  return footprint_mm * 1e-3 * height / (2.0 * std::tan(0.5 * fovy_degrees * kPi / 180.0));
}

// The turned planes' perspective field of view (vertical, degrees): the one whose corner rays lie
// kTurnedPlaneSpreadDegrees off the view axis. A pixel sees the plane turned by the angle between
// its ray and the normal, which differs from the centre's turn by at most the angle between the two
// rays (the triangle inequality on the sphere of directions), so every pixel sees the turn asked for
// within that spread; the frame's aspect sets the angle, not its size, so it holds at every footprint.
// Why so narrow: the 30-degree camera's corners are 20.7 degrees off its axis, so a plane turned 75
// degrees was seen past its horizon there, far beyond the region rule's silhouette test (regions.hpp:
// a 4-neighbour more than four pixel widths nearer or farther, about 76 degrees about a screen
// axis), and that band with the profile's reach around it left no interior at 0.1 and 0.2 mm per
// pixel. A spread of 5 degrees still left none at 0.1 mm about the screen's x and y axes (the
// frame's border is as wide as the reach, so a silhouette at the far edge takes as much of the
// interior with it); 3 degrees keeps 1086 interior pixels there, 1690 at 0.2 mm (7056 and 4624 on
// the orthographic frames; the diagonal axis loses none, its depth steps split between x and y),
// and across a 75-degree frame the depth, and with it the footprint, still changes by a factor of
// 1.32 (1.48 about the diagonal).
double turned_plane_fovy_degrees(int width, int height) {
  const double aspect = static_cast<double>(width) / height;
  const double tan_half = std::tan(kTurnedPlaneSpreadDegrees * kPi / 180.0) / std::sqrt(1.0 + aspect * aspect);
  return 2.0 * std::atan(tan_half) * 180.0 / kPi;
}

// The turned plane and what its pixels are measured against.
struct TurnedFrame {
  Mat4 projection{};
  Vec3 point, normal;
  Vec3 along, across;  // in the plane: the turn axis, and normal x along (the foreshortened direction)
  Vec3 centre;         // the plane's point at the image centre: the content's origin
  double max_distance = 0.0, backdrop_distance = 0.0;
};

// Perspective: the narrow camera of turned_plane_fovy_degrees with the plane at the facing distance
// D; pixels whose ray misses the plane or meets it beyond 4 D (with that camera only past a turn of
// 83 degrees) are backdrop at 6 D. Orthographic: pixels of the footprint,
// the plane pushed back by its largest depth change from the centre to a corner (so its depth is
// at least D everywhere), near and far planes around it.
TurnedFrame turned_frame(double footprint_mm, bool is_orthographic, int width, int height, const Vec3& normal) {
  TurnedFrame f;
  const double fovy = turned_plane_fovy_degrees(width, height);
  const double facing = footprint_distance(footprint_mm, height, is_orthographic ? kFovyDegrees : fovy);
  double distance = facing;
  if (is_orthographic) {
    const double hx = 0.5e-3 * footprint_mm * width, hy = 0.5e-3 * footprint_mm * height;
    const double extent = (std::fabs(normal.x) * hx + std::fabs(normal.y) * hy) / normal.z;
    distance = facing + extent;
    const double far_plane = distance + extent + facing;
    f.projection = to_double(to_float(orthographic(-hx, hx, -hy, hy, 0.5 * facing, far_plane)));
    f.max_distance = 2.0 * far_plane;  // the plane never reaches it
    f.backdrop_distance = 0.75 * far_plane;
  } else {
    f.projection = make_pinhole(width, height, fovy * kPi / 180.0, 0.2 * facing, 8.0 * facing).projection;
    f.max_distance = 4.0 * facing;
    f.backdrop_distance = 6.0 * facing;
  }
  f.point = {0.0, 0.0, -distance};
  f.normal = normal;
  Vec3 origin, direction;
  window_ray(f.projection, width, height, 0.5 * width, 0.5 * height, &origin, &direction);
  f.centre = origin + direction * plane_hit(origin, direction, f.point, normal);
  return f;
}

// The light at surface coordinates (mm along the turn axis, mm across it from the centre): the
// shadow edge along the axis, lit where across < 0, and the spot on the lit side.
double turned_plane_light(double along_mm, double across_mm) {
  const double dy = across_mm + kTurnedSpotOffsetMm;
  if (along_mm * along_mm + dy * dy <= kSpotRadiusMm * kSpotRadiusMm) return kTurnedSpotLight;
  return across_mm < 0.0 ? kLit : kDark;
}

// Pixel (i, j)'s light: the mean over 4x4 rays through it, each where it meets the plane (rays that
// miss, at the horizon, are left out).
double turned_pixel_light(const TurnedFrame& f, int width, int height, int i, int j) {
  constexpr int kSub = 4;
  double sum = 0.0;
  int hits = 0;
  for (int a = 0; a < kSub; ++a) {
    for (int b = 0; b < kSub; ++b) {
      Vec3 origin, direction;
      window_ray(f.projection, width, height, i + (a + 0.5) / kSub, j + (b + 0.5) / kSub, &origin, &direction);
      const double d = plane_hit(origin, direction, f.point, f.normal);
      if (d <= 0.0) continue;
      const Vec3 p = origin + direction * d - f.centre;
      sum += turned_plane_light(1e3 * dot(p, f.along), 1e3 * dot(p, f.across));
      ++hits;
    }
  }
  return hits > 0 ? sum / hits : kDark;
}

std::string degrees_label(double degrees) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", degrees);
  return text;
}

}  // namespace

Scene make_turned_plane_scene(double footprint_mm, double turn_degrees, double axis_degrees, bool orthographic_camera,
                              int width, int height, PlaneGeometry* plane) {
  const double t = turn_degrees * kPi / 180.0, a = axis_degrees * kPi / 180.0;
  // The normal (0, 0, 1) turned by t about the screen axis `along` (Rodrigues' formula).
  const Vec3 along{std::cos(a), std::sin(a), 0.0};
  const Vec3 normal{std::sin(t) * std::sin(a), -std::sin(t) * std::cos(a), std::cos(t)};
  TurnedFrame f = turned_frame(footprint_mm, orthographic_camera, width, height, normal);
  f.along = along;
  f.across = cross(normal, along);
  const std::string name = "turned-" + degrees_label(turn_degrees) + "-about-" + degrees_label(axis_degrees) +
                           (orthographic_camera ? "-orthographic" : "-perspective");
  Scene s = scene_for_projection(name, width, height, f.projection);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      Vec3 origin, direction;
      window_ray(f.projection, width, height, i + 0.5, j + 0.5, &origin, &direction);
      const double d = plane_hit(origin, direction, f.point, f.normal);
      if (d <= 0.0 || d > f.max_distance) {
        set_pixel(s, f.projection, i, j, 0.3, 0.3, 0.3, false, f.backdrop_distance);
        continue;
      }
      const double e = texture_albedo(i, j) * turned_pixel_light(f, width, height, i, j);
      set_pixel(s, f.projection, i, j, e, e, e, true, d);
    }
  }
  if (plane != nullptr) {
    plane->point = {f.point.x, f.point.y, f.point.z};
    plane->normal = {normal.x, normal.y, normal.z};
  }
  return s;
}

namespace {

// The view distance t where the ray t · ray (from the eye) first meets the cylinder of radius r
// around the line through `centre` along the unit `axis` (centre · axis = 0); -1 where it misses.
double cylinder_hit(const Vec3& ray, const Vec3& centre, const Vec3& axis, double r) {
  const Vec3 ray_across = ray - axis * dot(ray, axis);  // the parts off the axis' direction
  const double qa = dot(ray_across, ray_across), qb = -2.0 * dot(ray_across, centre);
  const double qc = dot(centre, centre) - r * r;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0.0 || qa <= 0.0) return -1.0;
  return (-qb - std::sqrt(disc)) / (2.0 * qa);
}

}  // namespace

Scene make_cylinder_scene(double footprint_mm, int width, int height) {
  const double facing = footprint_distance(footprint_mm, height), r = kTurnSweepRadius;
  const PinholeCamera camera = make_pinhole(width, height, kFovyDegrees * kPi / 180.0, 0.5 * facing, facing + 6.0 * r);
  Scene s = scene_for_camera("cylinder", camera);
  const double tilt = 20.0 * kPi / 180.0, light_angle = 86.0 * kPi / 180.0;
  const Vec3 axis{std::sin(tilt), std::cos(tilt), 0.0}, centre{0.0, 0.0, -(facing + r)};
  // Towards the light: across the axis, 86 degrees from the view direction, so the terminator runs
  // along the cylinder where its normal is 4 degrees off the view direction.
  const Vec3 across = normalize(cross(axis, Vec3{0.0, 0.0, 1.0}));
  const Vec3 light = Vec3{0.0, 0.0, std::cos(light_angle)} + across * std::sin(light_angle);
  // The cast shadow's edge across the cylinder through its nearest point: the shadow plane holds the
  // light and `across`, so it is the plane normal to the axis (a ring round the cylinder), and the
  // lit side is cut into a lit and a shadowed half (the half towards -axis, below on screen).
  const CastShadow shadow = cast_shadow(Vec3{0.0, 0.0, -facing}, light, across);
  const auto hit_of = [&](const Vec3& ray) { return cylinder_hit(ray, centre, axis, r); };
  const double albedo[3] = {0.85, 0.6, 0.5}, ambient = 0.03, backdrop = 0.3;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const Vec3 ray = camera.ray(i, j);
      const double hit = hit_of(ray);
      if (hit <= 0.0) {
        set_pixel(s, camera, i, j, backdrop, backdrop, backdrop, false, facing + 3.0 * r);
        continue;
      }
      const Vec3 off_axis = ray * hit - centre;
      const Vec3 normal = normalize(off_axis - axis * dot(off_axis, axis));
      const double key = unshadowed_share(camera.projection, width, height, i, j, hit_of, shadow);
      const double lit = texture_albedo(i, j) * (std::max(0.0, dot(normal, light)) * key + ambient);
      set_pixel(s, camera, i, j, albedo[0] * lit, albedo[1] * lit, albedo[2] * lit, true, hit);
    }
  }
  return s;
}

Scene make_footprint_sphere_scene(double footprint_mm, int width, int height) {
  const double facing = footprint_distance(footprint_mm, height);
  if (!(facing + 2.0 * kTurnSweepRadius < kSphereBackdropDistance)) {
    throw std::invalid_argument("make_footprint_sphere_scene: " + std::to_string(footprint_mm) + " mm per pixel in " +
                                std::to_string(height) + " rows puts the sphere at " + std::to_string(facing) +
                                " m, through the sphere scene's backdrop");
  }
  // The cast shadow's edge through the nearest point (the image centre), 30 degrees below screen x
  // there: it crosses the lit side from limb to limb, 59 degrees from the direction the light
  // changes in (its screen projection), and shadows the side away from the light (below left), so
  // the terminator stays in view beyond the lit part.
  const double edge = -30.0 * kPi / 180.0;
  const CastShadow shadow = cast_shadow(Vec3{0.0, 0.0, -facing}, kSphereLight, Vec3{std::cos(edge), std::sin(edge), 0.0});
  return sphere_scene("sphere-40mm", width, height, false, kTurnSweepRadius, facing + kTurnSweepRadius, 0.5 * facing,
                      &shadow);
}

}  // namespace sss_bench::detail
