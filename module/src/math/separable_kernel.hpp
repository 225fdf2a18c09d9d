// The separable kernel of the paper's eq. (1): offsets and per-channel weights. Math layer: no GL.
#pragma once

#include <array>
#include <vector>

namespace sss::math {

// The paper's Table 1: eq. (1)'s strength and falloff as its authors fitted them (in their head
// model's units; sss_settings_separable_table1 pairs them with their own fitted separable_scale).
inline constexpr std::array<float, 3> kTable1Strength = {0.78f, 0.70f, 0.75f};
inline constexpr std::array<float, 3> kTable1Falloff = {0.57f, 0.13f, 0.08f};

struct KernelTap {
  std::array<float, 3> weight;  // r, g, b
  float offset_mm;              // position along the pass direction, profile millimetres
};

// Half-extent R of the kernel in mm: 2 for up to 20 taps, 3 above (the reference implementation's
// choice: more taps can afford to reach further into the tail).
double separable_kernel_range_mm(int samples);

// Tap offsets for an odd `samples` in [3, 65]: samples spaced evenly in t ∈ [-R, R] mapped to
// sign(t)·t²/R, so taps are denser at the centre where the profile is peaked.
std::vector<double> separable_kernel_offsets(int samples);
// The same spacing on [-range_mm, range_mm] (range_mm > 0).
std::vector<double> separable_kernel_offsets(int samples, double range_mm);

// The kernel: centre tap first, then the rest from most negative to most positive offset (the
// reference shader's layout). Each weight is the base profile integrated exactly over its tap's
// interval (midpoints between neighbours; the end taps stop at ±R), normalised per channel, then
// strength s applied: centre 1 - s + s·w0, others s·w. Each channel sums to 1.
// Preconditions (checked by the API layer): samples odd in [3, 65]; strength, falloff in [0, 1].
std::vector<KernelTap> separable_kernel(int samples, const std::array<float, 3>& strength,
                                        const std::array<float, 3>& falloff);
// The same with an explicit half-extent in kernel millimetres.
std::vector<KernelTap> separable_kernel(int samples, const std::array<float, 3>& strength,
                                        const std::array<float, 3>& falloff, double range_mm);

}  // namespace sss::math
