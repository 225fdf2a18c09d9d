// PNG files through stb_image_write (Debian's libstb provides the implementation), with tEXt
// chunks: the head scan's attribution goes into every image of it ("Copyright"), the settings
// into "Description".
#pragma once

#include "image.hpp"

#include <string>
#include <utility>
#include <vector>

namespace demo {

using PngText = std::vector<std::pair<std::string, std::string>>;  // keyword (1-79 Latin-1 chars), text

// Writes an RGBA8 image (alpha dropped: the images are opaque) with the text chunks after IHDR;
// prints the reason and returns false on failure.
bool write_png(const std::string &path, const Image &image, const PngText &text);

}  // namespace demo
