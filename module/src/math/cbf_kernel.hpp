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
  // Per 1D pass the result is b·centre + (1 - b)·(normalised cross-bilateral sum) with b = spike:
  // each pass is the whole profile's 1D marginal (the spike a delta, the broad part its marginal),
  // as the separable kernels' passes are, so a shadow edge along either axis gets exactly the
  // profile's edge response. Until 2026-11 b was 1 - sqrt(1 - spike), which leaves exactly
  // 1 - spike of the light fully 2D-filtered but adds the two 1D smears b·(1 - b) to it: an edge
  // then took (1 - b) of the broad blur instead of (1 - spike), 1.69 times too much in blue with
  // d'Eon's profile. On the footprint sweep (13 taps, quick run) the median interior miss fell
  // from 0.253 to 0.185 and the worst channel from 0.915 to 0.597 with b = spike (issue 40).
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
