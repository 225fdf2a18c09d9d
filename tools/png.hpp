// Small PNG helpers for the tools (stb_image_write / stb_image from Debian's libstb).
#pragma once

#include <string>
#include <vector>

namespace sss_tools {

// Linear [0, 1] to an 8-bit sRGB code.
unsigned char srgb8(double linear);
// Writes RGB bytes, top row first. False on failure.
bool write_png(const std::string& path, int width, int height, const std::vector<unsigned char>& rgb);
// Reads an image as 8-bit RGB (any format stb_image reads). False on failure.
bool read_rgb(const std::string& path, int* width, int* height, std::vector<unsigned char>* rgb);

}  // namespace sss_tools
