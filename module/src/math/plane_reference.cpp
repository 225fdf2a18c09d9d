#include "plane_reference.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <thread>

#include "surface.hpp"

namespace sss::math {

namespace {

// ½ [erf(b) - erf(a)] for a <= b, through erfc on the side of 0 where both lie so that a far tail
// is not the difference of two numbers near 1.
double half_erf_difference(double a, double b) {
  if (a >= 0.0) return 0.5 * (std::erfc(a) - std::erfc(b));
  if (b <= 0.0) return 0.5 * (std::erfc(-b) - std::erfc(-a));
  return 0.5 * (std::erf(b) - std::erf(a));
}

// Taps lighter than this are skipped: the kernel is symmetric and decreasing away from its centre,
// so the skipped ones (at most a few thousand per pass) hold less than 1e-14 of the light together,
// below what the double sums round away (the comparison with the 2D reference in
// plane_reference_test.cpp reads the same 2.3e-13 and 3.1e-15 with or without them).
constexpr double kNegligibleWeight = 1e-18;

// The half-width beyond which every value of k (centred, 2·radius + 1 values) is negligible.
int significant_radius(const std::vector<double>& k) {
  const int radius = static_cast<int>(k.size() / 2);
  int r = radius;
  while (r > 0 && k[static_cast<std::size_t>(radius + r)] < kNegligibleWeight &&
         k[static_cast<std::size_t>(radius - r)] < kNegligibleWeight) {
    --r;
  }
  return r;
}

// One axis of one term on a width x height plane (row-major): out = k * in along x (axis 0) or y
// (axis 1). Written as one scaled row or run added per tap offset, so every inner loop walks memory
// in order and vectorises; k is centred with at least (the axis length - 1) values on each side.
void convolve_axis(const std::vector<double>& k, int axis, int width, int height, const std::vector<double>& in,
                   std::vector<double>* out) {
  const int centre = static_cast<int>(k.size() / 2);
  const int count = axis == 0 ? width : height;
  const int reach = std::min(significant_radius(k), count - 1);
  std::fill(out->begin(), out->end(), 0.0);
  const auto w = static_cast<std::size_t>(width);
  for (int d = -reach; d <= reach; ++d) {
    const double weight = k[static_cast<std::size_t>(centre + d)];
    if (weight < kNegligibleWeight) continue;
    // Receivers i with a source i + d inside [0, count).
    const int i0 = std::max(0, -d), i1 = std::min(count, count - d);
    if (axis == 0) {
      const auto n = static_cast<std::size_t>(i1 - i0);
      for (int y = 0; y < height; ++y) {
        // Receivers i0 .. i1 - 1 of row y and their sources i0 + d .. i1 - 1 + d, all inside the row.
        const double* src = in.data() + static_cast<std::size_t>(y) * w + static_cast<std::size_t>(i0 + d);
        double* dst = out->data() + static_cast<std::size_t>(y) * w + static_cast<std::size_t>(i0);
        for (std::size_t x = 0; x < n; ++x) dst[x] += weight * src[x];
      }
    } else {
      for (int y = i0; y < i1; ++y) {
        const double* src = in.data() + static_cast<std::size_t>(y + d) * w;
        double* dst = out->data() + static_cast<std::size_t>(y) * w;
        for (std::size_t x = 0; x < w; ++x) dst[x] += weight * src[x];
      }
    }
  }
}

// The turned plane's kernel: the terms' weights K_b · K_a summed per channel, on the offsets
// Δi in [-reach_x, reach_x] and Δj in [-reach_y, reach_y] (row-major by Δj), with each row's span
// of non-zero taps, so that the convolution walks only those.
struct ShearedKernel {
  int reach_x = 0, reach_y = 0;
  std::array<std::vector<double>, 3> weight;
  std::vector<int> first, last;  // per row (Δj + reach_y): the span in Δi; first > last when empty
  std::array<bool, 3> used{};    // a channel with no weight at all is left at 0

