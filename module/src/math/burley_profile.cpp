#include "burley_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace sss::math {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTailFraction = 1e-4;  // as radial_profile.cpp's extent_mm()
}  // namespace

double burley_dmfp_scaling(double albedo) {
  const double t = albedo - 0.33;
  return 3.5 + 100.0 * t * t * t * t;
}

BurleyParameters burley_from_material(const MaterialCoefficients& m) {
  BurleyParameters p;
  p.albedo = DipoleProfile(m).integral();
  for (std::size_t c = 0; c < 3; ++c) {
    const double sigma_t = m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c];
    p.dmfp_mm[c] = 1.0 / std::sqrt(3.0 * m.sigma_a_per_mm[c] * sigma_t);
  }
  return p;
}

BurleyParameters burley_default_parameters() {
  static const BurleyParameters skin1 =
      burley_from_material(measured_materials()[static_cast<std::size_t>(material_index("skin1"))]);
  return skin1;
}

BurleyProfile::BurleyProfile(const BurleyParameters& p) : albedo_(p.albedo) {
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(p.albedo[c] > 0.0 && p.albedo[c] <= 1.0) || !(p.dmfp_mm[c] > 0.0) || !std::isfinite(p.dmfp_mm[c])) {
      throw std::invalid_argument("BurleyProfile: albedo must be in (0, 1] and dmfp finite and > 0");
    }
    d_[c] = p.dmfp_mm[c] / burley_dmfp_scaling(p.albedo[c]);
  }
}

Rgb BurleyProfile::evaluate(double r_mm) const {
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double d = d_[c];
    out[c] = r_mm > 0.0 ? albedo_[c] * (std::exp(-r_mm / d) + std::exp(-r_mm / (3.0 * d))) / (8.0 * kPi * d * r_mm)
                        : std::numeric_limits<double>::infinity();
  }
  return out;
}

Rgb BurleyProfile::outside(double r_mm) const {
  Rgb out{};
  const double r = std::max(r_mm, 0.0);
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = 0.25 * albedo_[c] * (std::exp(-r / d_[c]) + 3.0 * std::exp(-r / (3.0 * d_[c])));
  }
  return out;
}

Rgb BurleyProfile::encircled(double r_mm) const {
  // A − outside(r), written so that small radii keep their precision: 1 − e^{-x} = −expm1(−x).
  Rgb out{};
  const double r = std::max(r_mm, 0.0);
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = -0.25 * albedo_[c] * (std::expm1(-r / d_[c]) + 3.0 * std::expm1(-r / (3.0 * d_[c])));
  }
  return out;
}

double BurleyProfile::extent_mm() const { return support_mm(kTailFraction); }

double BurleyProfile::support_mm(double tail_fraction) const {
  double extent = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    // outside/A = e^{-x}/4 + 3e^{-x/3}/4 with x = r/d, decreasing in x; 3d·ln(1/tail) already
    // leaves at most `tail` (the first term is below the second), so bisect below it.
    double lo = 0.0, hi = 3.0 * d_[c] * std::log(1.0 / tail_fraction);
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (outside(mid)[c] > tail_fraction * albedo_[c] ? lo : hi) = mid;
    }
    extent = std::max(extent, hi);
  }
  return extent;
}

std::string BurleyProfile::identity() const {
  std::string text = "burley";
  for (std::size_t c = 0; c < 3; ++c) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, ";%.17g,%.17g", albedo_[c], d_[c]);
    text += buffer;
  }
  return text;
}

}  // namespace sss::math
