// Blurs a tangent-space normal map with the diffusion profile (Penner and Borshukov §1.5), giving the
// N_low map that integration/preintegrated/sss_preintegrated.glsl blends per channel:
//   sss_blur_normals --in normal.jpg --out normal-blurred.png (--texel-mm 0.35 | --mesh head.glb)
//                    [--channel r|g|b] [--preview PNG]
// --preview writes a 512x256 side-by-side of a 256x256 crop at the map's centre, before and after.
// The map is decoded to vectors (rgb·2 - 1), blurred linearly without renormalising in between
// (Kilgard's linear normal filtering, which the paper adopts), renormalised and encoded again. The
// blur is the profile's channel (red by default: the widest), radially symmetric, at the given
// size of a texel in mm; sums of Gaussians are applied term by term as separable Gaussians, clamped
// at the map's edges. It prints the per-channel blend factors for the include: each channel's RMS
// scattering radius over the blurred channel's (red 1, green ~0.22, blue ~0.13 for skin).
// --mesh measures the texel size from the mesh instead: the median over triangles of
// sqrt(world area / texel area), in mm (glTF is in metres).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "math/normal_blur.hpp"
#include "png.hpp"
#if defined(SSS_TOOLS_HAVE_GLTF)
#include "gltf_mesh.hpp"
#endif

namespace {

#if defined(SSS_TOOLS_HAVE_GLTF)
double texel_mm_from_mesh(const std::string& path, int w, int h) {
  const gltf_mesh::Model m = gltf_mesh::load_gltf(path);
  std::vector<double> ratios;
  const auto* v = m.vertices.data();
  const int stride = gltf_mesh::Model::kFloatsPerVertex;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const float* a = v + static_cast<std::size_t>(m.indices[t]) * stride;
    const float* b = v + static_cast<std::size_t>(m.indices[t + 1]) * stride;
    const float* c = v + static_cast<std::size_t>(m.indices[t + 2]) * stride;
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
    const double world = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    const double texels = 0.5 * std::fabs((b[6] - a[6]) * (c[7] - a[7]) - (c[6] - a[6]) * (b[7] - a[7])) * w * h;
    if (world > 0.0 && texels > 1e-6) ratios.push_back(std::sqrt(world / texels) * 1000.0);
  }
  if (ratios.empty()) return 0.0;
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2), ratios.end());
  return ratios[ratios.size() / 2];
}
#endif

}  // namespace

int main(int argc, char** argv) {
  std::string in, out, mesh, preview;
  double texel_mm = 0.0;
  std::size_t channel = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--in" && i + 1 < argc) {
      in = argv[++i];
    } else if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--texel-mm" && i + 1 < argc) {
      texel_mm = std::atof(argv[++i]);
    } else if (a == "--preview" && i + 1 < argc) {
      preview = argv[++i];
    } else if (a == "--mesh" && i + 1 < argc) {
      mesh = argv[++i];
    } else if (a == "--channel" && i + 1 < argc) {
      const std::string c = argv[++i];
      channel = c == "g" ? 1 : c == "b" ? 2 : 0;
    } else {
      std::fprintf(stderr, "usage: %s --in MAP --out PNG (--texel-mm MM | --mesh FILE.glb) [--channel r|g|b]\n", argv[0]);
      return a == "--help" ? 0 : 2;
    }
  }
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
  if (in.empty() || out.empty() || !sss_tools::read_rgb(in, &w, &h, &rgb)) {
    std::fprintf(stderr, "sss_blur_normals: cannot read --in '%s' (and --out is needed)\n", in.c_str());
    return 2;
  }
  if (!mesh.empty()) {
#if defined(SSS_TOOLS_HAVE_GLTF)
    texel_mm = texel_mm_from_mesh(mesh, w, h);
    std::printf("texel size from %s: %.4f mm (median over triangles)\n", mesh.c_str(), texel_mm);
#else
    std::fprintf(stderr, "sss_blur_normals: built without tinygltf: give --texel-mm\n");
    return 2;
#endif
  }
  if (!(texel_mm > 0.0 && texel_mm < 1e3)) {
    std::fprintf(stderr, "sss_blur_normals: texel size %g mm: must be in (0, 1000)\n", texel_mm);
    return 2;
  }
  const sss::math::RadialProfile& profile = sss::math::deon_skin_profile();
  const std::vector<unsigned char> encoded =
      sss::math::blur_normal_map(rgb, w, h, texel_mm, profile, static_cast<int>(channel));
  if (!sss_tools::write_png(out, w, h, encoded)) {
    std::fprintf(stderr, "sss_blur_normals: cannot write %s\n", out.c_str());
    return 1;
  }
  if (!preview.empty() && w >= 256 && h >= 256) {
    const int cx = w / 2 - 128, cy = h / 2 - 128;
    std::vector<unsigned char> side(512u * 256u * 3u);
    for (int y = 0; y < 256; ++y) {
      for (int x = 0; x < 256; ++x) {
        for (int c = 0; c < 3; ++c) {
          const std::size_t src = 3 * (static_cast<std::size_t>(cy + y) * w + static_cast<std::size_t>(cx + x)) + c;
          side[3 * (static_cast<std::size_t>(y) * 512 + x) + c] = rgb[src];
          side[3 * (static_cast<std::size_t>(y) * 512 + 256 + x) + c] = encoded[src];
        }
      }
    }
    if (!sss_tools::write_png(preview, 512, 256, side)) {
      std::fprintf(stderr, "sss_blur_normals: cannot write %s\n", preview.c_str());
      return 1;
    }
  }
  const std::array<double, 3> blend = sss::math::normal_blend_factors(profile, static_cast<int>(channel));
  std::printf("wrote %s (%dx%d, texel %.4f mm, profile channel %c)\n", out.c_str(), w, h, texel_mm, "rgb"[channel]);
  std::printf("blend for sss_skin_normals: vec3(%.3f, %.3f, %.3f)\n", blend[0], blend[1], blend[2]);
  return 0;
}
