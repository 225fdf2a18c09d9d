#include "cpu_half_resolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "cpu_filter_passes.hpp"
#include "half_float.hpp"
#include "half_resolution.hpp"
#include "pass_surface.hpp"

namespace sss::math {

namespace {

using cpu_passes::in_colour_range;
using cpu_passes::kUnusableColour;

std::uint32_t bits_of(float f) {
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return b;
}
float float_of(std::uint32_t b) {
  float f = 0.0f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// pass_inputs.frag's texel: the colour (kUnusableColour where out of range; with R8UI indices its
// blue word's low byte, which holds the index there, read as 0), the distance word (NaN where the
// colour is out of range), the R8UI index and the strength.
struct InputTexel {
  std::array<float, 3> colour{};
  std::uint32_t word = 0;
  std::uint32_t index = 0;
  float strength = 0.0f;
};

// The blue colour word as the passes read it with R8UI indices in its low byte.
float without_index(float blue) { return float_of(bits_of(blue) & 0xFFFFFF00u); }

struct Frame {
  int width = 0, height = 0;
  bool ids = false;  // R8UI indices in the blue colour words
  std::vector<InputTexel> texels;
  const InputTexel& at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
  float distance(std::uint32_t word) const { return float_of(word); }
};

Frame full_inputs(const CpuFilterImage& image, const PassConstants& shared, const std::uint16_t* ids) {
  Frame f;
  f.width = image.width;
  f.height = image.height;
  f.ids = ids != nullptr;
  f.texels.resize(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < f.texels.size(); ++i) {
    InputTexel& t = f.texels[i];
    const float* c = image.color + i * 4;
    std::uint32_t word = bits_of(linearise_depth(shared, image.depth[i]));
    t.colour = {c[0], c[1], c[2]};
    if (!in_colour_range(c, 3)) {  // pass_inputs.frag: kSssUnusableColour at distance NaN
      t.colour = {kUnusableColour, kUnusableColour, kUnusableColour};
      word = 0x7FC00000u;
    }
    if (ids != nullptr) {
      t.colour[2] = without_index(t.colour[2]);
      t.index = ids[i] & 0xFFu;
    }
    t.word = word;
    t.strength = c[3];
  }
  return f;
}

// Per profile: pixels per mm on x and y at clip w = 1 and strength 1, and the depth factor
// (1 / the kernel's reach in world units; 0 without follow-surface).
struct Look {
  float x, y, depth_factor;
};

int profile_of(const Frame& f, std::uint32_t index, std::size_t count) {
  if (!f.ids) return 0;
  const auto p = static_cast<std::size_t>(index & kProfileIndexMask);
  return p < count ? static_cast<int>(p) : -1;
}

// half_inputs.frag at half-size texel (i, j): `rect` the full-size drawn rectangle.
InputTexel reduce_block(const Frame& f, const std::vector<Look>& looks, const std::array<int, 4>& rect, int i, int j) {
  std::array<InputTexel, 4> t;
  std::array<bool, 4> translucent{};
  bool any = false;
  for (int k = 0; k < 4; ++k) {
    const int x = std::clamp(2 * i + (k & 1), rect[0], rect[0] + rect[2] - 1);
    const int y = std::clamp(2 * j + (k >> 1), rect[1], rect[1] + rect[3] - 1);
    t[static_cast<std::size_t>(k)] = f.at(x, y);
    translucent[static_cast<std::size_t>(k)] =
        t[static_cast<std::size_t>(k)].strength > 0.0f && !std::isnan(f.distance(t[static_cast<std::size_t>(k)].word));
    any = any || translucent[static_cast<std::size_t>(k)];
  }
  int r = -1;
  for (int k = 0; k < 4; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (translucent[ku] != any) continue;
    const float dk = f.distance(t[ku].word);
    if (r < 0 || std::isnan(f.distance(t[static_cast<std::size_t>(r)].word)) ||
        dk < f.distance(t[static_cast<std::size_t>(r)].word)) {
      r = k;
    }
  }
  const InputTexel& ref = t[static_cast<std::size_t>(r)];
  const float dr = f.distance(ref.word);
  int p = profile_of(f, ref.index, looks.size());
  const float factor = looks[static_cast<std::size_t>(p < 0 ? 0 : p)].depth_factor;
  std::array<float, 3> colour = {0.0f, 0.0f, 0.0f};
  float strength = 0.0f, n = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const bool same = ref.index == t[ku].index || !f.ids;
    const bool joins = k == r || (translucent[ku] == any && same &&
                                  factor * std::fabs(f.distance(t[ku].word) - dr) < kHalfResolutionMergeReach);
    if (!joins) continue;
    for (std::size_t c = 0; c < 3; ++c) colour[c] += t[ku].colour[c];
    strength += t[ku].strength;
    n += 1.0f;
  }
  InputTexel out;
  for (std::size_t c = 0; c < 3; ++c) out.colour[c] = colour[c] / n;
  if (f.ids) out.colour[2] = without_index(out.colour[2]);  // the representative's index rides there
  out.word = ref.word;
  out.index = ref.index;
  out.strength = any ? strength / n : 0.0f;
  return out;
}

// The full-size rectangle the constants clamp to (x, y, width, height).
std::array<int, 4> drawn_rect(const PassConstants& k) {
  return {static_cast<int>(k.clamp_min[0]), static_cast<int>(k.clamp_min[1]),
          static_cast<int>(k.clamp_max[0] - k.clamp_min[0]) + 1, static_cast<int>(k.clamp_max[1] - k.clamp_min[1]) + 1};
}

// The half-size frame: half_inputs.frag over the half-size rectangle.
Frame reduce(const Frame& full, const std::vector<Look>& looks, const std::array<int, 4>& rect,
             const std::array<int, 4>& hrect) {
  Frame half;
  half.width = half_size(full.width);
  half.height = half_size(full.height);
  half.ids = full.ids;
  half.texels.resize(static_cast<std::size_t>(half.width) * half.height);
  for (int j = hrect[1]; j < hrect[1] + hrect[3]; ++j) {
    for (int i = hrect[0]; i < hrect[0] + hrect[2]; ++i) {
      half.texels[static_cast<std::size_t>(j) * half.width + i] = reduce_block(full, looks, rect, i, j);
    }
  }
  return half;
}

// What the upsample reads at half size: the passes' result (RGBA) and where they blurred (the GL's
// result has alpha above 0 there, the strength as the target stores it, and 0 where the pass left
// the texel alone).
struct HalfResult {
  std::vector<float> rgba;
  std::vector<std::uint8_t> blurred;
};

HalfResult half_passes(const Frame& half, const std::vector<const PassKernel*>& kernels,
                       const std::vector<PassConstants>& half_constants, bool intermediate_is_half) {
  const std::size_t count = half.texels.size();
  std::vector<float> colour(count * 4), depth(count);
  std::vector<std::uint16_t> ids(half.ids ? count : 0);
  HalfResult r;
  r.rgba.resize(count * 4);
  r.blurred.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    const InputTexel& t = half.texels[i];
    std::copy(t.colour.begin(), t.colour.end(), colour.begin() + static_cast<std::ptrdiff_t>(i * 4));
    colour[i * 4 + 3] = t.strength;
    depth[i] = float_of(t.word);
    if (half.ids) ids[i] = static_cast<std::uint16_t>(t.index);
    const float w = clip_w(half_constants.front(), half.distance(t.word));
    const float stored = intermediate_is_half ? round_to_half(t.strength) : t.strength;
    r.blurred[i] = t.strength > 0.0f && in_colour_range(colour.data() + i * 4, 4) && !std::isnan(w) && w > 0.0f &&
                   !std::isinf(w) && profile_of(half, t.index, kernels.size()) >= 0 && stored > 0.0f;
  }
  CpuFilterImage image;
  image.width = half.width;
  image.height = half.height;
  image.color = colour.data();
  image.depth = depth.data();
  image.output_is_half = intermediate_is_half;  // the half-size result: the intermediate's format
  image.intermediate_is_half = intermediate_is_half;
  if (half.ids) {
    cpu_profile_filter(kernels, half_constants, ids.data(), image, r.rgba.data(), true);
  } else {
    cpu_pass_kernel_filter(*kernels.front(), half_constants.front(), image, r.rgba.data());
  }
  return r;
}

struct Upsample {
  const Frame& full;
  const Frame& half;
  const HalfResult& result;
  const std::vector<const PassKernel*>& kernels;
  const std::vector<Look>& looks;
  const PassConstants& shared;
  std::array<int, 4> hrect;
  float min_reach;
  bool output_is_half;

