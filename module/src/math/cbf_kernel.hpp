// The kernel of the pseudo-separable cross-bilateral filter (Mikkelsen 2010, §5) as its passes
// consume it: each channel's broad part (the profile less its spike) as a 1D marginal, truncated to
// [-r_max, r_max], in the footprint-aware form of the separable passes (footprint_kernel.hpp): its
// taps sit on whole pixels chosen from each pixel's footprint and each weighs the marginal
// integrated over the pixels it stands for, so a kernel narrower than a pixel stays on it.
//
// Until 2026-11 the taps sat at fixed offsets placed by the inverse CDF of red's marginal (Mikkelsen's
// importance placement), each read at the nearest texel with its interval's mass. On a coarse
// footprint a narrow channel's mass then landed whole on a neighbour whenever its tap's offset
// crossed half a pixel: blue (d'Eon's 0.0484 mm² term) spread three times too far at 1 mm per
// pixel, 3.8 times as far from the exact result as doing nothing (docs/surface-turns.md).
// Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "footprint_kernel.hpp"
#include "spike_gaussian_profile.hpp"

namespace sss::math {

struct CbfKernel {
  // Each channel's broad marginal, normalised to 1 on [-r_max, r_max] (no centre delta: the spike
  // is the blend below), and the sparse layout of its taps (footprint_spacing(taps / 2)).
  FootprintTable table;
  std::vector<float> spacing;
  // Per 1D pass the result is b·centre + (1 - b)·(normalised cross-bilateral sum), with
  // b = 1 - sqrt(1 - spike): after both passes the fully 2D-filtered share is exactly 1 - spike
  // (the rest is the unfiltered image and thin 1D smears, as in the separable kernel).
  std::array<float, 3> spike_blend = {0.0f, 0.0f, 0.0f};
  // 1 / (2 σ²) per channel in mm⁻², σ² the broad part's mean variance: the range Gaussian on a tap's
  // distance off the centre's surface (eq. 1).
  std::array<float, 3> inv_two_variance = {0.0f, 0.0f, 0.0f};
  float r_max_mm = 0.0f;
};

// The whole kernel. Preconditions (API layer): taps odd in [3, 65]; r_max_mm finite and > 0; every
// channel of the profile has a broad part.
CbfKernel cbf_kernel(const SpikeGaussianProfile& profile, int taps, double r_max_mm);

}  // namespace sss::math
