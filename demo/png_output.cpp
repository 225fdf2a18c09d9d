#include "png_output.hpp"

#include <stb/stb_image_write.h>

#include <cstdio>

namespace demo {

bool write_png(const std::string &path, const Image &image) {
  const int ok = stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4);
  if (ok == 0) {
    std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
    return false;
  }
  return true;
}

}  // namespace demo
