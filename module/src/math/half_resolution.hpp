// The half-resolution passes (sss.h SSS_PATH_HALF_RESOLUTION; issue 24 item 5): what the GL runner
// (module/src/gl/half_runner.cpp) and its CPU model (cpu_half_resolution.hpp) share. Math layer: no GL.
//
// The frame's inputs are reduced to half size (each 2x2 block to one texel: the block's nearest
// translucent pixel and those of its pixels on the same surface and profile, averaged), the two
// passes run there with the kernel at half the pixels per millimetre, and an upsample puts the
// result back at full size for the pixels whose kernel is wide enough:
//   out = B + Σ_q W_q · x_q − (Σ_q W_q) · X
// where B and X are the half-size result and input at the pixel, taken from the four nearest
// half-size texels with bilinear weights times a depth weight (1 − the follow-surface blend of
// their distance to the pixel's) on texels of the pixel's own profile and object; q runs over the
// pixel and its four neighbours along the axes, x_q is a neighbour's colour as the full-size
// passes take it (blended towards the pixel's own by the follow-surface rule, the pixel's own where
// its index differs) and W_q the weight the full-size passes give it (the product of the two
// passes' weights at offsets 0 and ±1: footprint_near_weights). The half-size passes see only 2x2
// means, so the kernel's near field (the centre and the first taps, which hold skin's narrow peak
// and eq. (1)'s unscattered light) is taken at full size instead and its half-size stand-in, that
// mass times X, taken out. Measured on the footprint sweep's CPU model, as the smallest kernel
// reach that keeps the margin below: 48 pixels with the centre alone (q = the pixel), 12 with the
// whole 3x3 ring, 8 with the centre and the four axis neighbours (the diagonals' tiny product
// weights put more mass on X's 2x2 means than their detail is worth); docs/benchmarks/half-resolution.md.
// Pixels whose kernel reaches fewer than kHalfResolutionMinReachPixels on either axis, and those
// with no such neighbour, run the full-size passes instead (they are cheap there: few taps).
#pragma once

#include <array>
#include <vector>

#include "filter_constants.hpp"
#include "footprint_kernel.hpp"

namespace sss::math {

// The smallest kernel reach (full-size pixels, on both axes) the upsample serves; the rest run at
// full size. Chosen on the benchmark's footprint sweep (docs/benchmarks-half.md): the largest
// interior miss of the head and plane scenes stays within kHalfResolutionMissMargin of the
// full-size passes' at every footprint.
inline constexpr float kHalfResolutionMinReachPixels = 8.0f;
// What the half-resolution path may add to the full-size passes' interior miss (the benchmark's
// and the tests' bound): a hundredth of the change the frame needs.
inline constexpr double kHalfResolutionMissMargin = 0.05;
// The least sum of the upsample's weights: below it the pixel has no half-size neighbour on its
// surface (a thin sliver, a depth step) and runs at full size.
inline constexpr float kHalfResolutionMinWeight = 0.0625f;
// A pixel of a 2x2 block joins the block's nearest translucent pixel when its distance differs by
// less than this share of the kernel's reach (the follow-surface factor): it is the same surface.
inline constexpr float kHalfResolutionMergeReach = 0.25f;

// The half-size rectangle (x, y, width, height in half-size texels) that covers `rect`'s pixels:
// texel (i, j) stands for full-size pixels 2i..2i+1, 2j..2j+1.
std::array<int, 4> half_rect(const std::array<int, 4>& rect);
// The half-size texture of a full-size texture (rounded up).
inline int half_size(int size) { return (size + 1) / 2; }

// The passes' constants at half size: half the pixels per millimetre, taps kept in `half`
// (half_rect of the run's drawn rectangle), distances read as they are (linear).
PassConstants half_pass_constants(const PassConstants& full, const std::array<int, 4>& half);

// The weights the pass with `table` and `spacing` gives, at `step` pixels per profile millimetre,
// to the centre pixel and to each pixel beside it (footprint_taps' weight[0], and weight[1] where
// its first tap is the neighbouring pixel, else 0), as footprint_taps.glsl computes them.
struct NearWeights {
  std::array<float, 3> centre{}, beside{};
};
NearWeights footprint_near_weights(const FootprintTable& table, const std::vector<float>& spacing, float step);

}  // namespace sss::math
