#include "cpu_separable_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "cpu_filter_passes.hpp"
#include "half_float.hpp"
#include "pass_surface.hpp"
#include "tile_culling.hpp"

namespace sss::math {

namespace {

using cpu_passes::in_colour_range;
using cpu_passes::Plane;
using cpu_passes::Rgba;

// The follow-surface blend of one tap towards the centre colour (GLSL mix()).
void follow_surface_blend(std::array<float, 3>* tap, const Rgba& centre, float d, bool gaussian_depth,
                          float inv_two_variance) {
  float s = gaussian_depth ? 1.0f - std::exp(-d * d * inv_two_variance) : d;
  if (!(s < 1.0f)) s = 1.0f;  // also catches NaN
  for (int c = 0; c < 3; ++c) (*tap)[static_cast<std::size_t>(c)] = (*tap)[static_cast<std::size_t>(c)] * (1.0f - s) + centre[static_cast<std::size_t>(c)] * s;
}

// Per-pixel profiles: each pixel's index (nullptr: none, every pixel the one kernel).
struct Indices {
  const std::uint16_t* ids = nullptr;
  int width = 0;
  std::uint16_t at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

// What every pixel of a pass shares: the frame's constants (depth linearisation, clamp, view
// offsets), the view distance per pixel as the passes' inputs hold it, the per-pixel profiles'
// indices, and how the model walks the surface.
struct PassFrame {
  const PassConstants& shared;
  const Plane& distance;
  Indices indices;
  CpuWalkChoices walk;
  std::uint32_t noise_index;  // CpuFilterImage::noise_index
  std::uint32_t debug_view;   // CpuFilterImage::debug_view
};

// The neighbour (x + ox, y + oy) of (x, y) for the surface's tangent (pass_surface.hpp): inside the
// clamp rectangle, with the view distance the passes' inputs hold (NaN for a colour they do not
// blur), in front of the camera, and with per-pixel profiles the centre's whole index (another
// object is another surface).
Neighbour neighbour_at(const PassConstants& shared, const Plane& distance, const Indices& indices, int x, int y,
                       int ox, int oy) {
  Neighbour n;
  if (!cpu_passes::inside(shared, x + ox, y + oy)) return n;
  n.distance = distance.at(x + ox, y + oy, 0);
  const float w = clip_w(shared, n.distance);
  n.usable = w > 0.0f && w < 1e30f;  // false for a NaN distance too (pass_surface.glsl)
  if (indices.ids != nullptr && indices.at(x + ox, y + oy) != indices.at(x, y)) n.usable = false;
  return n;
}

// The pass's walk over the surface at (x, y) (pass_surface.hpp), from the distances of its four
// neighbours (the vertical pass needs both tangents; the horizontal one only T_x).
PassGeometry pass_geometry(const PassFrame& frame, int axis, int x, int y, float d0) {
  if (frame.walk.facing) return PassGeometry{};
  const PassConstants& shared = frame.shared;
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  const std::array<float, 2> g = ray_slope(shared, cx, cy);
  const auto neighbour = [&](int ox, int oy) {
    return neighbour_at(shared, frame.distance, frame.indices, x, y, ox, oy);
  };
  const TangentRule rule = frame.walk.tangent;
  const Float3 tx = surface_tangent(shared, g, 0, d0, neighbour(-1, 0), neighbour(1, 0), rule);
  PassGeometry walk;
  if (axis == 0) {
    walk = horizontal_geometry(shared, g, d0, tx);
  } else {
    const Float3 ty = surface_tangent(shared, g, 1, d0, neighbour(0, -1), neighbour(0, 1), rule);
    walk = vertical_geometry(shared, g, d0, tx, ty);
  }
  walk.slack *= frame.walk.slack / kFollowSurfaceSlack;
  return walk;
}

// The taps of one pixel's pass as it blends them (follow-surface, per-pixel profiles), each side's
// in order outwards, and their 3D distances from the centre in profile millimetres (chords only).
struct PassTapColours {
  std::array<std::array<std::array<float, 3>, kMaxFootprintHalfTaps>, 2> colour{};
  std::array<std::array<float, kMaxFootprintHalfTaps>, 2> chord_mm{};
};

// The view-space distance between the centre (distance d0) and a tap whose pixel centre sits
// (ox, oy) window pixels away at distance d (pass_surface.hpp's ΔP), times to_mm.
float chord_mm(const PassConstants& k, const std::array<float, 2>& g, float ox, float oy, float d, float d0,
               float to_mm) {
  const float w = clip_w(k, d), dd = d - d0;
  const float px = k.pixel_span[0] * ox * w + dd * g[0], py = k.pixel_span[1] * oy * w + dd * g[1];
  const float c = std::sqrt(px * px + py * py + dd * dd) * to_mm;
  return std::isfinite(c) ? c : 1e30f;
}

// CpuWalkChoices::chords: the centre's delta, then on each side the kernel's half-CDF between the
// midpoints of consecutive taps' chords (made non-decreasing outwards), the centre taking what lies
// inside half the first tap's chord and the last tap the rest.
Rgba chord_weighted_sum(const FootprintTable& table, const Rgba& centre, int count, PassTapColours* taps) {
  Rgba sum = {0.0f, 0.0f, 0.0f, centre[3]};
  for (std::size_t c = 0; c < 3; ++c) sum[c] = centre[c] * table.delta[c];
  for (std::size_t side = 0; side < 2; ++side) {
    auto& mm = taps->chord_mm[side];
    for (std::size_t i = 1; i < static_cast<std::size_t>(count); ++i) mm[i] = std::max(mm[i], mm[i - 1]);
    std::array<float, 3> below = footprint_half_cdf(table, 0.5f * mm[0]);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += centre[c] * below[c];
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
      const std::array<float, 3> upto = i + 1 < static_cast<std::size_t>(count)
                                            ? footprint_half_cdf(table, 0.5f * (mm[i] + mm[i + 1]))
                                            : table.half_cdf.back();
      for (std::size_t c = 0; c < 3; ++c) sum[c] += (upto[c] - below[c]) * taps->colour[side][i][c];
      below = upto;
    }
  }
  return sum;
}

// A debug view's pass at a pixel the passes run (separable_blur.frag's SSS_DEBUG_VIEW): the
// horizontal pass's footprint (1 / step) and taps in r and g (b and alpha kept); the vertical pass's
// view, reading the horizontal numbers from its source's r and g.
Rgba debug_values(const PassFrame& frame, const Plane& source, int axis, int x, int y, const Rgba& centre,
                  float centre_distance, float step, int tap_count) {
  const float footprint = 1.0f / step;
  const auto taps = static_cast<float>(1 + 2 * tap_count);
  if (axis == 0) return {footprint, taps, centre[2], centre[3]};
  switch (frame.debug_view) {
    case 1: return {1.0f, 1.0f, 1.0f, 1.0f};  // SSS_DEBUG_VIEW_MASK
    case 2: return {centre_distance, centre_distance, centre_distance, 1.0f};  // _LINEAR_DEPTH
    case 3: return {source.at(x, y, 0), footprint, 0.0f, 1.0f};  // _FOOTPRINT
    case 4: return {source.at(x, y, 1), taps, 0.0f, 1.0f};  // _TAPS
    case kAlbedoDebugView: return {1.0f, 1.0f, 1.0f, 1.0f};   // times A_post where it is stored
    default: {  // _PROFILE
      const Indices& ids = frame.indices;
      if (ids.ids == nullptr) return {0.0f, 0.0f, 1.0f, 1.0f};
      const std::uint16_t id = ids.at(x, y);
      return {static_cast<float>(id & 15u), static_cast<float>(id >> 4), 1.0f, 1.0f};
    }
  }
}

// One pass at pixel (x, y) along axis `axis` (0: x, 1: y, sheared: pass_surface.hpp), with the look
// `k` (pixels per mm and the follow-surface numbers) in `frame`. Returns false when the pixel is left as it is (not translucent or no usable depth).
bool filter_pixel(const PassTaps& pass, const PassKernel& kernel, float depth_variance_mm2, const PassConstants& k,
                  const PassFrame& frame, const Plane& source, int axis, int x, int y, Rgba* result) {
  const PassConstants& shared = frame.shared;
  const Plane& distance = frame.distance;
  const Indices& indices = frame.indices;
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  const Rgba centre = source.rgba(x, y);
  if (!(centre[3] > 0.0f) || !in_colour_range(centre.data(), 4)) return false;
  const float strength = std::min(centre[3], 1.0f);
  const float centre_distance = distance.at(x, y, 0);
  const float w = clip_w(shared, centre_distance);
  if (!(w > 0.0f) || std::isinf(w)) return false;

  const PassGeometry walk = pass_geometry(frame, axis, x, y, centre_distance);
  const float step = k.pixels_per_mm[static_cast<std::size_t>(axis)] * strength / w * walk.ratio;
  const bool gaussian_depth = depth_variance_mm2 > 0.0f;
  const float follow_surface = (gaussian_depth ? k.mm_per_world : k.follow_surface_factor) / strength;
  const float inv_two_variance = gaussian_depth ? 0.5f / depth_variance_mm2 : 0.0f;
  Rgba sum = {0.0f, 0.0f, 0.0f, centre[3]};

  // Whole-pixel taps (footprint_kernel.hpp), read without filtering.
  const int jitter_from = kernel.jitter_from;
  const float noise = kernel.jittered() ? jitter_noise(x, y, axis, frame.noise_index) : 0.0f;
  const FootprintTaps taps = footprint_taps(pass.footprint, kernel.spacing, step, jitter_from, noise);
  if (frame.debug_view != 0) {
    *result = debug_values(frame, source, axis, x, y, centre, centre_distance, step, taps.count);
    return true;
  }
  const bool chords = frame.walk.chords && taps.count > 0;  // no taps: the pixel keeps the whole kernel
  const std::array<float, 2> g = chords ? ray_slope(shared, cx, cy) : std::array<float, 2>{};
  PassTapColours colours;
  for (int i = 0; i < taps.count; ++i) {
    const float p = static_cast<float>(taps.position[static_cast<std::size_t>(i)]);
    for (int side = 0; side < 2; ++side) {
      const float offset = side == 0 ? p : -p;
      float px = cx, py = cy;
      if (axis == 0) {
        px += offset;
      } else {
        py += offset;
        px += walk.shear * offset;
      }
      px = std::clamp(px, shared.clamp_min[0], shared.clamp_max[0]);
      py = std::clamp(py, shared.clamp_min[1], shared.clamp_max[1]);
      const int tx = static_cast<int>(px), ty = static_cast<int>(py);
      std::array<float, 3> tap = {source.at(tx, ty, 0), source.at(tx, ty, 1), source.at(tx, ty, 2)};
      if (!in_colour_range(tap.data(), 3)) tap = {centre[0], centre[1], centre[2]};
      if (k.follow_surface_factor > 0.0f) {
        // Measured where the tap reads: its pixel's centre (rounded to the sheared line, kept in the
        // viewport).
        const float ox = static_cast<float>(tx) + 0.5f - cx, oy = static_cast<float>(ty) + 0.5f - cy;
        const float d = off_surface_distance(shared, walk, follow_surface, offset, ox, oy, distance.at(tx, ty, 0),
                                             centre_distance, !gaussian_depth);
        follow_surface_blend(&tap, centre, d, gaussian_depth, inv_two_variance);
      }
      if (indices.ids != nullptr && indices.at(tx, ty) != indices.at(x, y)) tap = {centre[0], centre[1], centre[2]};
      const auto s = static_cast<std::size_t>(side), t = static_cast<std::size_t>(i);
      colours.colour[s][t] = tap;
      if (chords) {
        const float ox = static_cast<float>(tx) + 0.5f - cx, oy = static_cast<float>(ty) + 0.5f - cy;
        colours.chord_mm[s][t] = chord_mm(shared, g, ox, oy, distance.at(tx, ty, 0), centre_distance,
                                          k.mm_per_world / strength);
      }
    }
  }
  if (chords) {
    *result = chord_weighted_sum(pass.footprint, centre, taps.count, &colours);
    return true;
  }
  for (std::size_t c = 0; c < 3; ++c) sum[c] = centre[c] * taps.weight[0][c];
  for (std::size_t i = 0; i < static_cast<std::size_t>(taps.count); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      sum[c] += taps.weight[i + 1][c] * (colours.colour[0][i][c] + colours.colour[1][i][c]);
    }
  }
  *result = sum;
  return true;
}

// A blue colour word as the passes read it where its low byte holds an R8UI index: that byte as 0.
float without_index_byte(float blue) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &blue, sizeof bits);
  bits &= 0xFFFFFF00u;
  std::memcpy(&blue, &bits, sizeof bits);
  return blue;
}

