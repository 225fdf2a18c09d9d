// texturing_detail.hpp's measures.
#include "texturing_detail.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

namespace sss_bench {

PixelRegion bounding_box(const std::vector<uint8_t>& selected, int width, int height) {
  int x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (selected[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] == 0) {
        continue;
      }
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return {};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

double surface_frequency_per_mm(const sss::math::TurnedPlaneFootprint& footprint, double fx, double fy) {
  const double ku = fx / footprint.a_mm;
  const double kv = fy / footprint.b_mm - footprint.c_mm * fx / (footprint.a_mm * footprint.b_mm);
  return std::sqrt(ku * ku + kv * kv);
}

namespace {

// The frequency (cycles per pixel) of DFT bin k of n: k / n up to n / 2, then the negative ones.
double bin_frequency(int k, int n) { return (2 * k < n ? k : k - n) / static_cast<double>(n); }

}  // namespace

bool resolves_above(const PixelRegion& box, const sss::math::TurnedPlaneFootprint& footprint, double cutoff_per_mm) {
  for (int j = 0; j < box.height; ++j) {
    for (int i = 0; i < box.width; ++i) {
      const double f = surface_frequency_per_mm(footprint, bin_frequency(i, box.width), bin_frequency(j, box.height));
      if (f > cutoff_per_mm) return true;
    }
  }
  return false;
}

double power_above(const RgbImage& image, const PixelRegion& box, const sss::math::TurnedPlaneFootprint& footprint,
                   double cutoff_per_mm) {
  if (box.width < 2 || box.height < 2 || box.x < 0 || box.y < 0 || box.x + box.width > image.width ||
      box.y + box.height > image.height) {
    throw std::invalid_argument("power_above: the box is not inside the image");
  }
  const auto hann = [](int i, int n) { return 0.5 - 0.5 * std::cos(2.0 * std::acos(-1.0) * (i + 0.5) / n); };
  const int w = box.width, h = box.height;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> grid(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::vector<std::complex<double>> line_in, line_out;
  double power = 0.0;
  for (int c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) mean += image.at(box.x + x, box.y + y, c);
    }
    mean /= static_cast<double>(w) * h;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        grid[static_cast<std::size_t>(y) * w + x] = (image.at(box.x + x, box.y + y, c) - mean) * hann(x, w) * hann(y, h);
      }
    }
    line_in.resize(static_cast<std::size_t>(w));
    for (int y = 0; y < h; ++y) {  // rows
      std::copy_n(grid.begin() + static_cast<std::ptrdiff_t>(y) * w, w, line_in.begin());
      fft.fwd(line_out, line_in);
      std::copy_n(line_out.begin(), w, grid.begin() + static_cast<std::ptrdiff_t>(y) * w);
    }
    line_in.resize(static_cast<std::size_t>(h));
    for (int x = 0; x < w; ++x) {  // columns
      for (int y = 0; y < h; ++y) line_in[static_cast<std::size_t>(y)] = grid[static_cast<std::size_t>(y) * w + x];
      fft.fwd(line_out, line_in);
      for (int y = 0; y < h; ++y) {
        if (surface_frequency_per_mm(footprint, bin_frequency(x, w), bin_frequency(y, h)) > cutoff_per_mm) {
          power += std::norm(line_out[static_cast<std::size_t>(y)]);
        }
      }
    }
  }
  return power;
}

double box_high_pass_power(const RgbImage& image, const std::vector<uint8_t>& selected,
                           const std::vector<uint8_t>& support, const std::vector<float>& mm_per_pixel, double box_mm) {
  double power = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = image.index(x, y);
      if (selected[i] == 0) continue;
      const int r = std::max(1, static_cast<int>(std::lround(0.5 * box_mm / mm_per_pixel[i])));
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        int n = 0;
        for (int sy = std::max(0, y - r); sy <= std::min(image.height - 1, y + r); ++sy) {
          for (int sx = std::max(0, x - r); sx <= std::min(image.width - 1, x + r); ++sx) {
            if (support[image.index(sx, sy)] == 0) continue;
            sum += image.at(sx, sy, c);
            ++n;
          }
        }
        const double d = image.at(x, y, c) - sum / n;
        power += d * d;
      }
    }
  }
  return power;
}

}  // namespace sss_bench