  std::size_t row_index(int dj) const { return static_cast<std::size_t>(dj + reach_y); }
  const double* row(std::size_t channel, int dj) const {
    return weight[channel].data() + row_index(dj) * static_cast<std::size_t>(2 * reach_x + 1);
  }
};

// Past this many widths √(2v) beyond a pixel's edge a pixel integral is below ½ erfc(6.5) = 2e-20,
// under kNegligibleWeight: the offsets worth evaluating at all.
constexpr double kTailWidths = 6.5;

// The largest offset, in pixels of side `side_mm`, at which the pixel integral of a Gaussian of width
// √(2v) = width_mm centred shift_mm away can reach kNegligibleWeight; at most `limit`.
int offset_bound(double side_mm, double width_mm, double shift_mm, int limit) {
  const double bound = (std::fabs(shift_mm) + 0.5 * side_mm + kTailWidths * width_mm) / side_mm;
  return static_cast<int>(std::min(static_cast<double>(limit), std::ceil(bound)));
}

// One term added into the kernel: w · K_b(Δj) · K_a(Δi, Δj) for every pair of factors not below
// kNegligibleWeight, on the offsets inside the kernel's reach (the frame's).
void add_term(const GaussianTerm& term, const TurnedPlaneFootprint& f, ShearedKernel* k) {
  const double width_mm = std::sqrt(2.0 * term.variance_mm2), s = 1.0 / width_mm;
  const int rows = offset_bound(f.b_mm, width_mm, 0.0, k->reach_y);
  const int half = offset_bound(f.a_mm, width_mm, 0.0, 2 * k->reach_x);  // a row's taps about its centre
  const auto stride = static_cast<std::size_t>(2 * k->reach_x + 1);
  for (int dj = -rows; dj <= rows; ++dj) {
    const double kb = half_erf_difference((dj - 0.5) * f.b_mm * s, (dj + 0.5) * f.b_mm * s);
    if (kb < kNegligibleWeight) continue;
    // The row's taps centre where aΔi + cΔj = 0.
    const double shift = f.c_mm * dj;
    const double centre = -shift / f.a_mm;
    const int lo = std::max(-k->reach_x, static_cast<int>(std::floor(centre)) - half);
    const int hi = std::min(k->reach_x, static_cast<int>(std::ceil(centre)) + half);
    const std::size_t r = k->row_index(dj);
    for (int di = lo; di <= hi; ++di) {
      const double u = f.a_mm * di + shift;
      const double ka = half_erf_difference((u - 0.5 * f.a_mm) * s, (u + 0.5 * f.a_mm) * s);
      if (ka < kNegligibleWeight) continue;
      const std::size_t at = r * stride + static_cast<std::size_t>(di + k->reach_x);
      for (std::size_t c = 0; c < 3; ++c) k->weight[c][at] += term.weight[c] * kb * ka;
      k->first[r] = std::min(k->first[r], di);
      k->last[r] = std::max(k->last[r], di);
    }
  }
}

ShearedKernel sheared_kernel(const GaussianProfile& profile, const TurnedPlaneFootprint& f, int width, int height) {
  ShearedKernel k;
  // The reach: the widest term's, within the frame (no pair of pixels is farther apart).
  for (const GaussianTerm& term : profile) {
    const double width_mm = std::sqrt(2.0 * term.variance_mm2);
    const int rows = offset_bound(f.b_mm, width_mm, 0.0, height - 1);
    k.reach_y = std::max(k.reach_y, rows);
    k.reach_x = std::max(k.reach_x, offset_bound(f.a_mm, width_mm, f.c_mm * rows, width - 1));
    for (std::size_t c = 0; c < 3; ++c) k.used[c] = k.used[c] || term.weight[c] != 0.0;
  }
  const auto rows = static_cast<std::size_t>(2 * k.reach_y + 1);
  for (auto& w : k.weight) w.assign(rows * static_cast<std::size_t>(2 * k.reach_x + 1), 0.0);
  k.first.assign(rows, k.reach_x + 1);
  k.last.assign(rows, -k.reach_x - 1);
  for (const GaussianTerm& term : profile) add_term(term, f, &k);
  return k;
}

// Receivers x0 .. x0 + n - 1 of row y, one channel (its plane e, width x height): Σ over the kernel's
// taps into `row`. One scaled run of a source row added per tap, so the inner loop walks memory in
// order and vectorises.
void convolve_turned_row(const ShearedKernel& k, std::size_t channel, const std::vector<double>& e, int width,
                         int height, int y, int x0, int n, double* row) {
  std::fill(row, row + n, 0.0);
  for (int dj = std::max(-k.reach_y, -y); dj <= std::min(k.reach_y, height - 1 - y); ++dj) {
    const double* src = e.data() + static_cast<std::size_t>(y + dj) * static_cast<std::size_t>(width);
    const double* weights = k.row(channel, dj) + k.reach_x;
    const std::size_t r = k.row_index(dj);
    for (int di = k.first[r]; di <= k.last[r]; ++di) {
      const double w = weights[di];
      if (w == 0.0) continue;
      // The receivers whose source x + di is inside the row.
      const int lo = std::max(x0, -di), hi = std::min(x0 + n, width - di);
      if (lo >= hi) continue;
      const auto count = static_cast<std::size_t>(hi - lo);
      double* dst = row + (lo - x0);
      const double* s = src + (lo + di);
      for (std::size_t i = 0; i < count; ++i) dst[i] += w * s[i];
    }
  }
}

void check_turned_input(const TurnedPlaneInput& in, const PixelRegion& r, const double* out_rgb) {
  const std::string who = "convolve_turned_plane: ";
  if (in.width < 1 || in.height < 1) {
    throw std::invalid_argument(who + "bad size " + std::to_string(in.width) + "x" + std::to_string(in.height));
  }
  if (in.irradiance == nullptr || out_rgb == nullptr) throw std::invalid_argument(who + "irradiance and out_rgb must not be null");
  const TurnedPlaneFootprint& f = in.footprint;
  if (!(f.a_mm > 0.0) || !(f.b_mm > 0.0) || !std::isfinite(f.a_mm) || !std::isfinite(f.b_mm) || !std::isfinite(f.c_mm)) {
    throw std::invalid_argument(who + "footprint a = " + std::to_string(f.a_mm) + ", b = " + std::to_string(f.b_mm) +
                                ", c = " + std::to_string(f.c_mm) + " mm (a, b must be > 0, all finite)");
  }
  if (r.x < 0 || r.y < 0 || r.width < 0 || r.height < 0 || r.x + r.width > in.width || r.y + r.height > in.height) {
    throw std::invalid_argument(who + "receiver region (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ", " +
                                std::to_string(r.width) + "x" + std::to_string(r.height) + ") is not inside the frame");
  }
}

}  // namespace

std::vector<double> pixel_integrated_gaussian(double variance_mm2, double pixel_mm, int radius) {
  if (!(variance_mm2 > 0.0) || !std::isfinite(variance_mm2)) {
    throw std::invalid_argument("pixel_integrated_gaussian: variance_mm2 must be > 0, got " + std::to_string(variance_mm2));
  }
  if (!(pixel_mm > 0.0) || !std::isfinite(pixel_mm)) {
    throw std::invalid_argument("pixel_integrated_gaussian: pixel_mm must be > 0, got " + std::to_string(pixel_mm));
  }
  if (radius < 0) throw std::invalid_argument("pixel_integrated_gaussian: radius must be >= 0, got " + std::to_string(radius));
  const double scale = pixel_mm / std::sqrt(2.0 * variance_mm2);
  std::vector<double> k(static_cast<std::size_t>(2 * radius + 1));
  for (int d = -radius; d <= radius; ++d) {
    k[static_cast<std::size_t>(d + radius)] = half_erf_difference((d - 0.5) * scale, (d + 0.5) * scale);
  }
  return k;
}

void convolve_fronto_parallel_plane(const PlaneInput& input, const GaussianProfile& profile, double* out_rgb) {
  if (input.width < 1 || input.height < 1) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: bad size " + std::to_string(input.width) + "x" +
                                std::to_string(input.height));
  }
  if (input.irradiance == nullptr || out_rgb == nullptr) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: irradiance and out_rgb must not be null");
  }
  if (!(input.pixel_x_mm > 0.0) || !(input.pixel_y_mm > 0.0)) {
    throw std::invalid_argument("convolve_fronto_parallel_plane: pixel sides must be > 0, got " +
                                std::to_string(input.pixel_x_mm) + " x " + std::to_string(input.pixel_y_mm) + " mm");
  }
  const int w = input.width, h = input.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  for (std::size_t i = 0; i < n * 3; ++i) out_rgb[i] = 0.0;
  std::vector<double> channel(n), rows(n), both(n);
  for (const GaussianTerm& term : profile) {
    if (term.weight[0] == 0.0 && term.weight[1] == 0.0 && term.weight[2] == 0.0) continue;
    const std::vector<double> kx = pixel_integrated_gaussian(term.variance_mm2, input.pixel_x_mm, w - 1);
    const std::vector<double> ky = pixel_integrated_gaussian(term.variance_mm2, input.pixel_y_mm, h - 1);
    for (std::size_t c = 0; c < 3; ++c) {
      if (term.weight[c] == 0.0) continue;
      for (std::size_t i = 0; i < n; ++i) channel[i] = static_cast<double>(input.irradiance[i * 4 + c]);
      convolve_axis(kx, 0, w, h, channel, &rows);  // along x
      convolve_axis(ky, 1, w, h, rows, &both);     // along y
      for (std::size_t i = 0; i < n; ++i) out_rgb[i * 3 + c] += term.weight[c] * both[i];
    }
  }
}

