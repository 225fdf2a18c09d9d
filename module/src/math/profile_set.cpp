#include "profile_set.hpp"

#include <algorithm>

namespace sss::math {

void pack_profile_table(const PassTaps& taps, float* out) {
  std::fill(out, out + 4 * kProfileTableVectors, 0.0f);
  const FootprintTable& table = taps.footprint;
  const std::size_t entries = std::min<std::size_t>(table.half_cdf.size(), kFootprintEntries);
  for (std::size_t j = 0; j < entries; ++j) {
    for (std::size_t c = 0; c < 3; ++c) out[4 * j + c] = table.half_cdf[j][c];
  }
  float* footprint = out + 4 * kFootprintEntries;
  footprint[0] = table.reach_mm;
  for (std::size_t c = 0; c < 3; ++c) footprint[1 + c] = table.delta[c];
}

std::array<float, 4> profile_pass_vector(const PassConstants& constants, const PassTerm& term, int axis) {
  const bool gaussian = term.depth_variance_mm2 > 0.0f;
  return {constants.pixels_per_mm[axis == 0 ? 0 : 1],
          gaussian ? constants.mm_per_world : constants.follow_surface_factor,
          gaussian ? 0.5f / term.depth_variance_mm2 : 0.0f, 0.0f};
}

}  // namespace sss::math