// The view distance of every pixel as the fragment passes' inputs hold it (pass_inputs.frag): NaN
// where the colour is not one the passes blur.
std::vector<float> pass_distances(const PassConstants& shared, const CpuFilterImage& image, const float* depth) {
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  std::vector<float> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    const bool usable = in_colour_range(image.color + i * 4, 3);
    out[i] = usable ? linearise_depth(shared, depth[i]) : std::numeric_limits<float>::quiet_NaN();
  }
  return out;
}

// A debug view's output before its passes: (0, 0, 0, 1) over the clamp rectangle (the viewport),
// where the GL's view draws; the rest as it was. Its intermediate keeps the horizontal numbers'
// float bits (the GL writes them into RGBA32UI as they are): `image` without the half rounding.
CpuFilterImage prepare_debug_view(const CpuFilterImage& image, const PassConstants& k, float* out) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!cpu_passes::inside(k, x, y)) continue;
      float* p = out + (static_cast<std::size_t>(y) * image.width + x) * 4;
      p[0] = p[1] = p[2] = 0.0f;
      p[3] = 1.0f;
    }
  }
  CpuFilterImage debug = image;
  debug.intermediate_is_half = false;
  return debug;
}

// The tiles view over the clamp rectangle (the viewport), from the colour's alpha; no pass runs.
void tile_view(const CpuFilterImage& image, const PassConstants& k, float* out) {
  const int x = static_cast<int>(k.clamp_min[0] - 0.5f), y = static_cast<int>(k.clamp_min[1] - 0.5f);
  const std::array<int, 4> rect = {x, y, static_cast<int>(k.clamp_max[0] + 0.5f) - x,
                                   static_cast<int>(k.clamp_max[1] + 0.5f) - y};
  write_tile_view(image.color, image.width, rect, out);
}

}  // namespace

