#include "whole_surface_frame.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "math/exact_reference.hpp"
#include "math/half_float.hpp"
#include "pixel_light.hpp"
#include "scenes/head_asset.hpp"

namespace sss_bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// View to world: the rotation's transpose after removing the translation.
Point3 to_world(const detail::Mat4& m, const Point3& v) {
  const Point3 q = {v[0] - m[12], v[1] - m[13], v[2] - m[14]};
  return {m[0] * q[0] + m[1] * q[1] + m[2] * q[2], m[4] * q[0] + m[5] * q[1] + m[6] * q[2],
          m[8] * q[0] + m[9] * q[1] + m[10] * q[2]};
}

// Per triangle, whether any receiver lies within `reach` of it (its centroid's distance less its
// circumradius): the triangles a term's samples must cover.
std::vector<std::uint8_t> triangles_within(const SurfaceMesh& mesh, const std::vector<Point3>& receivers, double reach) {
  const double cell = reach;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t i = 0; i < receivers.size(); ++i) grid[cell_key(receivers[i], cell)].push_back(static_cast<std::uint32_t>(i));
  std::vector<std::uint8_t> keep(mesh.triangle_count(), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Point3 a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
    const Point3 centre = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    double radius = 0.0;
    for (const Point3& v : {a, b, c}) radius = std::max(radius, std::sqrt(point_dot(point_sub(v, centre), point_sub(v, centre))));
    const double limit = reach + radius;
    const int span = static_cast<int>(std::ceil(limit / cell));
    for (int dx = -span; dx <= span && keep[t] == 0; ++dx) {
      for (int dy = -span; dy <= span && keep[t] == 0; ++dy) {
        for (int dz = -span; dz <= span && keep[t] == 0; ++dz) {
          const Point3 probe = {centre[0] + dx * cell, centre[1] + dy * cell, centre[2] + dz * cell};
          const auto found = grid.find(cell_key(probe, cell));
          if (found == grid.end()) continue;
          for (std::uint32_t r : found->second) {
            const Point3 d = point_sub(receivers[r], centre);
            if (point_dot(d, d) <= limit * limit) {
              keep[t] = 1;
              break;
            }
          }
        }
      }
    }
  }
  return keep;
}

// The receiver's normal from its neighbours' surface points (the smaller step on each axis).
Point3 pixel_normal(const Scene& s, const detail::Mat4& view, std::size_t pixel) {
  const int x = static_cast<int>(pixel % static_cast<std::size_t>(s.width));
  const int y = static_cast<int>(pixel / static_cast<std::size_t>(s.width));
  const Point3 centre = pixel_world_point(s, view, pixel);
  Point3 axis[2] = {};
  for (int a = 0; a < 2; ++a) {
    const int dx = a == 0 ? 1 : 0, dy = a == 0 ? 0 : 1;
    double best = -1.0;
    for (int sign : {-1, 1}) {
      const int nx = x + sign * dx, ny = y + sign * dy;
      if (nx < 0 || ny < 0 || nx >= s.width || ny >= s.height || s.mask[pixel_index(s, nx, ny)] == 0) continue;
      const Point3 d = point_sub(pixel_world_point(s, view, pixel_index(s, nx, ny)), centre);
      const double step = std::fabs(s.distance[pixel_index(s, nx, ny)] - s.distance[pixel]);
      if (best < 0.0 || step < best) {
        best = step;
        axis[a] = {d[0] * sign, d[1] * sign, d[2] * sign};
      }
    }
  }
  Point3 n = point_cross(axis[0], axis[1]);
  const double length = std::sqrt(point_dot(n, n));
  if (!(length > 0.0)) return {0.0, 0.0, 0.0};
  n = {n[0] / length, n[1] / length, n[2] / length};
  // Towards the camera: the eye is at the view's origin.
  const Point3 eye = to_world(view, {0.0, 0.0, 0.0});
  if (point_dot(n, point_sub(eye, centre)) < 0.0) n = {-n[0], -n[1], -n[2]};
  return n;
}

}  // namespace

Point3 pixel_world_point(const Scene& s, const detail::Mat4& view, std::size_t pixel) {
  const int x = static_cast<int>(pixel % static_cast<std::size_t>(s.width));
  const int y = static_cast<int>(pixel / static_cast<std::size_t>(s.width));
  const double d = s.distance[pixel];
  const double ndc_x = (x + 0.5) / s.width * 2.0 - 1.0, ndc_y = (y + 0.5) / s.height * 2.0 - 1.0;
  return to_world(view, {ndc_x * d / s.projection[0], ndc_y * d / s.projection[5], -d});
}

