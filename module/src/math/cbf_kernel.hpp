// The taps of the pseudo-separable cross-bilateral filter (Mikkelsen 2010, §5): N taps placed by
// the inverse CDF of the red channel's 1D marginal, truncated to [-r_max, r_max], so each carries
// probability 1/N for red; green and blue reuse the same positions with weights equal to their own
// marginal's mass over each tap's interval. Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "spike_gaussian_profile.hpp"
#include "separable_kernel.hpp"

namespace sss::math {

struct CbfKernel {
  // Centre tap first (offset 0), then the others from most negative to most positive offset (the
  // same layout as the separable kernel). Weights of the broad part, each channel summing to 1.
  std::vector<KernelTap> taps;
  // Per 1D pass the result is b·centre + (1 - b)·(normalised cross-bilateral sum), with
  // b = 1 - sqrt(1 - spike): after both passes the fully 2D-filtered share is exactly 1 - spike
  // (the rest is the unfiltered image and thin 1D smears, as in the separable kernel).
  std::array<float, 3> spike_blend = {0.0f, 0.0f, 0.0f};
  // 1 / (2 σ²) per channel in mm⁻², σ² the broad part's mean variance: the range Gaussian on the
  // depth difference and the spatial Gaussian on the screen-parallel distance (eq. 1, 7).
  std::array<float, 3> inv_two_variance = {0.0f, 0.0f, 0.0f};
  float r_max_mm = 0.0f;
};

// The offsets of `taps` taps (odd, [3, 65]) by the inverse CDF of red's broad marginal truncated to
// [-r_max, r_max]: tap i at probability (i + 1/2) / N, interval boundaries at i / N. Ascending.
// `boundaries` (optional) receives the N + 1 interval ends (first -r_max, last r_max).
std::vector<double> cbf_tap_offsets(const SpikeGaussianProfile& profile, int taps, double r_max_mm,
                                    std::vector<double>* boundaries = nullptr);

// The whole kernel. Preconditions (API layer): taps odd in [3, 65]; r_max_mm finite and > 0; every
// channel of the profile has a broad part.
CbfKernel cbf_kernel(const SpikeGaussianProfile& profile, int taps, double r_max_mm);

}  // namespace sss::math
