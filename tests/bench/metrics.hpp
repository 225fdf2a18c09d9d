// Image metrics of the benchmark (DESIGN.md §6): how far a filter's output is from the exact
// reference, in linear light and as a person sees it after tone mapping, plus PNG writers for the
// pictures a person looks at. Benchmark side only (not part of the library).
//
// Images are linear RGB in doubles, row 0 at the bottom (GL order), like the exact reference's
// output. Every metric is taken over the pixels selected by a mask (the translucent pixels;
// nullptr selects every pixel); the two images must have the same size.
//
// Definitions
// -----------
// - relative RMSE: sqrt( Σ (a - r)² / Σ r² ), sums over the R, G and B components of the selected
//   pixels, in linear light. 0 when both sums are 0; +inf when only Σ r² is 0.
// - max abs: max |a - r| over the same components.
// - p99 abs: the 99th percentile of |a - r| over the same components, nearest-rank definition:
//   the ceil(0.99 · n)-th smallest of the n values (n = 3 · selected pixels).
// - SSIM (Wang et al. 2004) on the tone-mapped images (tone_map() below, values in [0, 1]):
//   per channel, local means, variances and covariance under an 11×11 Gaussian window, σ = 1.5
//   pixels (weights normalised to sum 1; near the border the window is cut to the image and
//   renormalised, so every pixel gets a full-weight window), C1 = (0.01)², C2 = (0.03)² (K1 = 0.01,
//   K2 = 0.03, dynamic range L = 1):
//     SSIM = (2 μa μr + C1)(2 σar + C2) / ((μa² + μr² + C1)(σa² + σr² + C2)),
//   averaged over the three channels and over the windows centred on selected pixels. The windows
//   themselves include unselected neighbours (in our benchmark those are identical in both images:
//   filters and the reference leave non-translucent pixels untouched). 1 when nothing is selected.
// - Tone map: exposure e (linear scale), then Narkowicz's 2015 fit of the ACES filmic curve,
//     f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1],
//   then the sRGB transfer function (12.92 x below 0.0031308, else 1.055 x^(1/2.4) - 0.055).
//   Negative inputs clamp to 0.
// - miss: the share of the needed change that a method leaves undone,
//     miss = ‖result − reference‖ / ‖input − reference‖   (L2 norms over the selected pixels)
//   per channel and pooled over R, G and B. 0: the result is the reference; 1: as far from it as
//   the unfiltered input (doing nothing); above 1: worse than doing nothing. Unlike relative RMSE,
//   which divides by the reference's own energy (large: most of the light does not move), it says
//   how much of the filter's job was done. With no pixel selected it is NaN (not measured). Where
//   the input already is the reference (nothing to change: light that stays inside its pixel, a
//   uniform area, to the reference's float precision) a result equal to it misses 0 and any other
//   +inf: no floor is put under the needed change, because any floor large enough to matter also
//   hides a channel made many times worse than the input where it needed a small change.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sss_bench {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<double> rgb;  // width · height · 3, row 0 at the bottom

  RgbImage() = default;
  RgbImage(int w, int h, double value = 0.0);
  static RgbImage from_rgba(const float* rgba, int width, int height);  // drops alpha
  static RgbImage from_rgb(const double* rgb, int width, int height);

  double& at(int x, int y, int c) { return rgb[index(x, y) * 3 + static_cast<std::size_t>(c)]; }
  double at(int x, int y, int c) const { return rgb[index(x, y) * 3 + static_cast<std::size_t>(c)]; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

struct ErrorMetrics {
  double relative_rmse = 0.0;
  double max_abs = 0.0;
  double p99_abs = 0.0;
  double ssim = 1.0;
  std::size_t pixels = 0;  // selected pixels
};

// The metrics/miss definition above: channel[c] per channel, pooled over the three.
struct Miss {
  std::array<double, 3> channel{};
  // ‖result − reference‖ of each channel over the pooled ‖input − reference‖ of all three: the
  // channel's part of the pooled miss (Σ share² = pooled²). Unlike channel[], it stays well
  // conditioned where a channel needs almost no change (blue at a coarse footprint), which is what
  // the regression guard compares there (tests/bench/miss_guard_test.cpp).
  std::array<double, 3> share{};
  double pooled = 0.0;
  std::size_t pixels = 0;  // selected pixels
  double worst_channel() const;  // the largest of channel[] (NaN when nothing was selected)
};

// The functions below throw std::invalid_argument when the sizes differ or are not positive.
Miss miss_share(const RgbImage& result, const RgbImage& reference, const RgbImage& input, const uint8_t* mask);
// `mask`: width · height bytes, non-zero selects; nullptr selects all.
double relative_rmse(const RgbImage& a, const RgbImage& reference, const uint8_t* mask);
double max_abs_error(const RgbImage& a, const RgbImage& reference, const uint8_t* mask);
double percentile_abs_error(const RgbImage& a, const RgbImage& reference, const uint8_t* mask, double fraction = 0.99);
double ssim_tonemapped(const RgbImage& a, const RgbImage& reference, const uint8_t* mask, double exposure = 1.0);
ErrorMetrics compare_images(const RgbImage& a, const RgbImage& reference, const uint8_t* mask, double exposure = 1.0);

// SSIM of two images already in [0, 1] (no tone map): the core of ssim_tonemapped.
double ssim_display(const RgbImage& a, const RgbImage& reference, const uint8_t* mask);

// The tone map of one linear component (see above): [0, 1] display value.
double tone_map(double linear, double exposure = 1.0);
RgbImage tone_map_image(const RgbImage& linear, double exposure = 1.0);

// The colour ramp of the heat maps: t in [0, 1] (clamped) -> 8-bit RGB, a piecewise-linear
// viridis-like ramp (dark blue-violet, blue, teal, green, yellow; lightness increases steadily).
std::array<uint8_t, 3> error_ramp(double t);

// Heat map of |a - r| (max over the channels) / scale through error_ramp (values >= scale are at
// the top). Unselected pixels are mid grey (128, 128, 128), which is not on the ramp. PNG, top row
// first as viewers expect (the image is flipped from GL order). Returns false if writing failed.
bool write_error_heatmap_png(const std::string& path, const RgbImage& a, const RgbImage& reference,
                             const uint8_t* mask, double scale);

// The error mapped to the top of the heat map's colour ramp: 10 % of the reference's brightest
// translucent value, so maps of one scene compare across methods.
double heat_map_scale(const RgbImage& reference, const uint8_t* mask);

// The image tone-mapped (tone_map, exposure) as an 8-bit sRGB PNG, top row first.
bool write_tonemapped_png(const std::string& path, const RgbImage& linear, double exposure = 1.0);

}  // namespace sss_bench
