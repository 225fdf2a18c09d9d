#include "radial_plane_reference.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "radial_integrals.hpp"

namespace sss::math {

namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void invalid(const std::string& message) {
  throw std::invalid_argument("radial plane reference: " + message);
}

// Runs work(0..count-1) on `threads` threads (0: the hardware's), each index once.
template <typename Work>
void parallel_for(int count, int threads, const Work& work) {
  unsigned n = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
  n = std::max(1u, std::min(n, static_cast<unsigned>(std::max(count, 1))));
  std::atomic<int> next{0};
  const auto run = [&]() {
    for (int i = next++; i < count; i = next++) work(i);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(run);
  run();
  for (auto& t : pool) t.join();
}

}  // namespace

RadialPixelKernel::RadialPixelKernel(const RadialProfile& profile, double sx, double sy, int nx, int ny, int threads)
    : nx_(nx), ny_(ny), sx_(sx), sy_(sy) {
  if (!(sx > 0.0) || !(sy > 0.0) || nx < 1 || ny < 1) {
    std::ostringstream why;
    why << "pixel " << sx << " x " << sy << " mm, kernel " << nx << " x " << ny << ": must all be positive";
    invalid(why.str());
  }
  k_.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  parallel_for(ny, threads, [&](int j) {
    for (int i = 0; i < nx; ++i) {
      k_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] =
          rectangle_integral(profile, (i - 0.5) * sx, (i + 0.5) * sx, (j - 0.5) * sy, (j + 0.5) * sy);
    }
  });
}

const Rgb& RadialPixelKernel::at(int i, int j) const {
  const auto ai = static_cast<std::size_t>(std::abs(i)), aj = static_cast<std::size_t>(std::abs(j));
  return k_[aj * static_cast<std::size_t>(nx_) + ai];
}

void convolve_plane_radial(const PlaneInput& in, const RadialProfile& profile, const PixelRegion& r, double* out_rgb,
                           int threads, int stride) {
  if (in.width <= 0 || in.height <= 0) {
    invalid("image " + std::to_string(in.width) + "x" + std::to_string(in.height) + " is not positive");
  }
  const RadialPixelKernel k(profile, in.pixel_x_mm, in.pixel_y_mm, in.width, in.height, threads);
  convolve_plane_radial(in, k, r, out_rgb, threads, stride);
}

void convolve_plane_radial(const PlaneInput& in, const RadialPixelKernel& k, const PixelRegion& r, double* out_rgb,
                           int threads, int stride) {
  if (stride < 1) invalid("stride " + std::to_string(stride) + " is not positive");
  if (in.width <= 0 || in.height <= 0 || in.irradiance == nullptr || out_rgb == nullptr) {
    std::ostringstream why;
    why << "image " << in.width << "x" << in.height << " with irradiance " << (in.irradiance ? "set" : "null")
        << " and out_rgb " << (out_rgb ? "set" : "null") << ": needs a positive size and both arrays";
    invalid(why.str());
  }
  if (r.x < 0 || r.y < 0 || r.width < 0 || r.height < 0 || r.x + r.width > in.width || r.y + r.height > in.height) {
    std::ostringstream why;
    why << "receiver region (" << r.x << ", " << r.y << ", " << r.width << "x" << r.height << ") is not inside the "
        << in.width << "x" << in.height << " image";
    invalid(why.str());
  }
  if (k.nx() < in.width || k.ny() < in.height || k.pixel_x_mm() != in.pixel_x_mm || k.pixel_y_mm() != in.pixel_y_mm) {
    std::ostringstream why;
    why << "a kernel of " << k.nx() << "x" << k.ny() << " cells of " << k.pixel_x_mm() << " x " << k.pixel_y_mm()
        << " mm does not serve a " << in.width << "x" << in.height << " image of " << in.pixel_x_mm << " x "
        << in.pixel_y_mm << " mm pixels";
    invalid(why.str());
  }
  const auto w = static_cast<std::size_t>(in.width);
  parallel_for(r.height, threads, [&](int row) {
    const int y = r.y + row;
    if (y % stride != stride / 2) return;
    for (int x = r.x; x < r.x + r.width; ++x) {
      if (x % stride != stride / 2) continue;
      double sum[3] = {0.0, 0.0, 0.0};
      for (int sy = 0; sy < in.height; ++sy) {
        const float* e = in.irradiance + static_cast<std::size_t>(sy) * w * 4;
        for (int sx = 0; sx < in.width; ++sx) {
          const Rgb& kv = k.at(sx - x, sy - y);
          const float* p = e + static_cast<std::size_t>(sx) * 4;
          sum[0] += kv[0] * static_cast<double>(p[0]);
          sum[1] += kv[1] * static_cast<double>(p[1]);
          sum[2] += kv[2] * static_cast<double>(p[2]);
        }
      }
      double* o = out_rgb + 3 * (static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x));
      o[0] = sum[0];
      o[1] = sum[1];
      o[2] = sum[2];
    }
  });
}

Rgb burley_line_profile(const BurleyProfile& profile, double x_mm) {
  const double x = std::fabs(x_mm);
  const Rgb a = profile.integral();
  const Rgb& d = profile.shape_mm();
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = x > 0.0 ? a[c] * (std::cyl_bessel_k(0.0, x / d[c]) + std::cyl_bessel_k(0.0, x / (3.0 * d[c]))) /
                           (4.0 * kPi * d[c])
                     : HUGE_VAL;
  }
  return out;
}

}  // namespace sss::math
