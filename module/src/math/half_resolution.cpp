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
  // Half-size texel (i, j) stands for the full-size pixels 2i..2i+1: its centre is full-size window
  // position 2 · (i + ½), so a half-size pixel spans twice the width and the ray's slope changes
  // twice as fast per pixel (pass_surface.hpp's view offsets).
  for (std::size_t a = 0; a < 2; ++a) {
    k.pixel_span[a] = 2.0f * full.pixel_span[a];
    k.slope_scale[a] = 2.0f * full.slope_scale[a];
  }
  k.linear_depth = true;
  clamp_to_rect(&k, half);
  return k;
}

NearWeights footprint_near_weights(const FootprintTable& table, const std::vector<float>& spacing, float step) {
  NearWeights w;
  if (table.empty()) {
    w.centre = table.delta;
    return w;
  }
  const FootprintTaps taps = footprint_taps(table, spacing, step, kNoJitter, 0.0f);
  w.centre = taps.weight[0];
  if (taps.count > 0 && taps.position[0] == 1) w.beside = taps.weight[1];
  return w;
}

}  // namespace sss::math
