#include "metrics.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sss_bench {

RgbImage::RgbImage(int w, int h, double value)
    : width(w), height(h), rgb(static_cast<std::size_t>(std::max(w, 0)) * static_cast<std::size_t>(std::max(h, 0)) * 3, value) {}

RgbImage RgbImage::from_rgba(const float* rgba, int w, int h) {
  RgbImage img(w, h);
  for (std::size_t i = 0; i < img.rgb.size() / 3; ++i) {
    for (std::size_t c = 0; c < 3; ++c) img.rgb[3 * i + c] = static_cast<double>(rgba[4 * i + c]);
  }
  return img;
}

RgbImage RgbImage::from_rgb(const double* rgb, int w, int h) {
  RgbImage img(w, h);
  std::copy(rgb, rgb + img.rgb.size(), img.rgb.begin());
  return img;
}

namespace {

void check_pair(const RgbImage& a, const RgbImage& r) {
  if (a.width <= 0 || a.height <= 0 || a.width != r.width || a.height != r.height ||
      a.rgb.size() != r.rgb.size() || a.rgb.size() != static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height) * 3) {
    std::ostringstream why;
    why << "metrics: images of " << a.width << "x" << a.height << " and " << r.width << "x" << r.height
        << " cannot be compared";
    throw std::invalid_argument(why.str());
  }
}

bool selected(const uint8_t* mask, std::size_t i) { return mask == nullptr || mask[i] != 0; }

// The 1D Gaussian window of the SSIM: 11 taps, σ = 1.5, unnormalised (normalised per position).
std::array<double, 11> ssim_window() {
  std::array<double, 11> w{};
  for (int i = 0; i < 11; ++i) {
    const double x = i - 5;
    w[static_cast<std::size_t>(i)] = std::exp(-x * x / (2.0 * 1.5 * 1.5));
  }
  return w;
}

// Separable Gaussian filtering, window cut to the image and renormalised.
std::vector<double> gaussian_filter(const std::vector<double>& in, int width, int height) {
  const auto w = ssim_window();
  std::vector<double> tmp(in.size()), out(in.size());
  const auto idx = [width](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x); };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -5; k <= 5; ++k) {
        const int xx = x + k;
        if (xx < 0 || xx >= width) continue;
        const double wk = w[static_cast<std::size_t>(k + 5)];
        sum += wk * in[idx(xx, y)];
        norm += wk;
      }
      tmp[idx(x, y)] = sum / norm;
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -5; k <= 5; ++k) {
        const int yy = y + k;
        if (yy < 0 || yy >= height) continue;
        const double wk = w[static_cast<std::size_t>(k + 5)];
        sum += wk * tmp[idx(x, yy)];
        norm += wk;
      }
      out[idx(x, y)] = sum / norm;
    }
  }
  return out;
}

double srgb_encode(double x) {
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

uint8_t to_byte(double v) {
  return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

bool write_png_top_row_first(const std::string& path, int width, int height, const std::vector<uint8_t>& gl_rows) {
  // gl_rows: row 0 at the bottom; PNG wants the top row first.
  std::vector<uint8_t> flipped(gl_rows.size());
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) {
    std::copy_n(gl_rows.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * stride), stride,
                flipped.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(height - 1 - y) * stride));
  }
  return stbi_write_png(path.c_str(), width, height, 3, flipped.data(), width * 3) != 0;
}

}  // namespace

double relative_rmse(const RgbImage& a, const RgbImage& r, const uint8_t* mask) {
  check_pair(a, r);
  double err = 0.0, ref = 0.0;
  for (std::size_t i = 0; i < a.rgb.size() / 3; ++i) {
    if (!selected(mask, i)) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const double d = a.rgb[3 * i + c] - r.rgb[3 * i + c];
      err += d * d;
      ref += r.rgb[3 * i + c] * r.rgb[3 * i + c];
    }
  }
  if (ref == 0.0) return err == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return std::sqrt(err / ref);
}

