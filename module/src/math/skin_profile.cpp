#include "skin_profile.hpp"

#include <cmath>

namespace sss::math {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

const std::array<GaussianTerm, 6>& skin_gaussians() {
  // Variances in mm² and weights from d'Eon & Luebke (GPU Gems 3, ch. 14), as DESIGN.md §5 lists
  // them (green's second weight is 0.336: the 0.366 printed in one table does not sum to 1).
  static const std::array<GaussianTerm, 6> terms = {{
      {0.0064, {0.233, 0.455, 0.649}},
      {0.0484, {0.100, 0.336, 0.344}},
      {0.187, {0.118, 0.198, 0.0}},
      {0.567, {0.113, 0.007, 0.007}},
      {1.99, {0.358, 0.004, 0.0}},
      {7.41, {0.078, 0.0, 0.0}},
  }};
  return terms;
}

double gaussian_2d(double variance_mm2, double r_mm) {
  return std::exp(-r_mm * r_mm / (2.0 * variance_mm2)) / (2.0 * kPi * variance_mm2);
}

double gaussian_2d_line_integral(double variance_mm2, double scale, double a_mm, double b_mm) {
  // ∫ exp(-(x/s)²/2v) dx = s·sqrt(πv/2)·[erf(x / (s·sqrt(2v)))], times 1/(2πv).
  const double k = scale * std::sqrt(2.0 * variance_mm2);
  const double antiderivative_scale = scale * std::sqrt(kPi * variance_mm2 / 2.0);
  return antiderivative_scale * (std::erf(b_mm / k) - std::erf(a_mm / k)) / (2.0 * kPi * variance_mm2);
}

double separable_base_profile_integral(double falloff, double a_mm, double b_mm) {
  const double scale = 0.001 + falloff;
  double sum = 0.0;
  const auto& terms = skin_gaussians();
  for (std::size_t i = 1; i < terms.size(); ++i) {  // term 0 is the delta (strength)
    sum += terms[i].weight[0] * gaussian_2d_line_integral(terms[i].variance_mm2, scale, a_mm, b_mm);
  }
  return sum;
}

}  // namespace sss::math