double plane_pixel_mm_x(const Matrix4& m, int width, double distance, double world_units_per_mm) {
  return std::fabs(2.0 * clip_w_from_distance(m, distance) / (static_cast<double>(m[0]) * width)) / world_units_per_mm;
}

double plane_pixel_mm_y(const Matrix4& m, int height, double distance, double world_units_per_mm) {
  return std::fabs(2.0 * clip_w_from_distance(m, distance) / (static_cast<double>(m[5]) * height)) / world_units_per_mm;
}

TurnedPlaneFootprint turned_plane_footprint(const Vec3& tx_mm, const Vec3& ty_mm) {
  PixelFootprint rectangle;
  set_footprint_rectangle(tx_mm, ty_mm, &rectangle);
  if (!(rectangle.area > 0.0) || !std::isfinite(rectangle.area)) {
    throw std::invalid_argument("turned_plane_footprint: the tangents span no area");
  }
  return {rectangle.a, rectangle.b, dot(ty_mm, rectangle.t1)};
}

TurnedPlaneFootprint turned_plane_footprint(const Matrix4& m, int width, int height, const Vec3& point,
                                            const Vec3& normal, double world_units_per_mm, int x, int y) {
  // A pixel's view position is linear in its distance d (surface.hpp): origin + d · direction.
  const auto on_plane = [&](int px, int py) {
    const Vec3 origin = pixel_position(m, width, height, px, py, 0.0);
    const Vec3 direction = pixel_position(m, width, height, px, py, 1.0) - origin;
    const double d = dot(normal, point - origin) / dot(normal, direction);
    if (!(d > 0.0) || !std::isfinite(d) || !(clip_w_from_distance(m, d) > 0.0)) {
      throw std::invalid_argument("turned_plane_footprint: pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                                  ")'s ray does not meet the plane in front of the camera");
    }
    return pixel_position(m, width, height, px, py, d);
  };
  const double to_mm = 1.0 / world_units_per_mm;
  const Vec3 tx = (0.5 * to_mm) * (on_plane(x + 1, y) - on_plane(x - 1, y));
  const Vec3 ty = (0.5 * to_mm) * (on_plane(x, y + 1) - on_plane(x, y - 1));
  return turned_plane_footprint(tx, ty);
}

