// texturing_detail.hpp's measures on images whose answer is known: a cosine's power lies wholly
// above or below the cut-off by its frequency on the surface, which a turned plane's footprint
// changes; the head's box high-pass keeps a fine pattern and removes a flat one.
#include <cmath>

#include <gtest/gtest.h>

#include "texturing_detail.hpp"

namespace {

using sss_bench::PixelRegion;
using sss_bench::RgbImage;

// A cosine of fx cycles per pixel along x and fy along y, in every channel, on an offset.
RgbImage cosine(int side, double fx, double fy) {
  RgbImage image(side, side);
  const double pi = std::acos(-1.0);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 1.0 + 0.25 * std::cos(2.0 * pi * (fx * x + fy * y));
    }
  }
  return image;
}

double total_power(const RgbImage& image, const PixelRegion& box, const sss::math::TurnedPlaneFootprint& fp) {
  return sss_bench::power_above(image, box, fp, 0.0);  // every frequency but the mean (removed)
}

TEST(TexturingDetail, ACosineCountsWhollyAboveOrBelowTheCutoffByItsSurfaceFrequency) {
  const int side = 64;
  const PixelRegion box{0, 0, side, side};
  const sss::math::TurnedPlaneFootprint facing{0.25, 0.25, 0.0};  // 0.25 mm per pixel
  // 8 cycles over 64 pixels at 0.25 mm/px: 0.5 cycle/mm; 24 cycles: 1.5 cycles/mm.
  const RgbImage low = cosine(side, 8.0 / side, 0.0), high = cosine(side, 24.0 / side, 0.0);
  EXPECT_LT(sss_bench::power_above(low, box, facing, 1.0), 1e-6 * total_power(low, box, facing));
  EXPECT_NEAR(sss_bench::power_above(high, box, facing, 1.0) / total_power(high, box, facing), 1.0, 1e-9);
  // Turned 60 degrees about screen x: a pixel measures 0.5 mm along y, so 24 cycles along y are
  // 0.75 cycle/mm on the surface, below the cut-off, and along x the same wave stays above it.
  const sss::math::TurnedPlaneFootprint turned{0.25, 0.5, 0.0};
  const RgbImage along_y = cosine(side, 0.0, 24.0 / side);
  EXPECT_LT(sss_bench::power_above(along_y, box, turned, 1.0), 1e-6 * total_power(along_y, box, turned));
  EXPECT_NEAR(sss_bench::power_above(high, box, turned, 1.0) / total_power(high, box, turned), 1.0, 1e-9);
  EXPECT_NEAR(sss_bench::surface_frequency_per_mm(turned, 0.0, 24.0 / side), 0.75, 1e-12);
}

TEST(TexturingDetail, CoarsePixelsResolveNothingAboveTheCutoff) {
  const PixelRegion box{0, 0, 64, 64};
  EXPECT_TRUE(sss_bench::resolves_above(box, {0.5, 0.5, 0.0}, 1.0));    // the diagonal reaches 1.41 cycles/mm
  EXPECT_FALSE(sss_bench::resolves_above(box, {1.0, 1.0, 0.0}, 1.0));   // at most 0.71 cycle/mm
}

TEST(TexturingDetail, TheBoxHighPassKeepsAFinePatternAndDropsAFlatOne) {
  const int side = 32;
  RgbImage flat(side, side, 0.5), fine(side, side, 0.0);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      for (int c = 0; c < 3; ++c) fine.at(x, y, c) = (x + y) % 2 == 0 ? 0.4 : 0.6;
    }
  }
  const std::vector<uint8_t> all(static_cast<std::size_t>(side) * side, 1);
  const std::vector<float> mm(all.size(), 0.25f);  // a 1 mm box: 5 x 5 pixels
  EXPECT_EQ(sss_bench::box_high_pass_power(flat, all, all, mm, 1.0), 0.0);
  // Pixels two or more from the border, whose boxes are whole: each box holds 13 of the pixel's value
  // and 12 of the other, so the pixel differs from its mean by 0.2 · 12 / 25.
  std::vector<uint8_t> inner(all.size(), 0);
  int count = 0;
  for (int y = 2; y < side - 2; ++y) {
    for (int x = 2; x < side - 2; ++x) inner[static_cast<std::size_t>(y) * side + x] = 1, ++count;
  }
  const double expected = 3.0 * count * std::pow(0.2 * 12.0 / 25.0, 2);
  EXPECT_NEAR(sss_bench::box_high_pass_power(fine, inner, all, mm, 1.0), expected, 1e-9 * expected);
}

}  // namespace
