// CPU-side RGBA8 images: GL's bottom-up rows flipped, magnified crops, labels.
#pragma once

#include <cstdint>
#include <vector>

namespace demo {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // rows top-down, 4 bytes a pixel
};

// Image from glReadPixels output (rows bottom-up).
Image image_from_gl_rows(const std::vector<std::uint8_t> &bottom_up, int width, int height);

// The image's rows bottom-up, as glTexImage2D takes them.
std::vector<std::uint8_t> gl_rows_from_image(const Image &image);

// The `width` x `height` window centred on (centre_x, centre_y) (clamped into the image), each pixel
// repeated `zoom` times in x and y.
Image crop_zoom(const Image &image, int centre_x, int centre_y, int width, int height, int zoom);

// `left` and `right` (the same height) next to each other with a white gap `gap` pixels wide.
Image side_by_side(const Image &left, const Image &right, int gap);

// Text in stb_easy_font's small bitmap font (about 7 x 12 pixels per character at scale 1), its top
// left at (x, y), each font pixel scale x scale, with a one-pixel dark shadow.
void draw_text(Image *image, int x, int y, const char *text, int scale, const std::uint8_t rgb[3]);

// A filled rectangle [x0, x1) x [y0, y1), clipped to the image.
void fill_rect(Image *image, int x0, int y0, int x1, int y1, const std::uint8_t rgb[3]);

// The centre of the window x window block (on a grid of window / 4) where a and b (the same size)
// differ most (sum of |a - b| over RGB): where the effect of a filter is easiest to see.
void largest_difference(const Image &a, const Image &b, int window, int *centre_x, int *centre_y);

}  // namespace demo