void convolve_turned_plane(const TurnedPlaneInput& input, const GaussianProfile& profile, const PixelRegion& receivers,
                           double* out_rgb, int threads) {
  check_turned_input(input, receivers, out_rgb);
  for (const GaussianTerm& term : profile) {
    if (!(term.variance_mm2 > 0.0) || !std::isfinite(term.variance_mm2)) {
      throw std::invalid_argument("convolve_turned_plane: a term's variance is " + std::to_string(term.variance_mm2));
    }
  }
  if (receivers.width == 0 || receivers.height == 0) return;
  const int w = input.width, h = input.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const ShearedKernel k = sheared_kernel(profile, input.footprint, w, h);
  std::array<std::vector<double>, 3> planes;
  for (std::size_t c = 0; c < 3; ++c) {
    planes[c].resize(n);
    for (std::size_t i = 0; i < n; ++i) planes[c][i] = static_cast<double>(input.irradiance[i * 4 + c]);
  }
  std::atomic<int> next{0};
  const auto work = [&]() {
    std::vector<double> row(static_cast<std::size_t>(receivers.width));
    for (int r = next++; r < receivers.height; r = next++) {
      const int y = receivers.y + r;
      double* out = out_rgb + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(receivers.x)) * 3;
      for (std::size_t c = 0; c < 3; ++c) {
        if (k.used[c]) {
          convolve_turned_row(k, c, planes[c], w, h, y, receivers.x, receivers.width, row.data());
        } else {
          std::fill(row.begin(), row.end(), 0.0);
        }
        for (std::size_t i = 0; i < row.size(); ++i) out[i * 3 + c] = row[i];
      }
    }
  };
  unsigned count = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
  count = std::max(1u, std::min(count, static_cast<unsigned>(receivers.height)));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < count; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace sss::math