namespace {

double share(double undone, double needed) {
  if (needed > 0.0) return std::sqrt(undone / needed);
  return undone > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

double Miss::worst_channel() const { return std::max({channel[0], channel[1], channel[2]}); }

Miss miss_share(const RgbImage& result, const RgbImage& reference, const RgbImage& input, const uint8_t* mask) {
  check_pair(result, reference);
  check_pair(input, reference);
  std::array<double, 3> undone{}, needed{};
  Miss m;
  for (std::size_t i = 0; i < reference.rgb.size() / 3; ++i) {
    if (!selected(mask, i)) continue;
    ++m.pixels;
    for (std::size_t c = 0; c < 3; ++c) {
      const double r = reference.rgb[i * 3 + c];
      undone[c] += (result.rgb[i * 3 + c] - r) * (result.rgb[i * 3 + c] - r);
      needed[c] += (input.rgb[i * 3 + c] - r) * (input.rgb[i * 3 + c] - r);
    }
  }
  if (m.pixels == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.channel = {nan, nan, nan};
    m.share = {nan, nan, nan};
    m.pooled = nan;
    return m;
  }
  const double needed_pooled = needed[0] + needed[1] + needed[2];
  for (std::size_t c = 0; c < 3; ++c) {
    m.channel[c] = share(undone[c], needed[c]);
    m.share[c] = share(undone[c], needed_pooled);
  }
  m.pooled = share(undone[0] + undone[1] + undone[2], needed_pooled);
  return m;
}

double max_abs_error(const RgbImage& a, const RgbImage& r, const uint8_t* mask) {
  check_pair(a, r);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rgb.size() / 3; ++i) {
    if (!selected(mask, i)) continue;
    for (std::size_t c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(a.rgb[3 * i + c] - r.rgb[3 * i + c]));
  }
  return worst;
}

double percentile_abs_error(const RgbImage& a, const RgbImage& r, const uint8_t* mask, double fraction) {
  check_pair(a, r);
  if (!(fraction > 0.0 && fraction <= 1.0)) throw std::invalid_argument("metrics: percentile fraction not in (0, 1]");
  std::vector<double> errors;
  for (std::size_t i = 0; i < a.rgb.size() / 3; ++i) {
    if (!selected(mask, i)) continue;
    for (std::size_t c = 0; c < 3; ++c) errors.push_back(std::fabs(a.rgb[3 * i + c] - r.rgb[3 * i + c]));
  }
  if (errors.empty()) return 0.0;
  // Nearest rank: the ceil(fraction · n)-th smallest (1-based).
  std::size_t rank = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(errors.size()) - 1e-9));
  rank = std::clamp<std::size_t>(rank, 1, errors.size());
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(rank - 1), errors.end());
  return errors[rank - 1];
}

double tone_map(double linear, double exposure) {
  const double x = std::max(linear * exposure, 0.0);
  const double mapped = std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  return std::clamp(srgb_encode(mapped), 0.0, 1.0);
}

RgbImage tone_map_image(const RgbImage& linear, double exposure) {
  RgbImage out = linear;
  for (double& v : out.rgb) v = tone_map(v, exposure);
  return out;
}

double ssim_display(const RgbImage& a, const RgbImage& r, const uint8_t* mask) {
  check_pair(a, r);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const std::size_t n = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) count += selected(mask, i) ? 1 : 0;
  if (count == 0) return 1.0;
  double total = 0.0;
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = a.rgb[3 * i + c];
      y[i] = r.rgb[3 * i + c];
      xx[i] = x[i] * x[i];
      yy[i] = y[i] * y[i];
      xy[i] = x[i] * y[i];
    }
    const auto mx = gaussian_filter(x, a.width, a.height);
    const auto my = gaussian_filter(y, a.width, a.height);
    const auto mxx = gaussian_filter(xx, a.width, a.height);
    const auto myy = gaussian_filter(yy, a.width, a.height);
    const auto mxy = gaussian_filter(xy, a.width, a.height);
    for (std::size_t i = 0; i < n; ++i) {
      if (!selected(mask, i)) continue;
      const double vx = std::max(mxx[i] - mx[i] * mx[i], 0.0);
      const double vy = std::max(myy[i] - my[i] * my[i], 0.0);
      const double cxy = mxy[i] - mx[i] * my[i];
      total += (2.0 * mx[i] * my[i] + c1) * (2.0 * cxy + c2) /
               ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
  }
  return total / (3.0 * static_cast<double>(count));
}

