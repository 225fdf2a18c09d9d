// Discretisation of a radial profile on a tap grid: the 1D tap layout every kernel family shares
// and the 2D matrix of the profile integrated over the grid's cells. Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "radial_profile.hpp"

namespace sss::math {

enum class TapSpacing { uniform, quadratic };

// `taps` (odd) positions on [-radius, radius] and the cells around them: cell i is
// [edges[i], edges[i+1]], bounded by the midpoints between neighbours and by ±radius at the ends.
// quadratic: t evenly spaced in [-R, R] mapped to sign(t)·t²/R (denser at the centre, as the eq. (1)
// kernel does), for peaked profiles.
struct TapGrid {
  std::vector<double> offsets_mm;
  std::vector<double> edges_mm;  // offsets_mm.size() + 1
  int size() const { return static_cast<int>(offsets_mm.size()); }
};
TapGrid make_tap_grid(int taps, double radius_mm, TapSpacing spacing);

// The profile integrated over each 2D cell (i along x, j along y) of grid × grid, per channel:
// cells[c][i * n + j]. Symmetric because the profile is radially symmetric. Each channel is scaled
// to sum to 1: kernels redistribute irradiance, the diffuse albedo stays the host's; `totals` keeps
// each channel's sum before scaling (the share of the profile's energy inside the square).
struct ProfileMatrix {
  TapGrid grid;
  std::array<std::vector<double>, 3> cells;
  Rgb totals{};
  int n() const { return grid.size(); }
  double at(int c, int i, int j) const {
    return cells[static_cast<std::size_t>(c)][static_cast<std::size_t>(i * n() + j)];
  }
};
ProfileMatrix discretise_profile(const RadialProfile& profile, const TapGrid& grid);

}  // namespace sss::math
