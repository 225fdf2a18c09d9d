#include "regions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "math/plane_reference.hpp"

namespace sss_bench {

double profile_tail_share(const sss::math::GaussianProfile& profile, double r_mm) {
  double worst = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    double share = 0.0;
    for (const auto& t : profile) share += t.weight[c] * std::exp(-r_mm * r_mm / (2.0 * t.variance_mm2));
    worst = std::max(worst, share);
  }
  return worst;
}

double profile_reach_mm(const sss::math::GaussianProfile& profile, double tail) {
  if (!(tail > 0.0 && tail < 1.0)) throw std::invalid_argument("profile_reach_mm: tail must be in (0, 1), got " + std::to_string(tail));
  double lo = 0.0, hi = 1.0;
  while (profile_tail_share(profile, hi) > tail) hi *= 2.0;
  while (hi - lo > 1e-9) {
    const double mid = 0.5 * (lo + hi);
    (profile_tail_share(profile, mid) > tail ? lo : hi) = mid;
  }
  return hi;
}

namespace {

void check(const RegionInput& in) {
  if (in.width < 1 || in.height < 1 || in.mask == nullptr || in.distance == nullptr || !(in.reach_mm > 0.0) ||
      !(in.world_units_per_mm > 0.0)) {
    throw std::invalid_argument("regions: bad input (size " + std::to_string(in.width) + "x" + std::to_string(in.height) +
                                ", reach " + std::to_string(in.reach_mm) + " mm, world_units_per_mm " +
                                std::to_string(in.world_units_per_mm) + ")");
  }
}

}  // namespace

std::vector<double> pixel_footprints_mm(const RegionInput& in) {
  check(in);
  const std::size_t n = static_cast<std::size_t>(in.width) * static_cast<std::size_t>(in.height);
  sss::math::Matrix4 m{};
  std::copy(in.projection.begin(), in.projection.end(), m.begin());
  std::vector<double> pixel_mm(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (in.mask[i] == 0) continue;
    const double d = in.distance[i];
    pixel_mm[i] = std::min(sss::math::plane_pixel_mm_x(m, in.width, d, in.world_units_per_mm),
                           sss::math::plane_pixel_mm_y(m, in.height, d, in.world_units_per_mm));
  }
  return pixel_mm;
}

double median_footprint_mm(const RegionInput& in) {
  const std::vector<double> all = pixel_footprints_mm(in);
  std::vector<double> translucent;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (in.mask[i] != 0) translucent.push_back(all[i]);
  }
  if (translucent.empty()) return 0.0;
  const auto middle = translucent.begin() + static_cast<std::ptrdiff_t>(translucent.size() / 2);
  std::nth_element(translucent.begin(), middle, translucent.end());
  return *middle;
}

namespace {

std::size_t pixel_index(int width, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
}

// Silhouette pixels (regions.hpp): non-translucent ones, and with `depth_steps` translucent ones
// at a depth step.
std::vector<uint8_t> edge_pixels(const RegionInput& in, const std::vector<double>& pixel_mm, bool depth_steps) {
  const int w = in.width, h = in.height;
  std::vector<uint8_t> edge(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = pixel_index(w, x, y);
      if (in.mask[i] == 0) {
        edge[i] = 1;
        continue;
      }
      if (!depth_steps) continue;
      const double limit = 4.0 * pixel_mm[i] * in.world_units_per_mm;  // world units
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4 && edge[i] == 0; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h || in.mask[pixel_index(w, nx[k], ny[k])] == 0) continue;
        if (std::fabs(static_cast<double>(in.distance[pixel_index(w, nx[k], ny[k])]) - in.distance[i]) > limit) edge[i] = 1;
      }
    }
  }
  return edge;
}

// Per translucent pixel: its region, with "near an edge" meaning within the reach of an `edge`
// pixel (silhouette) and border as regions.hpp says.
std::vector<uint8_t> classify_by_edges(const RegionInput& in, const std::vector<double>& pixel_mm,
                                       const std::vector<uint8_t>& edge) {
  const int w = in.width, h = in.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  // Per row, the column offset to the nearest edge pixel in that row (large when none).
  constexpr int kFar = std::numeric_limits<int>::max() / 4;
  std::vector<int> nearest(n, kFar);
  for (int y = 0; y < h; ++y) {
    int last = -kFar;
    for (int x = 0; x < w; ++x) {
      if (edge[pixel_index(w, x, y)] != 0) last = x;
      nearest[pixel_index(w, x, y)] = x - last;
    }
    last = 2 * kFar;
    for (int x = w - 1; x >= 0; --x) {
      if (edge[pixel_index(w, x, y)] != 0) last = x;
      nearest[pixel_index(w, x, y)] = std::min(nearest[pixel_index(w, x, y)], last - x);
    }
  }
  std::vector<uint8_t> regions(n, static_cast<uint8_t>(Region::none));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = pixel_index(w, x, y);
      if (in.mask[i] == 0) continue;
      const double reach = in.reach_mm / pixel_mm[i];  // pixels
      const double to_frame = std::min({x + 0.5, w - x - 0.5, y + 0.5, h - y - 0.5});
      if (to_frame < reach) {
        regions[i] = static_cast<uint8_t>(Region::border);
        continue;
      }
      // Rows within the reach (all inside the frame, as the pixel is not in the border).
      const int rows = static_cast<int>(std::floor(reach));
      bool near_edge = false;
      for (int dy = -rows; dy <= rows && !near_edge; ++dy) {
        const double dx = nearest[pixel_index(w, x, y + dy)];
        near_edge = dx * dx + static_cast<double>(dy) * dy <= reach * reach;
      }
      regions[i] = static_cast<uint8_t>(near_edge ? Region::silhouette : Region::interior);
    }
  }
  return regions;
}

}  // namespace

std::vector<uint8_t> classify_regions(const RegionInput& in) {
  check(in);
  const std::vector<double> pixel_mm = pixel_footprints_mm(in);
  return classify_by_edges(in, pixel_mm, edge_pixels(in, pixel_mm, true));
}

std::vector<uint8_t> classify_regions_with_depth_edges(const RegionInput& in) {
  check(in);
  const std::vector<double> pixel_mm = pixel_footprints_mm(in);
  std::vector<uint8_t> regions = classify_by_edges(in, pixel_mm, edge_pixels(in, pixel_mm, true));
  const std::vector<uint8_t> outline = classify_by_edges(in, pixel_mm, edge_pixels(in, pixel_mm, false));
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (regions[i] == static_cast<uint8_t>(Region::silhouette) && outline[i] == static_cast<uint8_t>(Region::interior))
      regions[i] = static_cast<uint8_t>(Region::depth_edge);
  }
  return regions;
}

std::vector<uint8_t> region_mask(const std::vector<uint8_t>& regions, Region r) {
  std::vector<uint8_t> mask(regions.size());
  for (std::size_t i = 0; i < regions.size(); ++i) mask[i] = regions[i] == static_cast<uint8_t>(r) ? 1 : 0;
  return mask;
}

}  // namespace sss_bench