double ssim_tonemapped(const RgbImage& a, const RgbImage& r, const uint8_t* mask, double exposure) {
  check_pair(a, r);
  return ssim_display(tone_map_image(a, exposure), tone_map_image(r, exposure), mask);
}

ErrorMetrics compare_images(const RgbImage& a, const RgbImage& r, const uint8_t* mask, double exposure) {
  ErrorMetrics m;
  m.relative_rmse = relative_rmse(a, r, mask);
  m.max_abs = max_abs_error(a, r, mask);
  m.p99_abs = percentile_abs_error(a, r, mask, 0.99);
  m.ssim = ssim_tonemapped(a, r, mask, exposure);
  const std::size_t n = a.rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i) m.pixels += selected(mask, i) ? 1 : 0;
  return m;
}

std::array<uint8_t, 3> error_ramp(double t) {
  // Nine stops, evenly spaced, approximating matplotlib's viridis (perceptually uniform, readable
  // in grey and by colour-blind viewers); linear in between.
  static const uint8_t stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 82, 139},  {44, 114, 142}, {33, 145, 140},
                                      {39, 173, 129}, {94, 201, 98},  {170, 220, 50}, {253, 231, 37}};
  if (!(t > 0.0)) t = 0.0;  // also NaN
  t = std::min(t, 1.0);
  const double s = t * 8.0;
  const int i = std::min(static_cast<int>(s), 7);
  const double f = s - i;
  std::array<uint8_t, 3> out{};
  for (int c = 0; c < 3; ++c) {
    const double v = (1.0 - f) * stops[i][c] + f * stops[i + 1][c];
    out[static_cast<std::size_t>(c)] = static_cast<uint8_t>(std::lround(v));
  }
  return out;
}

bool write_error_heatmap_png(const std::string& path, const RgbImage& a, const RgbImage& r, const uint8_t* mask,
                             double scale) {
  check_pair(a, r);
  if (!(scale > 0.0)) throw std::invalid_argument("metrics: heat-map scale must be positive");
  const std::size_t n = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  std::vector<uint8_t> pixels(n * 3, 128);
  for (std::size_t i = 0; i < n; ++i) {
    if (!selected(mask, i)) continue;
    double e = 0.0;
    for (std::size_t c = 0; c < 3; ++c) e = std::max(e, std::fabs(a.rgb[3 * i + c] - r.rgb[3 * i + c]));
    const auto colour = error_ramp(e / scale);
    std::copy(colour.begin(), colour.end(), pixels.begin() + static_cast<std::ptrdiff_t>(3 * i));
  }
  return write_png_top_row_first(path, a.width, a.height, pixels);
}

double heat_map_scale(const RgbImage& reference, const uint8_t* mask) {
  double brightest = 0.0;
  for (std::size_t i = 0; i < reference.rgb.size() / 3; ++i) {
    if (mask != nullptr && mask[i] == 0) continue;
    for (std::size_t c = 0; c < 3; ++c) brightest = std::max(brightest, reference.rgb[i * 3 + c]);
  }
  return brightest > 0.0 ? 0.1 * brightest : 1.0;
}

bool write_tonemapped_png(const std::string& path, const RgbImage& linear, double exposure) {
  if (linear.width <= 0 || linear.height <= 0 ||
      linear.rgb.size() != static_cast<std::size_t>(linear.width) * static_cast<std::size_t>(linear.height) * 3) {
    throw std::invalid_argument("metrics: image size does not match its data");
  }
  std::vector<uint8_t> pixels(linear.rgb.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = to_byte(tone_map(linear.rgb[i], exposure));
  return write_png_top_row_first(path, linear.width, linear.height, pixels);
}

}  // namespace sss_bench
