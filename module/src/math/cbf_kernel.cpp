#include "cbf_kernel.hpp"

#include <cmath>

namespace sss::math {

std::vector<double> cbf_tap_offsets(const SpikeGaussianProfile& profile, int taps, double r_max_mm,
                                    std::vector<double>* boundaries) {
  const double total = broad_marginal_integral(profile, 0, -r_max_mm, r_max_mm);
  // The truncated CDF is monotonic: bisection to a few ulps is plenty for 13..65 taps.
  auto inverse_cdf = [&](double probability) {
    double lo = -r_max_mm, hi = r_max_mm;
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (broad_marginal_integral(profile, 0, -r_max_mm, mid) / total < probability ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  std::vector<double> offsets(static_cast<std::size_t>(taps));
  const int middle = taps / 2;
  for (int i = 0; i < taps; ++i) {
    // The middle tap sits at the median, 0 by symmetry: set it exactly; mirror the rest.
    if (i < middle) offsets[static_cast<std::size_t>(i)] = inverse_cdf((i + 0.5) / taps);
    else if (i == middle) offsets[static_cast<std::size_t>(i)] = 0.0;
    else offsets[static_cast<std::size_t>(i)] = -offsets[static_cast<std::size_t>(taps - 1 - i)];
  }
  if (boundaries != nullptr) {
    boundaries->assign(static_cast<std::size_t>(taps) + 1, 0.0);
    for (int i = 0; i <= taps / 2; ++i) {
      const double b = i == 0 ? -r_max_mm : inverse_cdf(static_cast<double>(i) / taps);
      (*boundaries)[static_cast<std::size_t>(i)] = b;
      (*boundaries)[static_cast<std::size_t>(taps - i)] = -b;
    }
  }
  return offsets;
}

CbfKernel cbf_kernel(const SpikeGaussianProfile& profile, int taps, double r_max_mm) {
  std::vector<double> bounds;
  const std::vector<double> offsets = cbf_tap_offsets(profile, taps, r_max_mm, &bounds);
  std::array<std::vector<double>, 3> mass;
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (int i = 0; i < taps; ++i) {
      const double m = broad_marginal_integral(profile, c, bounds[static_cast<std::size_t>(i)],
                                               bounds[static_cast<std::size_t>(i) + 1]);
      mass[static_cast<std::size_t>(c)].push_back(m);
      sum += m;
    }
    for (double& m : mass[static_cast<std::size_t>(c)]) m /= sum;
  }
  CbfKernel k;
  k.r_max_mm = static_cast<float>(r_max_mm);
  auto tap = [&](int i) {
    KernelTap t{};
    for (int c = 0; c < 3; ++c) {
      t.weight[static_cast<std::size_t>(c)] =
          static_cast<float>(mass[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)]);
    }
    t.offset_mm = static_cast<float>(offsets[static_cast<std::size_t>(i)]);
    return t;
  };
  const int middle = taps / 2;
  k.taps.push_back(tap(middle));
  for (int i = 0; i < taps; ++i) {
    if (i != middle) k.taps.push_back(tap(i));
  }
  for (int c = 0; c < 3; ++c) {
    const auto s = static_cast<std::size_t>(c);
    k.spike_blend[s] = static_cast<float>(1.0 - std::sqrt(1.0 - profile.spike[s]));
    k.inv_two_variance[s] = static_cast<float>(1.0 / (2.0 * broad_variance_mm2(profile, c)));
  }
  return k;
}

}  // namespace sss::math
