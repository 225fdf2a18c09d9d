// sss_demo_image_check: checks on the PNGs sss_demo writes, for the demo's ctest entries.
//
//   sss_demo_image_check headless DIR ATTRIBUTION PRESET...
//       every PRESET-{before,after,split,heatmap,touched,zoom}.png exists, decodes, has valid chunk
//       CRCs and a tEXt "Copyright" chunk that contains ATTRIBUTION; before and after are not
//       blank (see not_blank), have the same size, and differ (the library changed some pixels) but not everywhere
//       (the background is left alone); the split's left part is before and its right part after;
//       the heat map uses the error ramp; the touched map has orange pixels; README.txt and
//       ATTRIBUTION.txt exist; a PRESET-zoom-texturing.png where there is one carries the attribution
//       too, is not blank and is three panels the zoom's size wide (4-pixel gaps).
//   sss_demo_image_check views DIR ATTRIBUTION PRESET
//       the library's debug views (--debug-view all) of the head: every PRESET-view-NAME.png exists
//       with the attribution and before.png's size; the mask view's orange pixels are the pixels
//       the library ran on (at least the touched map's orange ones, at most those and its blue
//       ones); at those pixels the depth view is grey and varies, the footprint and taps views
//       carry their two channels over the 0.15 blue, the profile view shows profile 0's hue, and
//       the tiles view is near white (a marked tile both draws cover); somewhere the tiles view
//       shows the inputs draw alone (green).
//   sss_demo_image_check window FRAME.png WINDOW.png REFERENCE.png
//       the window's screenshot: FRAME (the frame as rendered) is not blank and matches REFERENCE
//       (the headless render of the same preset and size): mean |difference| <= 0.5 levels of 255
//       and at most 0.5 % of the pixels off by more than 8 levels; WINDOW (with the panel) has
//       FRAME's size and differs from it where the panel is (top left) but not far away from it
//       (right edge, above the attribution line).
// Exit status 0 when every check passed, 1 otherwise (each failure is printed).
#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "check_tool.hpp"

namespace {

using demo_check::check;
using demo_check::g_failures;

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // rows top-down
  std::vector<std::pair<std::string, std::string>> text;
  bool crc_ok = false;
  bool ok() const { return width > 0 && height > 0; }
  const uint8_t *at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3u]; }
};

uint32_t crc32(const uint8_t *data, size_t size) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) {
    c ^= data[i];
    for (int k = 0; k < 8; ++k) c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}

uint32_t be32(const uint8_t *p) {
  return (static_cast<uint32_t>(p[0]) << 24) | (static_cast<uint32_t>(p[1]) << 16) | (static_cast<uint32_t>(p[2]) << 8) | p[3];
}

// Walks the chunks: CRCs and tEXt entries.
void read_chunks(const std::vector<uint8_t> &file, Image *image) {
  static const uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (file.size() < 8 || std::memcmp(file.data(), kSignature, 8) != 0) return;
  size_t at = 8;
  bool all_ok = true;
  while (at + 12 <= file.size()) {
    const uint32_t length = be32(&file[at]);
    if (at + 12 + length > file.size()) {
      all_ok = false;
      break;
    }
    const uint8_t *type = &file[at + 4];
    all_ok = all_ok && crc32(type, 4 + length) == be32(&file[at + 8 + length]);
    if (std::memcmp(type, "tEXt", 4) == 0) {
      const char *data = reinterpret_cast<const char *>(&file[at + 8]);
      const size_t key_length = strnlen(data, length);
      if (key_length < length)
        image->text.emplace_back(std::string(data, key_length), std::string(data + key_length + 1, length - key_length - 1));
    }
    if (std::memcmp(type, "IEND", 4) == 0) break;
    at += 12 + length;
  }
  image->crc_ok = all_ok;
}

Image load(const std::string &path) {
  Image image;
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (file.empty()) {
    check(false, path + " cannot be read");
    return image;
  }
  int components = 0;
  uint8_t *pixels = stbi_load_from_memory(file.data(), static_cast<int>(file.size()), &image.width, &image.height,
                                          &components, 3);
  if (pixels == nullptr) {
    check(false, path + " does not decode: " + (stbi_failure_reason() != nullptr ? stbi_failure_reason() : "?"));
    image.width = image.height = 0;
    return image;
  }
  image.rgb.assign(pixels, pixels + static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3u);
  stbi_image_free(pixels);
  read_chunks(file, &image);
  check(image.crc_ok, path + ": a chunk has a wrong CRC or the file is cut short");
  return image;
}

