// sss_side_by_side: the same rectangle of two images, magnified and placed side by side with a white
// divider, for before/after comparisons in the docs (scripts/compare-defaults.sh).
//
//   sss_side_by_side LEFT.png RIGHT.png X Y WIDTH HEIGHT ZOOM OUT.png
//
// X, Y: the rectangle's top-left corner in pixels (top row 0); both images must hold it.
#include <cstdio>
#include <string>
#include <vector>

#include "png.hpp"

int main(int argc, char** argv) {
  if (argc != 9) {
    std::fprintf(stderr, "usage: sss_side_by_side LEFT.png RIGHT.png X Y WIDTH HEIGHT ZOOM OUT.png\n");
    return 2;
  }
  const int x0 = std::stoi(argv[3]), y0 = std::stoi(argv[4]), w = std::stoi(argv[5]), h = std::stoi(argv[6]);
  const int zoom = std::stoi(argv[7]);
  constexpr int kDivider = 4;
  if (w <= 0 || h <= 0 || zoom <= 0 || x0 < 0 || y0 < 0) {
    std::fprintf(stderr, "sss_side_by_side: the rectangle and zoom must be positive\n");
    return 2;
  }
  std::vector<unsigned char> images[2];
  int widths[2], heights[2];
  for (int i = 0; i < 2; ++i) {
    if (!sss_tools::read_rgb(argv[1 + i], &widths[i], &heights[i], &images[i])) {
      std::fprintf(stderr, "sss_side_by_side: cannot read %s\n", argv[1 + i]);
      return 1;
    }
    if (x0 + w > widths[i] || y0 + h > heights[i]) {
      std::fprintf(stderr, "sss_side_by_side: %s (%dx%d) does not hold the rectangle\n", argv[1 + i], widths[i], heights[i]);
      return 1;
    }
  }
  const int out_w = 2 * w * zoom + kDivider, out_h = h * zoom;
  std::vector<unsigned char> out(static_cast<std::size_t>(out_w) * static_cast<std::size_t>(out_h) * 3, 255);
  for (int i = 0; i < 2; ++i) {
    const int left = i * (w * zoom + kDivider);
    for (int y = 0; y < out_h; ++y) {
      for (int x = 0; x < w * zoom; ++x) {
        const std::size_t from =
            (static_cast<std::size_t>(y0 + y / zoom) * static_cast<std::size_t>(widths[i]) + static_cast<std::size_t>(x0 + x / zoom)) * 3;
        const std::size_t to = (static_cast<std::size_t>(y) * static_cast<std::size_t>(out_w) + static_cast<std::size_t>(left + x)) * 3;
        for (int c = 0; c < 3; ++c) out[to + static_cast<std::size_t>(c)] = images[i][from + static_cast<std::size_t>(c)];
      }
    }
  }
  if (!sss_tools::write_png(argv[8], out_w, out_h, out)) {
    std::fprintf(stderr, "sss_side_by_side: cannot write %s\n", argv[8]);
    return 1;
  }
  return 0;
}
