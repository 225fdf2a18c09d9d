#include "half_resolution.hpp"

namespace sss::math {

std::array<int, 4> half_rect(const std::array<int, 4>& rect) {
  const int x0 = rect[0] / 2, y0 = rect[1] / 2;  // rect's x, y >= 0
  const int x1 = (rect[0] + rect[2] + 1) / 2, y1 = (rect[1] + rect[3] + 1) / 2;
  return {x0, y0, x1 - x0, y1 - y0};
}

PassConstants half_pass_constants(const PassConstants& full, const std::array<int, 4>& half) {
  PassConstants k = full;
  k.pixels_per_mm = {0.5f * full.pixels_per_mm[0], 0.5f * full.pixels_per_mm[1]};
  k.linear_depth = true;
  clamp_to_rect(&k, half);
  return k;
}

std::array<float, 3> footprint_centre_weight(const FootprintTable& table, const std::vector<float>& spacing,
                                             float step) {
  if (table.empty()) return table.delta;
  return footprint_taps(table, spacing, step, kNoJitter, 0.0f).weight[0];
}

}  // namespace sss::math
