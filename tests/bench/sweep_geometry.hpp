// The footprint sweep's geometry, shared by the benchmark and the default kernel's calibration
// (calibration.hpp), so that both measure the same frames.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace sss_bench {

// The sweep's interior spans at least this many millimetres: the widest content (plane-disk, 6 mm
// across) with a millimetre on either side, so that it holds every edge of the light.
constexpr double kSweepInteriorMm = 8.0;

// The default footprints: seven log-spaced values from 0.05 to 2 mm per pixel (a 4K close-up of a
// face to a crowd), 0.05 · 40^(k/6).
inline std::vector<double> default_sweep_footprints() {
  std::vector<double> footprints;
  for (int k = 0; k <= 6; ++k) footprints.push_back(0.05 * std::pow(40.0, k / 6.0));
  return footprints;
}

// The footprints the default kernel is calibrated on (sss_fit_default): the sweep's, and 1.3, 3 and
// 4 mm. A surface turned away from the camera sees the kernel at its facing footprint over the
// turn's cosine along one axis (up to 3.9 times it at 75 degrees: pass_surface.hpp), and a rank-1
// kernel's blue, which needs almost no change there, was worse than doing nothing between the sweep's
// 1.08 and 2 mm on a diagonal edge (1.26 at 1.3 mm), where the sweep had no footprint.
inline std::vector<double> calibration_footprints() {
  std::vector<double> footprints = default_sweep_footprints();
  footprints.insert(footprints.end(), {1.3, 3.0, 4.0});
  std::sort(footprints.begin(), footprints.end());
  return footprints;
}

// The side of a sweep frame at footprint f (mm per pixel): the interior and the profile's reach on
// every side (border pixels), plus one for the float camera.
inline int sweep_frame_side(double footprint_mm, int interior_px, double reach_mm) {
  const int interior = std::max(interior_px, static_cast<int>(std::ceil(kSweepInteriorMm / footprint_mm)));
  return interior + 2 * (static_cast<int>(std::ceil(reach_mm / footprint_mm)) + 1);
}

}  // namespace sss_bench
