#include "whole_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace sss_bench {

namespace {

constexpr double kPi = 3.14159265358979323846;


// 21 bits per axis, centred: cells -2^20 .. 2^20 - 1.
constexpr std::int64_t kCellOffset = 1 << 20;

std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  const auto field = [](std::int64_t v) {
    return static_cast<std::uint64_t>(std::clamp<std::int64_t>(v + kCellOffset, 0, 2 * kCellOffset - 1));
  };
  return (field(x) << 42) | (field(y) << 21) | field(z);
}

std::int64_t cell_index(double v, double cell) { return static_cast<std::int64_t>(std::floor(v / cell)); }

// *values reordered so that element k is the old element order[k].
template <typename T>
void permute(std::vector<T>* values, const std::vector<std::uint32_t>& order) {
  std::vector<T> sorted;
  sorted.reserve(values->size());
  for (const std::uint32_t i : order) sorted.push_back((*values)[i]);
  values->swap(sorted);
}

}  // namespace

Point3 SurfaceMesh::vertex(std::size_t triangle, int corner) const {
  const float* v = vertices + static_cast<std::size_t>(indices[triangle * 3 + static_cast<std::size_t>(corner)]) * floats_per_vertex;
  return {v[0], v[1], v[2]};
}

Point3 surface_position(const SurfaceMesh& mesh, const SurfacePoint& p) {
  const Point3 a = mesh.vertex(p.triangle, 0), b = mesh.vertex(p.triangle, 1), c = mesh.vertex(p.triangle, 2);
  const double b0 = 1.0 - static_cast<double>(p.b1) - static_cast<double>(p.b2);
  Point3 out{};
  for (std::size_t k = 0; k < 3; ++k) out[k] = b0 * a[k] + p.b1 * b[k] + p.b2 * c[k];
  return out;
}

Point3 triangle_normal(const SurfaceMesh& mesh, std::size_t triangle) {
  const Point3 a = mesh.vertex(triangle, 0);
  const Point3 n = point_cross(point_sub(mesh.vertex(triangle, 1), a), point_sub(mesh.vertex(triangle, 2), a));
  const double length = std::sqrt(point_dot(n, n));
  if (!(length > 0.0)) return {0.0, 0.0, 0.0};
  return {n[0] / length, n[1] / length, n[2] / length};
}

SurfaceSampling sample_surface(const SurfaceMesh& mesh, double spacing, const std::vector<std::uint8_t>* keep) {
  if (!(spacing > 0.0)) throw std::invalid_argument("sample_surface: spacing must be positive, got " + std::to_string(spacing));
  SurfaceSampling out;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (keep != nullptr && (*keep)[t] == 0) continue;
    const Point3 a = mesh.vertex(t, 0), b = mesh.vertex(t, 1), c = mesh.vertex(t, 2);
    const Point3 ab = point_sub(b, a), ac = point_sub(c, a), bc = point_sub(c, b);
    const Point3 n = point_cross(ab, ac);
    const double area = 0.5 * std::sqrt(point_dot(n, n));
    if (!(area > 0.0)) continue;
    const double longest = std::sqrt(std::max({point_dot(ab, ab), point_dot(ac, ac), point_dot(bc, bc)}));
    const int divisions = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
    const double sub_area = area / (static_cast<double>(divisions) * divisions);
    const double step = 1.0 / divisions;
    // The lattice of the n² sub-triangles in barycentric (b1, b2): n(n+1)/2 pointing one way,
    // centroids at ((i + 1/3) / n, (j + 1/3) / n), and n(n-1)/2 the other, at ((i + 2/3) / n, (j + 2/3) / n).
    for (int i = 0; i < divisions; ++i) {
      for (int j = 0; i + j < divisions; ++j) {
        out.points.push_back({static_cast<std::uint32_t>(t), static_cast<float>((i + 1.0 / 3.0) * step),
                              static_cast<float>((j + 1.0 / 3.0) * step)});
        out.area.push_back(sub_area);
        if (i + j < divisions - 1) {
          out.points.push_back({static_cast<std::uint32_t>(t), static_cast<float>((i + 2.0 / 3.0) * step),
                                static_cast<float>((j + 2.0 / 3.0) * step)});
          out.area.push_back(sub_area);
        }
      }
    }
  }
  return out;
}

TermSamples term_samples(const SurfaceMesh& mesh, const SurfaceSampling& sampling) {
  TermSamples s;
  s.position.reserve(sampling.points.size());
  s.normal.reserve(sampling.points.size());
  for (const SurfacePoint& p : sampling.points) {
    s.position.push_back(surface_position(mesh, p));
    s.normal.push_back(triangle_normal(mesh, p.triangle));
  }
  s.area = sampling.area;
  return s;
}

std::uint64_t cell_key(const Point3& p, double cell) {
  return pack(cell_index(p[0], cell), cell_index(p[1], cell), cell_index(p[2], cell));
}

WholeSurfaceReference::WholeSurfaceReference(WholeSurfaceSettings settings) : settings_(std::move(settings)) {
  const int terms = static_cast<int>(settings_.profile.size());
  if (terms == 0 || settings_.analytic_terms < 0 || settings_.analytic_terms > terms ||
      !(settings_.spacing_per_sigma > 0.0) || !(settings_.cutoff_sigmas > 0.0) || !(settings_.world_units_per_mm > 0.0)) {
    throw std::invalid_argument("WholeSurfaceReference: bad settings (" + std::to_string(terms) + " terms, analytic_terms " +
                                std::to_string(settings_.analytic_terms) + ", spacing_per_sigma " +
                                std::to_string(settings_.spacing_per_sigma) + ", cutoff_sigmas " +
                                std::to_string(settings_.cutoff_sigmas) + ")");
  }
  terms_.resize(settings_.profile.size());
}

