// PNG files through stb_image_write (Debian's libstb provides the implementation).
#pragma once

#include "image.hpp"

#include <string>

namespace demo {

// Writes an RGBA8 image; prints the reason and returns false on failure.
bool write_png(const std::string &path, const Image &image);

}  // namespace demo
