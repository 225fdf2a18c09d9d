#include "png.hpp"

#include <algorithm>
#include <cmath>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace sss_tools {

unsigned char srgb8(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(s * 255.0));
}

bool write_png(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb) {
  return stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
}

bool read_rgb(const std::string& path, int* width, int* height, std::vector<unsigned char>* rgb) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), width, height, &channels, 3);
  if (data == nullptr) return false;
  rgb->assign(data, data + static_cast<std::size_t>(*width) * static_cast<std::size_t>(*height) * 3);
  stbi_image_free(data);
  return true;
}

}  // namespace sss_tools