std::string text_of(const Image &image, const std::string &keyword) {
  for (const auto &[k, v] : image.text)
    if (k == keyword) return v;
  return "";
}

// Not blank: at least 0.1 % of the pixels (and 50) differ by more than 16 levels from the top-left
// pixel (the background) and the luminance is not flat.
bool not_blank(const Image &image) {
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  size_t different = 0;
  double sum = 0.0, sum2 = 0.0;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(static_cast<int>(image.rgb[3 * i + c]) - image.rgb[c]));
    different += worst > 16 ? 1 : 0;
    const double l = 0.2126 * image.rgb[3 * i] + 0.7152 * image.rgb[3 * i + 1] + 0.0722 * image.rgb[3 * i + 2];
    sum += l;
    sum2 += l * l;
  }
  const double mean = sum / static_cast<double>(n);
  const double spread = std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
  return different >= std::max<size_t>(50, n / 1000) && spread > 1.0;
}

struct Difference {
  double mean = 0.0;          // mean |a - b| over the components
  double over_fraction = 0.0; // pixels with some component off by more than `level`
  size_t differing = 0;       // pixels not bit-identical
};

// Over the rectangle [x0, x1) x [y0, y1) (whole image by default).
Difference difference(const Image &a, const Image &b, int level, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1) {
  Difference d;
  if (x1 < 0) x1 = a.width;
  if (y1 < 0) y1 = a.height;
  size_t over = 0, n = 0;
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint8_t *p = a.at(x, y), *q = b.at(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int e = std::abs(static_cast<int>(p[c]) - static_cast<int>(q[c]));
        sum += e;
        worst = std::max(worst, e);
      }
      over += worst > level ? 1 : 0;
      d.differing += worst > 0 ? 1 : 0;
      ++n;
    }
  d.mean = n > 0 ? sum / (3.0 * static_cast<double>(n)) : 0.0;
  d.over_fraction = n > 0 ? static_cast<double>(over) / static_cast<double>(n) : 0.0;
  return d;
}

bool same_size(const Image &a, const Image &b) { return a.ok() && b.ok() && a.width == b.width && a.height == b.height; }

bool exists(const std::string &path) { return std::ifstream(path).good(); }

void check_preset(const std::string &dir, const std::string &attribution, const std::string &preset) {
  const std::string prefix = dir + "/" + preset + "-";
  const char *const names[] = {"before", "after", "split", "heatmap", "touched", "zoom"};
  std::array<Image, 6> images;
  for (size_t i = 0; i < 6; ++i) {
    images[i] = load(prefix + names[i] + ".png");
    check(text_of(images[i], "Copyright").find(attribution) != std::string::npos,
          prefix + names[i] + ".png carries no attribution (tEXt Copyright with '" + attribution + "')");
  }
  // The close-up's zoom in each texturing mode, where the demo wrote it (not with MSAA): three panels
  // with the attribution, not blank.
  if (exists(prefix + "zoom-texturing.png")) {
    const Image texturing = load(prefix + "zoom-texturing.png");
    check(text_of(texturing, "Copyright").find(attribution) != std::string::npos,
          prefix + "zoom-texturing.png carries no attribution");
    check(texturing.ok() && not_blank(texturing) && images[5].ok() && 2 * texturing.width == 3 * images[5].width + 4,
          prefix + "zoom-texturing.png is blank or not three panels wide");
  }
  const Image &before = images[0], &after = images[1], &split = images[2], &heat = images[3], &touched = images[4];
  for (size_t i = 1; i < 5; ++i) check(same_size(before, images[i]), prefix + names[i] + ".png: not the size of before.png");
  if (!same_size(before, after) || !same_size(before, split) || !same_size(before, heat) || !same_size(before, touched))
    return;
  check(not_blank(before), prefix + "before.png is blank");
  check(not_blank(after), prefix + "after.png is blank");
  const Difference d = difference(before, after, 0);
  const size_t pixels = static_cast<size_t>(before.width) * static_cast<size_t>(before.height);
  std::printf("%s: before/after differ in %zu of %zu pixels (mean %.3f levels)\n", preset.c_str(), d.differing, pixels,
              d.mean);
  // The far shot: a pixel there measures more than skin's kernel (millimetres), so the exact result
  // is the input to within a level and the footprint-aware taps leave those pixels alone. Closer
  // shots must change.
  const bool far = preset == "far";
  if (far) {
    check(d.mean < 0.05, prefix + "after.png: the far shot changed by more than the exact result allows");
  } else {
    check(d.differing > 0, prefix + "after.png equals before.png: the library changed nothing");
  }
  check(d.differing < pixels / 2, prefix + "after.png differs from before.png almost everywhere (the background too?)");
  // The split: before left of the 2-pixel divider, after right of it.
  const int divider = before.width / 2;
  check(difference(split, before, 0, 0, 0, divider - 1, before.height).differing == 0,
        prefix + "split.png: the left part is not before.png");
  check(difference(split, after, 0, divider + 1, 0, before.width, before.height).differing == 0,
        prefix + "split.png: the right part is not after.png");
  // The heat map shows ramp colours (the ramp's dark end is (68, 1, 84): red and blue above green).
  size_t ramp = 0, orange = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t *p = &heat.rgb[3 * i];
    ramp += (p[0] != p[1] || p[1] != p[2]) ? 1 : 0;
    const uint8_t *q = &touched.rgb[3 * i];
    orange += (q[0] > q[1] + 40 && q[1] > q[2] + 20) ? 1 : 0;
  }
  check(ramp > 0, prefix + "heatmap.png has no coloured pixel");
  if (!far) check(orange > 0, prefix + "touched.png has no orange pixel");
  std::printf("%s: heat map %zu coloured pixels, touched map %zu orange pixels\n", preset.c_str(), ramp, orange);
}

