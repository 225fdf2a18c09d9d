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

// Half-extent R of the kernel in kernel mm, at every tap count: the kernel is a property of the
// look, the taps only how finely it is sampled. (The reference implementation, DESIGN.md's eq. (1)
// notes and this library until issue 49, which changes them, widened it to 3 above 20 taps; the calibrated default was fitted at 17 taps, range 2, so
// 21 taps and more ran a wider kernel with a longer follow-surface reach than the one fitted, and
// missed 0.175 of the head close-up's interior light against 0.103 at 17: docs/migration.md.)
inline constexpr double kSeparableKernelRangeMm = 2.0;

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