WholeSurfaceFrame make_whole_surface_frame(const std::string& name, const detail::HeadView& view,
                                           const WholeSurfaceFrameSettings& settings) {
  const auto start = Clock::now();
  WholeSurfaceFrame frame;
  detail::Mat4 projection{};
  detail::head_camera(view, settings.width, settings.height, &projection, &frame.view_matrix);

  const detail::HeadAsset& asset = detail::head_asset();
  SurfaceMesh mesh;
  mesh.vertices = asset.vertices.data();
  mesh.floats_per_vertex = detail::HeadAsset::kFloatsPerVertex;
  mesh.indices = asset.indices.data();
  mesh.index_count = asset.indices.size();
  WholeSurfaceSettings ws;
  ws.profile = sss::math::skin_profile_terms();
  ws.spacing_per_sigma = settings.spacing_per_sigma;
  ws.analytic_terms = settings.analytic_terms;
  std::unique_ptr<WholeSurfaceReference> reference;
  std::vector<Point3> receivers;
  std::vector<SurfaceSampling> samplings;

  // Chosen from the rendered frame, before its points pass: the receivers (the translucent pixels
  // of the grid) and every numerical term's samples where they can reach one, lit in one pass.
  const auto points_of = [&](const Scene& scene) {
    for (int y = settings.stride / 2; y < scene.height; y += settings.stride) {
      for (int x = settings.stride / 2; x < scene.width; x += settings.stride) {
        const std::size_t i = pixel_index(scene, x, y);
        if (scene.mask[i] == 0) continue;
        frame.pixels.push_back(i);
        receivers.push_back(pixel_world_point(scene, frame.view_matrix, i));
        frame.normals.push_back(pixel_normal(scene, frame.view_matrix, i));
      }
    }
    ws.world_units_per_mm = scene.world_units_per_mm;
    reference = std::make_unique<WholeSurfaceReference>(ws);
    samplings.assign(reference->term_count(), SurfaceSampling{});
    std::vector<SurfacePoint> all_points;
    for (std::size_t t = 0; t < reference->term_count(); ++t) {
      if (reference->analytic(t)) continue;
      const std::vector<std::uint8_t> keep = triangles_within(mesh, receivers, reference->term_cutoff(t));
      samplings[t] = sample_surface(mesh, reference->term_spacing(t), &keep);
      all_points.insert(all_points.end(), samplings[t].points.begin(), samplings[t].points.end());
    }
    return all_points;
  };
  std::vector<std::array<float, 3>> light;
  frame.scene = detail::render_head_scene(name, settings.width, settings.height, view, points_of, &light);
  Scene& scene = frame.scene;
  // What a filter is handed: the host's RGBA16F colour. The pixels' light is read from it, so the
  // pixel-consistent answer's floor includes the colour's rounding (at most 2^-11 relative).
  for (float& v : scene.irradiance) v = sss::math::round_to_half(v);
  frame.render_seconds = seconds_since(start);

  std::size_t first = 0;
  for (std::size_t t = 0; t < reference->term_count(); ++t) {
    if (reference->analytic(t)) continue;
    TermSamples samples = term_samples(mesh, samplings[t]);
    samplings[t] = SurfaceSampling{};  // its positions are in `samples` now: free them before the next term
    const std::size_t n = samples.position.size();
    samples.light.exact.assign(light.begin() + static_cast<std::ptrdiff_t>(first),
                               light.begin() + static_cast<std::ptrdiff_t>(first + n));
    samples.light.pixels = samples.light.exact;
    samples.light.visible.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const PixelLight p = light_from_pixels(scene, frame.view_matrix, samples.position[i]);
      if (!p.visible) continue;
      samples.light.visible[i] = 1;
      samples.light.pixels[i] = p.light;
      ++frame.visible_samples;
    }
    frame.samples += n;
    first += n;
    reference->set_samples(t, std::move(samples));
  }

  const auto convolve = Clock::now();
  frame.values.resize(frame.pixels.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next++) < frame.pixels.size();) {
      Receiver r;
      r.position = receivers[i];
      for (std::size_t c = 0; c < 3; ++c) r.light[c] = scene.irradiance[frame.pixels[i] * 4 + c];
      frame.values[i] = reference->at(r, frame.normals[i]);
    }
  };
  std::thread helper(work);
  work();
  helper.join();
  frame.reference_seconds = seconds_since(convolve);
  return frame;
}

}  // namespace sss_bench