int headless(int argc, char **argv) {
  if (argc < 5) return 2;
  const std::string dir = argv[2], attribution = argv[3];
  for (int i = 4; i < argc; ++i) check_preset(dir, attribution, argv[i]);
  check(exists(dir + "/README.txt"), dir + "/README.txt is missing");
  check(exists(dir + "/ATTRIBUTION.txt"), dir + "/ATTRIBUTION.txt is missing");
  return g_failures == 0 ? 0 : 1;
}

bool near(const uint8_t *p, int r, int g, int b) {
  return std::abs(p[0] - r) <= 1 && std::abs(p[1] - g) <= 1 && std::abs(p[2] - b) <= 1;
}

int views(int argc, char **argv) {
  if (argc != 5) return 2;
  const std::string dir = argv[2], attribution = argv[3], prefix = dir + "/" + argv[4] + "-";
  const Image before = load(prefix + "before.png"), touched = load(prefix + "touched.png");
  const char *const names[] = {"mask", "depth", "footprint", "taps", "profile", "tiles"};
  std::array<Image, 6> view;
  for (size_t i = 0; i < 6; ++i) {
    const std::string file = prefix + "view-" + names[i] + ".png";
    view[i] = load(file);
    check(same_size(before, view[i]), file + ": missing or not the size of before.png");
    if (!view[i].ok()) continue;
    check(text_of(view[i], "Copyright").find(attribution) != std::string::npos, file + " carries no attribution");
    check(not_blank(view[i]), file + " is blank");
  }
  if (g_failures != 0) return 1;
  const Image &mask = view[0], &depth = view[1], &footprint = view[2], &taps = view[3], &profile = view[4],
              &tiles = view[5];
  size_t ran = 0, changed = 0, unchanged = 0, grey_depth = 0, two_channels = 0, profile_hue = 0, white_tiles = 0,
         inputs_alone = 0;
  int depth_low = 255, depth_high = 0;
  const size_t pixels = static_cast<size_t>(before.width) * static_cast<size_t>(before.height);
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t *t = &touched.rgb[3 * i], *g = &tiles.rgb[3 * i];
    changed += (t[0] > t[1] + 40 && t[1] > t[2] + 20) ? 1 : 0;  // as check_preset's orange
    unchanged += t[2] > t[0] + 40 ? 1 : 0;                      // translucent but unchanged: blue
    inputs_alone += (g[1] > g[0] + 40 && g[1] > g[2] + 40) ? 1 : 0;
    if (!near(&mask.rgb[3 * i], 255, 140, 26)) continue;  // composite.cpp: (1, 0.55, 0.1)
    ++ran;
    const uint8_t *d = &depth.rgb[3 * i], *f = &footprint.rgb[3 * i], *k = &taps.rgb[3 * i];
    if (d[0] == d[1] && d[1] == d[2]) {
      ++grey_depth;
      depth_low = std::min<int>(depth_low, d[0]);
      depth_high = std::max<int>(depth_high, d[0]);
    }
    // Blue 0.15 and not the grey of a pixel left alone (a pixel of one tap a pass is (0, 0, 0.15)).
    const auto carried = [](const uint8_t *p) { return std::abs(p[2] - 38) <= 1 && !(p[0] == p[1] && p[1] == p[2]); };
    two_channels += carried(f) && carried(k) ? 1 : 0;
    profile_hue += near(&profile.rgb[3 * i], 242, 140, 115) ? 1 : 0;  // profile 0: (0.95, 0.55, 0.45)
    white_tiles += std::min({g[0], g[1], g[2]}) >= 150 ? 1 : 0;      // 0.6 of (1, 1, 1) over the grey
  }
  std::printf("views: %zu pixels ran (touched: %zu changed, %zu unchanged); at them grey depth %zu (%d..%d), both "
              "channels %zu, profile hue %zu, white tiles %zu; inputs-only tile pixels %zu\n",
              ran, changed, unchanged, grey_depth, depth_low, depth_high, two_channels, profile_hue, white_tiles,
              inputs_alone);
  check(ran > 0, "the mask view shows no pixel");
  // The touched map's colours are a blend over the frame's grey, read back through 8 bits: 2 % slack.
  check(static_cast<double>(ran) >= 0.98 * static_cast<double>(changed), "the mask view misses pixels the library changed");
  check(static_cast<double>(ran) <= 1.02 * static_cast<double>(changed + unchanged),
        "the mask view shows pixels that are not translucent");
  check(grey_depth == ran && depth_high - depth_low > 20, "the depth view is not a varying grey on the skin");
  check(two_channels == ran, "the footprint or taps view lacks its channels on the skin");
  check(profile_hue == ran, "the profile view does not show profile 0 on the head");
  check(white_tiles == ran, "the tiles view does not mark every tile with skin");
  check(inputs_alone > 0, "the tiles view shows no tile the inputs draw covers alone");
  return g_failures == 0 ? 0 : 1;
}

