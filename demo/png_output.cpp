#include "png_output.hpp"

#include <stb/stb_image_write.h>

#include <array>
#include <cstdint>
#include <cstdio>

namespace demo {

namespace {

// CRC-32 of PNG chunks (ISO 3309, reflected polynomial 0xEDB88320).
std::uint32_t crc32(const std::vector<std::uint8_t> &bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::uint8_t b : bytes) c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void append_be32(std::vector<std::uint8_t> *out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<std::uint8_t>(v >> shift));
}

// length, "tEXt", keyword, NUL, text, CRC over type and data.
std::vector<std::uint8_t> text_chunk(const std::string &keyword, const std::string &text) {
  std::vector<std::uint8_t> typed = {'t', 'E', 'X', 't'};
  typed.insert(typed.end(), keyword.begin(), keyword.end());
  typed.push_back(0);
  typed.insert(typed.end(), text.begin(), text.end());
  std::vector<std::uint8_t> chunk;
  append_be32(&chunk, static_cast<std::uint32_t>(typed.size() - 4));
  chunk.insert(chunk.end(), typed.begin(), typed.end());
  append_be32(&chunk, crc32(typed));
  return chunk;
}

void append_to_vector(void *context, void *data, int size) {
  auto *out = static_cast<std::vector<std::uint8_t> *>(context);
  const auto *bytes = static_cast<const std::uint8_t *>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

bool write_png(const std::string &path, const Image &image, const PngText &text) {
  std::vector<std::uint8_t> rgb(static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3u);
  for (size_t i = 0, n = rgb.size() / 3; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = image.rgba[i * 4 + c];
  std::vector<std::uint8_t> png;
  if (stbi_write_png_to_func(append_to_vector, &png, image.width, image.height, 3, rgb.data(), image.width * 3) == 0) {
    std::fprintf(stderr, "sss_demo: could not encode %s\n", path.c_str());
    return false;
  }
  // The signature (8 bytes) and IHDR (4 length + 4 type + 13 data + 4 CRC) come first.
  const size_t after_ihdr = 8 + 25;
  std::vector<std::uint8_t> chunks;
  for (const auto &[keyword, value] : text) {
    const std::vector<std::uint8_t> chunk = text_chunk(keyword, value);
    chunks.insert(chunks.end(), chunk.begin(), chunk.end());
  }
  png.insert(png.begin() + static_cast<std::ptrdiff_t>(after_ihdr), chunks.begin(), chunks.end());

  std::FILE *f = std::fopen(path.c_str(), "wb");
  bool ok = f != nullptr && std::fwrite(png.data(), 1, png.size(), f) == png.size();
  if (f != nullptr) ok = std::fclose(f) == 0 && ok;
  if (!ok) std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
  return ok;
}

}  // namespace demo
