#include "separable_kernel.hpp"

#include <cmath>

#include "skin_profile.hpp"

namespace sss::math {

std::vector<double> separable_kernel_offsets(int samples) {
  return separable_kernel_offsets(samples, kSeparableKernelRangeMm);
}

std::vector<double> separable_kernel_offsets(int samples, double range) {
  std::vector<double> offsets(static_cast<std::size_t>(samples));
  const int half = samples / 2;
  for (int i = 0; i < samples; ++i) {
    // Exact symmetric integer steps avoid a centre that is 1e-17 instead of 0.
    const double t = range * static_cast<double>(i - half) / static_cast<double>(half);
    offsets[static_cast<std::size_t>(i)] = std::copysign(t * t / range, t);
  }
  return offsets;
}

std::vector<KernelTap> separable_kernel(int samples, const std::array<float, 3>& strength,
                                        const std::array<float, 3>& falloff) {
  return separable_kernel(samples, strength, falloff, kSeparableKernelRangeMm);
}

std::vector<KernelTap> separable_kernel(int samples, const std::array<float, 3>& strength,
                                        const std::array<float, 3>& falloff, double range) {
  const std::vector<double> offsets = separable_kernel_offsets(samples, range);
  const std::size_t n = offsets.size();

  // Weights in spatial order: the profile integrated over each tap's interval.
  std::vector<std::array<double, 3>> weights(n);
  std::array<double, 3> sums = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; ++i) {
    const double lo = i == 0 ? -range : 0.5 * (offsets[i - 1] + offsets[i]);
    const double hi = i + 1 == n ? range : 0.5 * (offsets[i] + offsets[i + 1]);
    for (int c = 0; c < 3; ++c) {
      const double w = separable_base_profile_integral(falloff[static_cast<std::size_t>(c)], lo, hi);
      weights[i][static_cast<std::size_t>(c)] = w;
      sums[static_cast<std::size_t>(c)] += w;
    }
  }

  // Reorder (centre first), normalise, apply strength.
  const std::size_t centre = n / 2;
  std::vector<KernelTap> kernel;
  kernel.reserve(n);
  auto emit = [&](std::size_t i, bool is_centre) {
    KernelTap tap{};
    tap.offset_mm = static_cast<float>(offsets[i]);
    for (std::size_t c = 0; c < 3; ++c) {
      const double s = strength[c];
      const double normalised = weights[i][c] / sums[c];
      tap.weight[c] = static_cast<float>(is_centre ? 1.0 - s + s * normalised : s * normalised);
    }
    kernel.push_back(tap);
  };
  emit(centre, true);
  for (std::size_t i = 0; i < n; ++i) {
    if (i != centre) emit(i, false);
  }
  return kernel;
}

}  // namespace sss::math
