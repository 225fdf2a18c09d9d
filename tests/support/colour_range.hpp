// The range of an image's finite colours, and how far a blurred channel may stand outside it: the
// CPU model's policy checks (property/math_properties_test.cpp, fuzz/fuzz_cpu_model.cpp). Header
// only, no GL and no test framework (the fuzz targets use it too).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace sss_test {

struct ColourRange {
  std::array<float, 3> lo, hi;  // per channel, over pixels whose colour is finite
  float magnitude = 0.0f;       // the largest |value| among them
  // The least and the greatest value a blur of these colours may give in channel c: the range, by
  // the fp16 rounding of the intermediate and of a half output (2^-10 each, round to nearest) and
  // the float sum's error.
  float least(int c) const { return lo[at(c)] - (std::fabs(lo[at(c)]) * (1.0f / 1024.0f) + magnitude * 4e-6f + 6e-8f); }
  float greatest(int c) const {
    return hi[at(c)] + (std::fabs(hi[at(c)]) * (1.0f / 1024.0f) + magnitude * 4e-6f + 6e-8f);
  }

 private:
  static std::size_t at(int c) { return static_cast<std::size_t>(c); }
};

// Over `pixels` RGBA pixels; the range is empty (lo = +inf, hi = -inf) when none is finite.
inline ColourRange finite_colour_range(const float* rgba, std::size_t pixels) {
  ColourRange r;
  r.lo.fill(std::numeric_limits<float>::infinity());
  r.hi.fill(-std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < pixels; ++i) {
    const float* p = &rgba[i * 4];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      r.lo[c] = std::min(r.lo[c], p[c]);
      r.hi[c] = std::max(r.hi[c], p[c]);
      r.magnitude = std::max(r.magnitude, std::fabs(p[c]));
    }
  }
  return r;
}

}  // namespace sss_test
