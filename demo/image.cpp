#include "image.hpp"

#include <stb/stb_easy_font.h>  // header-only (static functions)

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

namespace demo {

Image image_from_gl_rows(const std::vector<std::uint8_t> &bottom_up, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(bottom_up.size());
  const size_t row = static_cast<size_t>(width) * 4u;
  for (int y = 0; y < height; ++y) {
    std::memcpy(&image.rgba[static_cast<size_t>(y) * row], &bottom_up[static_cast<size_t>(height - 1 - y) * row], row);
  }
  return image;
}

std::vector<std::uint8_t> gl_rows_from_image(const Image &image) {
  return image_from_gl_rows(image.rgba, image.width, image.height).rgba;  // the flip is its own inverse
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
      const size_t from = (static_cast<size_t>(y0 + y / zoom) * static_cast<size_t>(image.width) +
                           static_cast<size_t>(x0 + x / zoom)) * 4u;
      const size_t to = (static_cast<size_t>(y) * static_cast<size_t>(out.width) + static_cast<size_t>(x)) * 4u;
      std::memcpy(&out.rgba[to], &image.rgba[from], 4);
    }
  }
  return out;
}

Image side_by_side(const Image &left, const Image &right, int gap) {
  Image out;
  out.width = left.width + gap + right.width;
  out.height = std::min(left.height, right.height);
  out.rgba.assign(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * 4u, 255);
  for (int y = 0; y < out.height; ++y) {
    std::memcpy(&out.rgba[static_cast<size_t>(y) * static_cast<size_t>(out.width) * 4u],
                &left.rgba[static_cast<size_t>(y) * static_cast<size_t>(left.width) * 4u],
                static_cast<size_t>(left.width) * 4u);
    std::memcpy(&out.rgba[(static_cast<size_t>(y) * static_cast<size_t>(out.width) + static_cast<size_t>(left.width + gap)) * 4u],
                &right.rgba[static_cast<size_t>(y) * static_cast<size_t>(right.width) * 4u],
                static_cast<size_t>(right.width) * 4u);
  }
  return out;
}

void fill_rect(Image *image, int x0, int y0, int x1, int y1, const std::uint8_t rgb[3]) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image->width);
  y1 = std::min(y1, image->height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      std::uint8_t *p = &image->rgba[(static_cast<size_t>(y) * static_cast<size_t>(image->width) + static_cast<size_t>(x)) * 4u];
      p[0] = rgb[0];
      p[1] = rgb[1];
      p[2] = rgb[2];
      p[3] = 255;
    }
}

void draw_text(Image *image, int x, int y, const char *text, int scale, const std::uint8_t rgb[3]) {
  // stb_easy_font emits axis-aligned quads: 4 vertices of {x, y, z float; 4 colour bytes}.
  struct Vertex {
    float x, y, z;
    unsigned char colour[4];
  };
  std::vector<Vertex> vertices(4 * 1000);
  std::string copy(text);
  const int quads = stb_easy_font_print(0.0f, 0.0f, &copy[0], nullptr, vertices.data(),
                                        static_cast<int>(vertices.size() * sizeof(Vertex)));
  static const std::uint8_t kShadow[3] = {0, 0, 0};
  for (int pass = 0; pass < 2; ++pass) {
    const int offset = pass == 0 ? std::max(1, scale / 2) : 0;
    for (int q = 0; q < quads; ++q) {
      const Vertex &a = vertices[static_cast<size_t>(4 * q)];
      const Vertex &c = vertices[static_cast<size_t>(4 * q + 2)];
      fill_rect(image, x + offset + static_cast<int>(a.x) * scale, y + offset + static_cast<int>(a.y) * scale,
                x + offset + static_cast<int>(c.x) * scale, y + offset + static_cast<int>(c.y) * scale,
                pass == 0 ? kShadow : rgb);
    }
  }
}

void largest_difference(const Image &a, const Image &b, int window, int *centre_x, int *centre_y) {
  // Summed-area table of the per-pixel difference.
  const size_t w = static_cast<size_t>(a.width), h = static_cast<size_t>(a.height);
  std::vector<long long> sum((w + 1) * (h + 1), 0);
  for (size_t y = 0; y < h; ++y) {
    long long row = 0;
    for (size_t x = 0; x < w; ++x) {
      const size_t i = (y * w + x) * 4u;
      for (size_t c = 0; c < 3; ++c) row += std::abs(static_cast<int>(a.rgba[i + c]) - static_cast<int>(b.rgba[i + c]));
      sum[(y + 1) * (w + 1) + x + 1] = sum[y * (w + 1) + x + 1] + row;
    }
  }
  window = std::max(1, std::min({window, a.width, a.height}));
  const int step = std::max(1, window / 4);
  long long best = -1;
  *centre_x = a.width / 2;
  *centre_y = a.height / 2;
  for (int y = 0; y + window <= a.height; y += step) {
    for (int x = 0; x + window <= a.width; x += step) {
      const size_t x0 = static_cast<size_t>(x), y0 = static_cast<size_t>(y);
      const size_t x1 = x0 + static_cast<size_t>(window), y1 = y0 + static_cast<size_t>(window);
      const long long s = sum[y1 * (w + 1) + x1] - sum[y0 * (w + 1) + x1] - sum[y1 * (w + 1) + x0] + sum[y0 * (w + 1) + x0];
      if (s > best) {
        best = s;
        *centre_x = x + window / 2;
        *centre_y = y + window / 2;
      }
    }
  }
}

}  // namespace demo