void cpu_pass_kernel_filter(const PassKernel& kernel, const PassConstants& constants, const CpuFilterImage& given,
                            float* out) {
  const int w = given.width, h = given.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const float* untouched = given.original != nullptr ? given.original : given.color;
  std::copy(untouched, untouched + count * 4, out);
  if (given.debug_view == kTilesDebugView) return tile_view(given, constants, out);
  const CpuFilterImage image = given.debug_view != 0 ? prepare_debug_view(given, constants, out) : given;
  const Plane color{w, h, 4, image.color};
  const std::vector<float> distances = pass_distances(constants, image, image.depth);
  const Plane distance{w, h, 1, distances.data()};
  const PassFrame frame{constants, distance, Indices{}, image.walk, image.noise_index, image.debug_view};
  std::vector<float> intermediate(count * 4);
  std::vector<float> accumulated(count * 3, 0.0f);  // the earlier terms' vertical sums
  const std::size_t terms = image.debug_view != 0 ? 1 : kernel.terms.size();  // a view: the first term
  for (std::size_t t = 0; t < terms; ++t) {
    const PassTerm& term = kernel.terms[t];
    const bool last = t + 1 == terms;
    // Horizontal pass into the intermediate: translucent pixels blurred, the rest copied.
    cpu_passes::horizontal_into_intermediate(
        image, constants, false,
        [&](int x, int y, Rgba* blurred) {
          return filter_pixel(term.horizontal, kernel, term.depth_variance_mm2, constants, frame, color, 0, x, y,
                              blurred);
        },
        intermediate.data());
    // Vertical pass from the intermediate, plus the earlier terms: into the module's sum target,
    // or (the last term) into the output, where alpha keeps its input value.
    const Plane half_plane{w, h, 4, intermediate.data()};
    cpu_passes::vertical(
        image, constants,
        [&](int x, int y, Rgba* blurred) {
          return filter_pixel(term.vertical, kernel, term.depth_variance_mm2, constants, frame, half_plane, 1, x, y,
                              blurred);
        },
        [&](std::size_t i, const Rgba& blurred) {
          for (int c = 0; c < 3; ++c) {
            const float v = blurred[static_cast<std::size_t>(c)] + accumulated[i * 3 + c];
            if (last) {
              const float post = multiplies_albedo(image) ? v * image.albedo_post[i * 3 + c] : v;
              out[i * 4 + c] = image.output_is_half ? round_to_half(post) : post;
            } else {
              accumulated[i * 3 + c] = image.accumulator_is_half ? round_to_half(v) : v;
            }
          }
        });
  }
}

