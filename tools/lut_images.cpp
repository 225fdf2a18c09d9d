// Writes the pre-integrated LUTs and the figures of docs/preintegrated.md (after Penner and
// Borshukov's Figures 1.2-1.4) as PNGs, from the math layer:
//   sss_lut_images --out docs/preintegrated [--size 256] [--threads 0]
// diffuse-lut.png        D(N·L, curvature): N·L -1..1 left to right, curvature 0..1/mm bottom to top
// shadow-lut-box.png     P_S(s, w) for a box PCF: s 0..1 left to right, w 1..32 mm bottom to top
// shadow-lut-gaussian.png the same for a Gaussian PCF
// spheres.png            spheres of radius 2..64 mm lit from the right: Lambert (top), LUT (bottom)
// shadow-edge.png        a straight shadow edge for 2, 8, 32 mm penumbrae: filter (grey), LUT (colour)
// Values are linear light, written as sRGB.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "math/preintegrated_lut.hpp"
#include "png.hpp"

namespace {

using sss_tools::srgb8;

struct Lut {
  int width = 0, height = 0;
  std::vector<float> rgba;
  // Bilinear lookup at grid coordinates u, v in [0, 1] (endpoint-inclusive grid).
  std::array<double, 3> sample(double u, double v) const {
    const double x = std::clamp(u, 0.0, 1.0) * (width - 1), y = std::clamp(v, 0.0, 1.0) * (height - 1);
    const int x0 = std::min(static_cast<int>(x), width - 2), y0 = std::min(static_cast<int>(y), height - 2);
    const double fx = x - x0, fy = y - y0;
    std::array<double, 3> out{};
    for (std::size_t c = 0; c < 3; ++c) {
      auto at = [&](int xx, int yy) { return static_cast<double>(rgba[4 * static_cast<std::size_t>(yy * width + xx) + c]); };
      out[c] = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
    }
    return out;
  }
};

bool write_lut(const std::string& path, const Lut& lut) {
  std::vector<unsigned char> rgb(static_cast<std::size_t>(lut.width) * lut.height * 3);
  for (int y = 0; y < lut.height; ++y) {
    const int row = lut.height - 1 - y;  // last row (largest curvature / penumbra) at the top
    for (int x = 0; x < lut.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        rgb[3 * static_cast<std::size_t>(y * lut.width + x) + c] =
            srgb8(lut.rgba[4 * static_cast<std::size_t>(row * lut.width + x) + c]);
      }
    }
  }
  return sss_tools::write_png(path, lut.width, lut.height, rgb);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  int size = 256, threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--size" && i + 1 < argc) {
      size = std::atoi(argv[++i]);
    } else if (a == "--threads" && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--out DIR] [--size 2..4096] [--threads N]\n", argv[0]);
      return a == "--help" ? 0 : 2;
    }
  }
  if (size < 2 || size > 4096) {
    std::fprintf(stderr, "--size %d: must be in [2, 4096]\n", size);
    return 2;
  }
  const sss::math::RadialProfile& profile = sss::math::deon_skin_profile();
  bool ok = true;

  sss::math::DiffuseLutDesc dd;
  dd.width = dd.height = size;
  Lut diffuse{size, size, std::vector<float>(4u * size * size)};
  sss::math::generate_diffuse_lut(profile, dd, threads, diffuse.rgba.data());
  ok &= write_lut(out + "/diffuse-lut.png", diffuse);

  for (auto [name, filter] : {std::pair<const char*, sss::math::ShadowFilter>{"box", sss::math::ShadowFilter::box},
                              {"gaussian", sss::math::ShadowFilter::gaussian}}) {
    sss::math::ShadowLutDesc sd;
    sd.width = sd.height = size;
    sd.filter = filter;
    Lut shadow{size, size, std::vector<float>(4u * size * size)};
    sss::math::generate_shadow_lut(profile, sd, threads, shadow.rgba.data());
    ok &= write_lut(out + "/shadow-lut-" + name + ".png", shadow);
  }

  // Spheres (Figure 1.3, bottom): each in a 128-pixel cell, light from the right and slightly up.
  const double radii[] = {2.0, 4.0, 8.0, 16.0, 32.0, 64.0};
  const int cell = 128, cols = 6, rows = 2;
  std::vector<unsigned char> spheres(static_cast<std::size_t>(cell * cols) * cell * rows * 3, 0);
  const double lx = 0.9, ly = 0.3, lz = 0.3, ln = std::sqrt(lx * lx + ly * ly + lz * lz);
  for (int s = 0; s < cols; ++s) {
    const double curvature = 1.0 / radii[s];
    for (int py = 0; py < cell; ++py) {
      for (int px = 0; px < cell; ++px) {
        const double nx = (px + 0.5) / cell * 2.2 - 1.1, ny = 1.1 - (py + 0.5) / cell * 2.2;
        const double rr = nx * nx + ny * ny;
        if (rr >= 1.0) continue;
        const double nz = std::sqrt(1.0 - rr);
        const double ndotl = (nx * lx + ny * ly + nz * lz) / ln;
        const auto d = diffuse.sample(ndotl * 0.5 + 0.5, (curvature - dd.curvature_min_per_mm) /
                                                           (dd.curvature_max_per_mm - dd.curvature_min_per_mm));
        for (int c = 0; c < 3; ++c) {
          const std::size_t top = 3 * (static_cast<std::size_t>(py) * cell * cols + s * cell + px) + c;
          const std::size_t bottom = top + static_cast<std::size_t>(cell) * cell * cols * 3;
          spheres[top] = srgb8(std::max(0.0, ndotl));
          spheres[bottom] = srgb8(d[static_cast<std::size_t>(c)]);
        }
      }
    }
  }
  ok &= sss_tools::write_png(out + "/spheres.png", cell * cols, cell * rows, spheres);

  // A straight shadow edge (Figure 1.4): for each penumbra width, the box filter's ramp (grey) and
  // the skin shadow (colour), over ±1 penumbra around it. Strips 24 pixels high.
  sss::math::ShadowLutDesc sd;
  sd.width = sd.height = size;
  Lut box{size, size, std::vector<float>(4u * size * size)};
  sss::math::generate_shadow_lut(profile, sd, threads, box.rgba.data());
  const double widths[] = {0.002, 0.008, 0.032};
  const int strip = 24, edge_w = 512;
  std::vector<unsigned char> edge(static_cast<std::size_t>(edge_w) * strip * 6 * 3, 0);
  for (int k = 0; k < 3; ++k) {
    const double v = (widths[k] - sd.penumbra_min) / (sd.penumbra_max - sd.penumbra_min);
    for (int px = 0; px < edge_w; ++px) {
      const double t = (px + 0.5) / edge_w * 3.0 - 1.0;  // penumbra widths: [-1, 2]
      const double s = std::clamp(t, 0.0, 1.0);          // the box filter's shadow value
      const auto p = box.sample(s, v);
      for (int py = 0; py < strip; ++py) {
        for (int c = 0; c < 3; ++c) {
          edge[3 * (static_cast<std::size_t>((2 * k) * strip + py) * edge_w + px) + c] = srgb8(s);
          edge[3 * (static_cast<std::size_t>((2 * k + 1) * strip + py) * edge_w + px) + c] =
              srgb8(p[static_cast<std::size_t>(c)]);
        }
      }
    }
  }
  ok &= sss_tools::write_png(out + "/shadow-edge.png", edge_w, strip * 6, edge);
  if (!ok) {
    std::fprintf(stderr, "sss_lut_images: writing into %s failed\n", out.c_str());
    return 1;
  }
  std::printf("sss_lut_images: wrote diffuse-lut, shadow-lut-box, shadow-lut-gaussian, spheres, shadow-edge (.png) into %s\n",
              out.c_str());
  return 0;
}
