#include "dump_output.hpp"

#include "heat_map.hpp"

#include <cstdint>
#include <cstdio>
#include <vector>

namespace demo {

namespace {

bool write_pfm(const std::string &path, const std::vector<float> &rgba, int width, int height) {
  std::FILE *f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) {
    std::fprintf(stderr, "sss_demo: cannot write %s\n", path.c_str());
    return false;
  }
  std::fprintf(f, "PF\n%d %d\n-1.0\n", width, height);  // negative scale: little-endian
  std::vector<float> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3u);
  for (size_t i = 0; i < rgb.size() / 3; ++i) {
    for (size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
  }
  bool ok = std::fwrite(rgb.data(), sizeof(float), rgb.size(), f) == rgb.size();
  ok = std::fclose(f) == 0 && ok;
  if (!ok) std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
  return ok;
}

bool write_pgm(const std::string &path, const std::vector<uint8_t> &bottom_up, int width, int height) {
  std::FILE *f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) {
    std::fprintf(stderr, "sss_demo: cannot write %s\n", path.c_str());
    return false;
  }
  std::fprintf(f, "P5\n%d %d\n255\n", width, height);
  bool ok = true;
  for (int y = height - 1; y >= 0; --y) {
    const size_t w = static_cast<size_t>(width);
    ok = std::fwrite(&bottom_up[static_cast<size_t>(y) * w], 1, w, f) == w && ok;
  }
  ok = std::fclose(f) == 0 && ok;
  if (!ok) std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
  return ok;
}

}  // namespace

bool write_frame_dumps(const FrameTargets &targets, bool sss_ran, const std::string &prefix) {
  const std::vector<float> before = read_texture_rgba(targets.diffuse, targets.width, targets.height);
  const std::vector<float> after =
      sss_ran ? read_texture_rgba(targets.after, targets.width, targets.height) : before;
  const std::vector<uint8_t> ids = read_texture_r8ui(targets.profile, targets.width, targets.height);
  const bool a = write_pfm(prefix + "before.pfm", before, targets.width, targets.height);
  const bool b = write_pfm(prefix + "after.pfm", after, targets.width, targets.height);
  return write_pgm(prefix + "ids.pgm", ids, targets.width, targets.height) && a && b;
}

}  // namespace demo