void cpu_profile_filter(const std::vector<const PassKernel*>& kernels, const std::vector<PassConstants>& constants,
                        const std::uint16_t* ids, const CpuFilterImage& given, float* out, bool index_in_blue) {
  const int w = given.width, h = given.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  const float* untouched = given.original != nullptr ? given.original : given.color;
  std::copy(untouched, untouched + count * 4, out);
  if (given.debug_view == kTilesDebugView) return tile_view(given, constants.front(), out);
  const CpuFilterImage image = given.debug_view != 0 ? prepare_debug_view(given, constants.front(), out) : given;
  // With R8UI ids the passes' inputs carry each index in the low byte of the blue colour word, which
  // the passes read as 0 (and the horizontal pass's result carries on the same way).
  std::vector<float> colours(image.color, image.color + count * 4);
  if (index_in_blue) {
    for (std::size_t i = 0; i < count; ++i) colours[i * 4 + 2] = without_index_byte(colours[i * 4 + 2]);
  }
  const Plane color{w, h, 4, colours.data()};
  const PassConstants& shared = constants.front();
  const std::vector<float> distances = pass_distances(shared, image, image.depth);
  const Plane distance{w, h, 1, distances.data()};
  const Indices indices{ids, w};
  const PassFrame frame{shared, distance, indices, image.walk, image.noise_index, image.debug_view};
  std::vector<float> intermediate(count * 4);
  // The pixel's profile, or -1 where its index has none (the pixel is left alone).
  const auto profile_of = [&](int x, int y) {
    const auto p = static_cast<std::size_t>(indices.at(x, y) & kProfileIndexMask);
    return p < kernels.size() ? static_cast<int>(p) : -1;
  };
  const auto pass = [&](int axis, const Plane& source, int x, int y, Rgba* blurred) {
    const int p = profile_of(x, y);
    if (p < 0) return false;
    const PassKernel& kernel = *kernels[static_cast<std::size_t>(p)];
    const PassTerm& term = kernel.terms.front();
    return filter_pixel(axis == 0 ? term.horizontal : term.vertical, kernel, term.depth_variance_mm2,
                        constants[static_cast<std::size_t>(p)], frame, source, axis, x, y, blurred);
  };
  cpu_passes::horizontal_into_intermediate(
      image, constants.front(), false, [&](int x, int y, Rgba* blurred) { return pass(0, color, x, y, blurred); },
      intermediate.data());
  if (index_in_blue) {
    for (std::size_t i = 0; i < count; ++i) intermediate[i * 4 + 2] = without_index_byte(intermediate[i * 4 + 2]);
  }
  const Plane half_plane{w, h, 4, intermediate.data()};
  cpu_passes::vertical(
      image, constants.front(), [&](int x, int y, Rgba* blurred) { return pass(1, half_plane, x, y, blurred); },
      [&](std::size_t i, const Rgba& blurred) {
        for (std::size_t c = 0; c < 3; ++c) {
          const float post = multiplies_albedo(image) ? blurred[c] * image.albedo_post[i * 3 + c] : blurred[c];
          out[i * 4 + c] = image.output_is_half ? round_to_half(post) : post;
        }
      });
}

}  // namespace sss::math
