#include "cbf_kernel.hpp"

#include <cmath>

namespace sss::math {

CbfKernel cbf_kernel(const SpikeGaussianProfile& profile, int taps, double r_max_mm) {
  CbfKernel k;
  k.r_max_mm = static_cast<float>(r_max_mm);
  // Each channel's broad marginal over [0, x], normalised to half its mass on [0, r_max].
  Rgb3 half_total{};
  for (int c = 0; c < 3; ++c) half_total[static_cast<std::size_t>(c)] = 0.5;
  const auto half_cdf = [&](double x_mm) {
    Rgb3 out{};
    for (int c = 0; c < 3; ++c) {
      const double total = broad_marginal_integral(profile, c, 0.0, r_max_mm);
      out[static_cast<std::size_t>(c)] = 0.5 * broad_marginal_integral(profile, c, 0.0, std::fmin(x_mm, r_max_mm)) / total;
    }
    return out;
  };
  k.table = tabulate_footprint_table(half_cdf, half_total, Rgb3{}, r_max_mm);
  k.spacing = footprint_spacing(taps / 2, FootprintLayout::cubic);
  for (int c = 0; c < 3; ++c) {
    const auto s = static_cast<std::size_t>(c);
    k.spike_blend[s] = static_cast<float>(profile.spike[s]);
    k.inv_two_variance[s] = static_cast<float>(1.0 / (2.0 * broad_variance_mm2(profile, c)));
  }
  return k;
}

}  // namespace sss::math