int window(int argc, char **argv) {
  if (argc != 5) return 2;
  const Image frame = load(argv[2]), shown = load(argv[3]), reference = load(argv[4]);
  check(same_size(frame, reference), std::string(argv[2]) + " and " + argv[4] + " differ in size");
  check(same_size(frame, shown), std::string(argv[2]) + " and " + argv[3] + " differ in size");
  if (g_failures != 0) return 1;
  check(not_blank(frame), std::string(argv[2]) + " is blank");
  check(text_of(frame, "Copyright").find("Lee Perry-Smith") != std::string::npos,
        std::string(argv[2]) + " carries no attribution (tEXt Copyright)");
  const Difference d = difference(frame, reference, 8);
  std::printf("window frame against the headless render: mean |difference| %.4f levels, %.4f %% of pixels off by > 8, "
              "%zu pixels not bit-identical\n", d.mean, 100.0 * d.over_fraction, d.differing);
  check(d.mean <= 0.5, "the window's frame does not match the headless render (mean)");
  check(d.over_fraction <= 0.005, "the window's frame does not match the headless render (outliers)");
  // The panel (top left) is drawn over the frame; the right edge above the attribution is not.
  const Difference panel = difference(shown, frame, 2, 0, 0, frame.width / 4, frame.height / 4);
  const Difference clear = difference(shown, frame, 0, frame.width - 8, 0, frame.width, frame.height / 2);
  std::printf("window with the panel: %.1f %% of the top-left quarter-square changed, %zu pixels changed at the right edge\n",
              100.0 * panel.over_fraction, clear.differing);
  check(panel.over_fraction > 0.3, std::string(argv[3]) + ": no panel in the top left");
  check(clear.differing == 0, std::string(argv[3]) + ": the frame is not shown under the panel");
  return g_failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char **argv) {
  return demo_check::run_mode(argc, argv, {{"headless", headless}, {"views", views}, {"window", window}},
                              "headless DIR ATTRIBUTION PRESET... | views DIR ATTRIBUTION PRESET | "
                              "window FRAME.png WINDOW.png REFERENCE.png");
}
