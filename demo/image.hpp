// CPU-side RGBA8 images: flipping GL's bottom-up rows and building the before/after split.
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

// The `width` x `height` window centred on (centre_x, centre_y) (clamped into the image), each pixel
// repeated `zoom` times in x and y.
Image crop_zoom(const Image &image, int centre_x, int centre_y, int width, int height, int zoom);

// Left half of `left`, right half of `right`, a white divider `divider` pixels wide at the centre.
Image make_split(const Image &left, const Image &right, int divider);

}  // namespace demo
