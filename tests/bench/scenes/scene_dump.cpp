// sss_scene_dump: writes the canonical scenes as PNG for a person to look at.
//
//   sss_scene_dump [--backend osmesa|egl|egl-device] [--size WxH] [--scene NAME]... OUTDIR
//
// For each scene (all of them unless --scene is given): NAME_irradiance.png (linear irradiance,
// tone-mapped x(1 + x/16)/(1 + x) (white point 4), sRGB-encoded) and NAME_mask.png (white where
// translucent), and it prints the time make_scene took. Images of the head scenes carry the scan's
// attribution (CC BY 3.0) in a PNG tEXt "Copyright" chunk, and OUTDIR/ATTRIBUTION.txt repeats it.
#include <stb/stb_image_write.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "host_context.hpp"
#include "host_gl.hpp"
#include "scenes.hpp"
#include "sss_headless.h"

namespace {

uint32_t crc32(const uint8_t* data, size_t size) {
  static uint32_t table[256];
  static bool ready = false;
  if (!ready) {
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[n] = c;
    }
    ready = true;
  }
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
}

// A PNG tEXt chunk (keyword, NUL, Latin-1 text), with its length and CRC.
std::vector<uint8_t> text_chunk(const std::string& keyword, const std::string& text) {
  std::vector<uint8_t> body = {'t', 'E', 'X', 't'};
  body.insert(body.end(), keyword.begin(), keyword.end());
  body.push_back(0);
  body.insert(body.end(), text.begin(), text.end());
  std::vector<uint8_t> chunk;
  put_u32(chunk, static_cast<uint32_t>(body.size() - 4));
  chunk.insert(chunk.end(), body.begin(), body.end());
  put_u32(chunk, crc32(body.data(), body.size()));
  return chunk;
}

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

// Writes rows given bottom first (GL order) as a PNG, with tEXt chunks after IHDR.
bool write_png(const std::string& path, int width, int height, int components, const std::vector<uint8_t>& bottom_up,
               const std::vector<std::pair<std::string, std::string>>& texts) {
  const size_t row = static_cast<size_t>(width) * static_cast<size_t>(components);
  std::vector<uint8_t> top_down(bottom_up.size());
  for (int j = 0; j < height; ++j)
    std::memcpy(&top_down[static_cast<size_t>(height - 1 - j) * row], &bottom_up[static_cast<size_t>(j) * row], row);
  std::vector<uint8_t> png;
  if (stbi_write_png_to_func(append_bytes, &png, width, height, components, top_down.data(), static_cast<int>(row)) == 0)
    return false;
  const size_t after_ihdr = 8 + 4 + 4 + 13 + 4;  // signature, IHDR length, type, data, CRC
  if (png.size() < after_ihdr) return false;
  std::vector<uint8_t> chunks;
  for (const auto& t : texts) {
    const std::vector<uint8_t> c = text_chunk(t.first, t.second);
    chunks.insert(chunks.end(), c.begin(), c.end());
  }
  png.insert(png.begin() + static_cast<std::ptrdiff_t>(after_ihdr), chunks.begin(), chunks.end());
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  const bool ok = std::fwrite(png.data(), 1, png.size(), f) == png.size();
  return std::fclose(f) == 0 && ok;
}

uint8_t encode_srgb(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(s * 255.0));
}

double tone_map(double x) { return x * (1.0 + x / 16.0) / (1.0 + x); }

int usage() {
  std::fprintf(stderr,
               "usage: sss_scene_dump [--backend osmesa|egl|egl-device] [--size WxH] [--scene NAME]... OUTDIR\n"
               "scenes:");
  for (const std::string& n : sss_bench::canonical_scene_names()) std::fprintf(stderr, " %s", n.c_str());
  std::fprintf(stderr, "\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  sss_headless_backend backend = SSS_HEADLESS_OSMESA;
  int width = 1920, height = 1080;
  std::vector<std::string> names;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--backend" && i + 1 < argc) {
      if (sss_headless_backend_from_name(argv[++i], &backend) != 0) return usage();
    } else if (arg == "--size" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 1 || height < 1) return usage();
    } else if (arg == "--scene" && i + 1 < argc) {
      names.push_back(argv[++i]);
    } else if (!arg.empty() && arg[0] != '-' && out_dir.empty()) {
      out_dir = arg;
    } else {
      return usage();
    }
  }
  if (out_dir.empty()) return usage();
  if (names.empty()) names = sss_bench::canonical_scene_names();

  sss_headless* headless = nullptr;
  bool any_head = false;
  for (const std::string& n : names) any_head = any_head || sss_bench::scene_needs_gl(n);
  if (any_head) {
    headless = sss_test::open_host_context(backend, "sss_scene_dump");
    if (headless == nullptr) return 1;
    std::printf("GL_RENDERER: %s\n", sss_headless_renderer(headless));
  }

  int status = 0;
  for (const std::string& name : names) {
    try {
      const auto start = std::chrono::steady_clock::now();
      const sss_bench::Scene s = sss_bench::make_scene(name, width, height);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const size_t n = static_cast<size_t>(s.width) * static_cast<size_t>(s.height);
      std::vector<uint8_t> rgb(n * 3), mask(n);
      size_t translucent = 0;
      for (size_t p = 0; p < n; ++p) {
        for (int c = 0; c < 3; ++c) rgb[p * 3 + static_cast<size_t>(c)] = encode_srgb(tone_map(s.irradiance[p * 4 + static_cast<size_t>(c)]));
        mask[p] = s.mask[p] != 0 ? 255 : 0;
        translucent += s.mask[p] != 0 ? 1 : 0;
      }
      std::vector<std::pair<std::string, std::string>> texts = {
          {"Software", "sss_scene_dump (sss benchmark scenes)"},
          {"Description", "sss canonical scene '" + name + "' " + std::to_string(width) + "x" + std::to_string(height)}};
      if (sss_bench::scene_needs_gl(name)) texts.emplace_back("Copyright", sss_bench::head_attribution());
      const bool ok = write_png(out_dir + "/" + name + "_irradiance.png", s.width, s.height, 3, rgb, texts) &&
                      write_png(out_dir + "/" + name + "_mask.png", s.width, s.height, 1, mask, texts);
      std::printf("%-11s %dx%d  %8.1f ms  translucent %5.1f %%%s\n", name.c_str(), s.width, s.height, ms,
                  100.0 * static_cast<double>(translucent) / static_cast<double>(n), ok ? "" : "  (write failed)");
      if (!ok) status = 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sss_scene_dump: %s: %s\n", name.c_str(), e.what());
      status = 1;
    }
  }
  if (any_head) {
    FILE* f = std::fopen((out_dir + "/ATTRIBUTION.txt").c_str(), "w");
    if (f != nullptr) {
      std::fprintf(f, "The head images here show a 3D scan: %s\n", sss_bench::head_attribution());
      std::fclose(f);
    }
    sss_headless_destroy(headless);
  }
  return status;
}
