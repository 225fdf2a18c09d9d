#include "image.hpp"

#include <algorithm>
#include <cstring>

namespace demo {

Image image_from_gl_rows(const std::vector<std::uint8_t> &bottom_up, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(bottom_up.size());
  const size_t row = static_cast<size_t>(width) * 4u;
  for (int y = 0; y < height; ++y) {
    std::memcpy(&image.rgba[static_cast<size_t>(y) * row],
                &bottom_up[static_cast<size_t>(height - 1 - y) * row], row);
  }
  return image;
}

Image crop_zoom(const Image &image, int centre_x, int centre_y, int width, int height, int zoom) {
  width = std::min(width, image.width);
  height = std::min(height, image.height);
  const int x0 = std::clamp(centre_x - width / 2, 0, image.width - width);
  const int y0 = std::clamp(centre_y - height / 2, 0, image.height - height);
  Image out;
  out.width = width * zoom;
  out.height = height * zoom;
  out.rgba.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * 4u);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const size_t from =
          (static_cast<size_t>(y0 + y / zoom) * static_cast<size_t>(image.width) + static_cast<size_t>(x0 + x / zoom)) * 4u;
      const size_t to = (static_cast<size_t>(y) * static_cast<size_t>(out.width) + static_cast<size_t>(x)) * 4u;
      std::memcpy(&out.rgba[to], &image.rgba[from], 4);
    }
  }
  return out;
}

Image make_split(const Image &left, const Image &right, int divider) {
  Image split = left;
  const int half = left.width / 2;
  const int divider_begin = std::max(0, half - divider / 2);
  const int divider_end = std::min(left.width, divider_begin + divider);
  for (int y = 0; y < split.height; ++y) {
    for (int x = half; x < split.width; ++x) {
      const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(split.width) + static_cast<size_t>(x)) * 4u;
      std::memcpy(&split.rgba[i], &right.rgba[i], 4);
    }
    for (int x = divider_begin; x < divider_end; ++x) {
      const size_t i = (static_cast<size_t>(y) * static_cast<size_t>(split.width) + static_cast<size_t>(x)) * 4u;
      std::memset(&split.rgba[i], 255, 4);
    }
  }
  return split;
}

}  // namespace demo