  // The full-size pixel (x, y)'s neighbour (x + ox, y + oy) for the surface's tangent, as the passes
  // take it (pass_surface.hpp; their inputs' distance, the pixel's index where there are indices).
  Neighbour neighbour(int x, int y, int ox, int oy, std::uint32_t index) const {
    Neighbour n;
    if (!cpu_passes::inside(shared, x + ox, y + oy)) return n;
    const InputTexel& q = full.at(x + ox, y + oy);
    n.distance = full.distance(q.word);
    const float w = clip_w(shared, n.distance);
    n.usable = w > 0.0f && w < 1e30f && (!full.ids || q.index == index);
    return n;
  }

  // The full-size passes' walks at (x, y): along the row, and up the sheared column.
  struct Walks {
    PassGeometry across, up;
  };
  Walks walks(int x, int y, float d, std::uint32_t index) const {
    const std::array<float, 2> g = ray_slope(shared, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const Float3 tx = surface_tangent(shared, g, 0, d, neighbour(x, y, -1, 0, index), neighbour(x, y, 1, 0, index));
    const Float3 ty = surface_tangent(shared, g, 1, d, neighbour(x, y, 0, -1, index), neighbour(x, y, 0, 1, index));
    return {horizontal_geometry(shared, g, d, tx), vertical_geometry(shared, g, d, tx, ty)};
  }

  // half_upsample.frag at (x, y) into `out` (RGBA); false where it discards (the full-size passes' pixel).
  bool pixel(int x, int y, float* out) const {
    const InputTexel& t = full.at(x, y);
    const std::array<float, 4> centre = {t.colour[0], t.colour[1], t.colour[2], t.strength};
    if (!(centre[3] > 0.0f) || !in_colour_range(centre.data(), 4)) return false;
    const float d = full.distance(t.word);
    const float w = clip_w(shared, d);
    if (std::isnan(w) || !(w > 0.0f) || std::isinf(w)) return false;
    const int p = profile_of(full, t.index, kernels.size());
    if (p < 0) return false;
    const PassKernel& kernel = *kernels[static_cast<std::size_t>(p)];
    const PassTerm& term = kernel.terms.front();
    const Look& look = looks[static_cast<std::size_t>(p)];
    const float a = std::min(centre[3], 1.0f);
    const Walks walk = walks(x, y, d, t.index);
    const float step_x = look.x * a / w * walk.across.ratio, step_y = look.y * a / w * walk.up.ratio;
    const float reach_x = std::min(term.horizontal.footprint.reach_mm * step_x, 1.0e6f);
    const float reach_y = std::min(term.vertical.footprint.reach_mm * step_y, 1.0e6f);
    if (!(std::min(reach_x, reach_y) >= min_reach)) return false;
    float weight = 0.0f;
    std::array<float, 3> blurred{}, reduced{};
    Range range;
    neighbours(x, y, t.index, d, look.depth_factor / a, walk.up, &weight, &blurred, &reduced, &range);
    if (!(weight >= kHalfResolutionMinWeight)) return false;
    std::array<float, 3> near{}, mass{};
    near_field(x, y, t, d, look.depth_factor / a, walk,
               footprint_near_weights(term.horizontal.footprint, kernel.spacing, step_x),
               footprint_near_weights(term.vertical.footprint, kernel.spacing, step_y), &near, &mass, &range);
    for (std::size_t c = 0; c < 3; ++c) {
      float v = blurred[c] / weight + near[c] - mass[c] * (reduced[c] / weight);
      v = std::min(std::max(v, range.lowest[c]), range.highest[c]);  // within what it combined
      out[c] = output_is_half ? round_to_half(v) : v;
    }
    return true;
  }

  // The range of the values a pixel's upsample combines (half_upsample.frag's lowest, highest):
  // the half-size results it weighs and its near field's pixels as taken.
  struct Range {
    std::array<float, 3> lowest = {3.4e38f, 3.4e38f, 3.4e38f}, highest = {-3.4e38f, -3.4e38f, -3.4e38f};
    void add(std::size_t c, float v) {
      lowest[c] = std::min(lowest[c], v);
      highest[c] = std::max(highest[c], v);
    }
  };

  // The full-size passes' near field at (x, y): the pixel, its neighbours along the row and the
  // nearest pixels of the rows above and below on the vertical pass's sheared line, as their taps
  // take them (follow-surface by their distance off the pixel's surface, less the ramp's slack of one
  // step), weighed by the product of the two passes' weights, and that weight's sum.
  void near_field(int x, int y, const InputTexel& t, float d, float factor, const Walks& walk, const NearWeights& h,
                  const NearWeights& v, std::array<float, 3>* near, std::array<float, 3>* mass, Range* range) const {
    const float cx = static_cast<float>(x) + 0.5f;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx != 0 && dy != 0) continue;  // the diagonals: half_resolution.hpp says why not
        const float offset = static_cast<float>(dx + dy);  // steps along the pass's line: -1, 0 or 1
        const int column = dy == 0 ? x + dx : static_cast<int>(cx + walk.up.shear * offset);
        const int qx = std::clamp(column, static_cast<int>(shared.clamp_min[0]), static_cast<int>(shared.clamp_max[0]));
        const int qy = std::clamp(y + dy, static_cast<int>(shared.clamp_min[1]), static_cast<int>(shared.clamp_max[1]));
        const InputTexel& q = full.at(qx, qy);
        const PassGeometry& line = dy == 0 ? walk.across : walk.up;
        float s = off_surface_distance(shared, line, factor, offset, static_cast<float>(qx - x),
                                       static_cast<float>(qy - y), full.distance(q.word), d, true);
        if (!(s < 1.0f)) s = 1.0f;
        if (full.ids && q.index != t.index) s = 1.0f;  // another index: the centre's colour
        for (std::size_t c = 0; c < 3; ++c) {
          const float wx = dx == 0 ? h.centre[c] : h.beside[c], wy = dy == 0 ? v.centre[c] : v.beside[c];
          const float w = wx * wy;
          const float taken = s < 1.0f ? q.colour[c] * (1.0f - s) + t.colour[c] * s : t.colour[c];
          (*near)[c] += w * taken;
          (*mass)[c] += w;
          range->add(c, taken);
        }
      }
    }
  }

  // The four nearest half-size texels: bilinear weight times the depth weight (1 - the follow-surface
  // blend of their distance off the pixel's tangent plane, `plane`: the vertical walk's, taken at
  // the centre of the 2x2 block each stands for), on the pixel's index.
  void neighbours(int x, int y, std::uint32_t index, float d, float factor, const PassGeometry& plane, float* weight,
                  std::array<float, 3>* blurred, std::array<float, 3>* reduced, Range* range) const {
    const int i0 = x > 0 ? (x - 1) / 2 : -1, j0 = y > 0 ? (y - 1) / 2 : -1;  // GLSL's (pixel - 1) >> 1
    const float fx = (x & 1) != 0 ? 0.25f : 0.75f, fy = (y & 1) != 0 ? 0.25f : 0.75f;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const int qi = std::clamp(i0 + dx, hrect[0], hrect[0] + hrect[2] - 1);
        const int qj = std::clamp(j0 + dy, hrect[1], hrect[1] + hrect[3] - 1);
        const std::size_t qk = static_cast<std::size_t>(qj) * half.width + qi;
        if (result.blurred[qk] == 0) continue;
        const InputTexel& q = half.texels[qk];
        if (full.ids && q.index != index) continue;
        // The block's centre, full-size window 2 q + 1, from the pixel's centre.
        const float ox = static_cast<float>(2 * qi - x) + 0.5f, oy = static_cast<float>(2 * qj - y) + 0.5f;
        float s = off_surface_distance(shared, plane, factor, 0.0f, ox, oy, half.distance(q.word), d, false);
        if (!(s < 1.0f)) s = 1.0f;
        const float wq = (dx == 0 ? 1.0f - fx : fx) * (dy == 0 ? 1.0f - fy : fy) * (1.0f - s);
        *weight += wq;
        for (std::size_t c = 0; c < 3; ++c) {
          (*blurred)[c] += wq * result.rgba[qk * 4 + c];
          (*reduced)[c] += wq * q.colour[c];
          if (wq > 0.0f) range->add(c, result.rgba[qk * 4 + c]);
        }
      }
    }
  }
};

}  // namespace