double WholeSurfaceReference::term_width(std::size_t term) const {
  return std::sqrt(settings_.profile.at(term).variance_mm2) * settings_.world_units_per_mm;
}

double WholeSurfaceReference::term_spacing(std::size_t term) const { return settings_.spacing_per_sigma * term_width(term); }

double WholeSurfaceReference::term_cutoff(std::size_t term) const { return settings_.cutoff_sigmas * term_width(term); }

void WholeSurfaceReference::set_samples(std::size_t term, TermSamples samples) {
  const std::size_t n = samples.position.size();
  if (term >= terms_.size() || analytic(term) || samples.area.size() != n || samples.normal.size() != n ||
      samples.light.exact.size() != n || samples.light.pixels.size() != n || samples.light.visible.size() != n) {
    throw std::invalid_argument("WholeSurfaceReference::set_samples: term " + std::to_string(term) +
                                " is analytic, out of range or its sample arrays differ in size");
  }
  Buckets& b = terms_[term];
  b.cell = term_cutoff(term);
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = cell_key(samples.position[i], b.cell);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return key[x] < key[y]; });
  b.keys.clear();
  b.begin.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = order[k];
    if (b.keys.empty() || b.keys.back() != key[i]) {
      b.keys.push_back(key[i]);
      b.begin.push_back(static_cast<std::uint32_t>(k));
    }
  }
  b.begin.push_back(static_cast<std::uint32_t>(n));
  // One array at a time, so that a term of tens of millions of samples is never held twice.
  permute(&samples.position, order);
  permute(&samples.area, order);
  permute(&samples.normal, order);
  permute(&samples.light.exact, order);
  permute(&samples.light.pixels, order);
  permute(&samples.light.visible, order);
  b.samples = std::move(samples);
  b.ready = true;
}

WholeSurfaceValue WholeSurfaceReference::at(const Receiver& receiver, const Point3& normal) const {
  WholeSurfaceValue v;
  const double mm2_per_world2 = 1.0 / (settings_.world_units_per_mm * settings_.world_units_per_mm);
  double opposite = 0.0, total = 0.0;  // mass summed over channels, for opposite_share
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    const sss::math::GaussianTerm& term = settings_.profile[t];
    if (analytic(t)) {
      for (std::size_t c = 0; c < 3; ++c) {
        const double w = term.weight[c];
        v.exact[c] += w * receiver.light[c];
        v.pixels[c] += w * receiver.light[c];
        v.visible[c] += w * receiver.light[c];
        v.mass[c] += w;
        v.visible_mass[c] += w;
        total += w;
      }
      continue;
    }
    const Buckets& b = terms_[t];
    if (!b.ready) throw std::logic_error("WholeSurfaceReference::at: term " + std::to_string(t) + " has no samples");
    const double cutoff2 = b.cell * b.cell;
    const double inv_two_v = 0.5 / term.variance_mm2 * mm2_per_world2;  // per world unit²
    const double norm = mm2_per_world2 / (2.0 * kPi * term.variance_mm2);  // 1/(2πv), per world unit²
    std::array<double, 3> exact{}, pixels{}, visible{};
    double mass = 0.0, visible_mass = 0.0, away = 0.0;
    const std::int64_t cx = cell_index(receiver.position[0], b.cell), cy = cell_index(receiver.position[1], b.cell),
                       cz = cell_index(receiver.position[2], b.cell);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const std::uint64_t key = pack(cx + dx, cy + dy, cz + dz);
          const auto found = std::lower_bound(b.keys.begin(), b.keys.end(), key);
          if (found == b.keys.end() || *found != key) continue;
          const std::size_t k = static_cast<std::size_t>(found - b.keys.begin());
          for (std::size_t i = b.begin[k]; i < b.begin[k + 1]; ++i) {
            const Point3 d = point_sub(b.samples.position[i], receiver.position);
            const double r2 = point_dot(d, d);
            if (r2 > cutoff2) continue;
            const double g = std::exp(-r2 * inv_two_v) * norm * b.samples.area[i];
            const auto& e = b.samples.light.exact[i];
            const auto& p = b.samples.light.pixels[i];
            for (std::size_t c = 0; c < 3; ++c) {
              exact[c] += g * e[c];
              pixels[c] += g * p[c];
            }
            mass += g;
            if (b.samples.light.visible[i] != 0) {
              for (std::size_t c = 0; c < 3; ++c) visible[c] += g * p[c];
              visible_mass += g;
            }
            if (point_dot(b.samples.normal[i], normal) < 0.0) away += g;
          }
        }
      }
    }
    for (std::size_t c = 0; c < 3; ++c) {
      const double w = term.weight[c];
      v.exact[c] += w * exact[c];
      v.pixels[c] += w * pixels[c];
      v.visible[c] += w * visible[c];
      v.mass[c] += w * mass;
      v.visible_mass[c] += w * visible_mass;
      opposite += w * away;
      total += w * mass;
    }
  }
  for (std::size_t c = 0; c < 3; ++c) {
    if (v.visible_mass[c] > 0.0) v.visible[c] *= v.mass[c] / v.visible_mass[c];
  }
  v.opposite_share = total > 0.0 ? opposite / total : 0.0;
  return v;
}

}  // namespace sss_bench
