#include "radial_profile.hpp"

#include <cmath>
#include <cstdio>

namespace sss::math {

SumOfGaussiansProfile::SumOfGaussiansProfile(std::string name, std::vector<GaussianTerm> terms)
    : terms_(std::move(terms)) {
  // exp(-R²/2v) of a 2D Gaussian's mass lies beyond R: 1e-9 for R = sqrt(2 v ln 1e9).
  identity_ = std::move(name);
  for (const GaussianTerm& t : terms_) {
    if (t.weight[0] > 0.0 || t.weight[1] > 0.0 || t.weight[2] > 0.0) {
      support_mm_ = std::max(support_mm_, std::sqrt(2.0 * t.variance_mm2 * std::log(1e9)));
    }
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, ";%.17g:%.17g,%.17g,%.17g", t.variance_mm2, t.weight[0], t.weight[1],
                  t.weight[2]);
    identity_ += buffer;
  }
}

std::array<double, 3> SumOfGaussiansProfile::evaluate(double r_mm) const {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (const GaussianTerm& t : terms_) {
    const double g = gaussian_2d(t.variance_mm2, r_mm);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += t.weight[c] * g;
  }
  return sum;
}

const RadialProfile& deon_skin_profile() {
  static const SumOfGaussiansProfile profile(
      "deon-luebke-skin", std::vector<GaussianTerm>(skin_gaussians().begin(), skin_gaussians().end()));
  return profile;
}

}  // namespace sss::math