void cpu_half_resolution_filter(const std::vector<const PassKernel*>& kernels,
                                const std::vector<PassConstants>& constants, const std::uint16_t* ids,
                                const CpuFilterImage& image, float min_reach_pixels, float* out,
                                CpuHalfResolutionStats* stats) {
  const PassConstants& shared = constants.front();
  const std::array<int, 4> rect = drawn_rect(shared);
  const Frame full = full_inputs(image, shared, ids);
  std::vector<Look> looks;
  for (const PassConstants& k : constants) looks.push_back({k.pixels_per_mm[0], k.pixels_per_mm[1], k.follow_surface_factor});
  const std::array<int, 4> hrect = half_rect(rect);
  std::vector<PassConstants> half_constants;
  for (const PassConstants& k : constants) half_constants.push_back(half_pass_constants(k, hrect));
  const Frame half = reduce(full, looks, rect, hrect);
  const HalfResult result = half_passes(half, kernels, half_constants, image.intermediate_is_half);

  // The upsample where it serves the pixel; the full-size passes on the rest (the others hold
  // their input in the intermediate, as the GL's culling leaves them).
  const Upsample upsample{full, half, result, kernels, looks, shared, hrect, min_reach_pixels, image.output_is_half};
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  std::vector<std::uint8_t> full_size(count, 1);
  if (image.mask != nullptr) std::copy(image.mask, image.mask + count, full_size.begin());
  std::copy(image.color, image.color + count * 4, out);
  CpuHalfResolutionStats counted;
  for (int y = rect[1]; y < rect[1] + rect[3]; ++y) {
    for (int x = rect[0]; x < rect[0] + rect[2]; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (full_size[i] == 0) continue;  // outside the host's stencil: neither draw writes it
      if (upsample.pixel(x, y, out + i * 4)) {
        full_size[i] = 0;
        ++counted.upsampled;
      } else if (full.texels[i].strength > 0.0f) {
        ++counted.full_size;
      }
    }
  }
  CpuFilterImage rest = image;
  rest.mask = full_size.data();
  std::vector<float> passes(count * 4);
  if (ids != nullptr) {
    cpu_profile_filter(kernels, constants, ids, rest, passes.data(), true);
  } else {
    cpu_pass_kernel_filter(*kernels.front(), constants.front(), rest, passes.data());
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (full_size[i] != 0) {
      std::copy(passes.begin() + static_cast<std::ptrdiff_t>(i * 4), passes.begin() + static_cast<std::ptrdiff_t>(i * 4 + 4),
                out + i * 4);
    }
  }
  if (stats != nullptr) *stats = counted;
}

}  // namespace sss::math
