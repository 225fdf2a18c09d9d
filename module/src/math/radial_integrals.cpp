#include "radial_integrals.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sss::math {

namespace {

constexpr double kPi = 3.14159265358979323846;

// 8-point Gauss–Legendre on [-1, 1].
constexpr std::array<double, 8> kNodes = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                          -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                          0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> kWeights = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                            0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                            0.2223810344533745, 0.1012285362903763};

struct EdgeIntegrand {
  const RadialProfile& profile;
  double h2, p2;
  Rgb operator()(double psi) const {
    const double t = std::tan(psi);
    return profile.outside(std::sqrt(h2 + p2 * (1.0 + t * t)));
  }
};

Rgb gauss(const EdgeIntegrand& f, double a, double b) {
  Rgb sum{};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  for (std::size_t k = 0; k < kNodes.size(); ++k) {
    const Rgb v = f(mid + half * kNodes[k]);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += kWeights[k] * half * v[c];
  }
  return sum;
}

// Adaptive: a panel is accepted when its two halves agree with it to `floor` plus 1e-13 relative.
Rgb adaptive(const EdgeIntegrand& f, double a, double b, const Rgb& whole, double floor, int depth) {
  const double mid = 0.5 * (a + b);
  const Rgb left = gauss(f, a, mid), right = gauss(f, mid, b);
  Rgb halves{};
  bool converged = true;
  for (std::size_t c = 0; c < 3; ++c) {
    halves[c] = left[c] + right[c];
    converged = converged && std::fabs(halves[c] - whole[c]) <= 1e-13 * std::fabs(halves[c]) + floor;
  }
  if (converged || depth >= 40) return halves;
  const Rgb l = adaptive(f, a, mid, left, 0.5 * floor, depth + 1);
  const Rgb r = adaptive(f, mid, b, right, 0.5 * floor, depth + 1);
  return {l[0] + r[0], l[1] + r[1], l[2] + r[2]};
}

}  // namespace

Rgb rectangle_integral(const RadialProfile& profile, double x0, double x1, double y0, double y1, double h_mm) {
  const Rgb total = profile.integral();
  const double floor = 1e-16 * std::max({total[0], total[1], total[2], 0.0});
  const double h2 = h_mm * h_mm;
  Rgb sum{};
  if (x0 < 0.0 && x1 > 0.0 && y0 < 0.0 && y1 > 0.0) sum = profile.outside(std::fabs(h_mm));
  // The edges counter-clockwise.
  const std::array<std::array<double, 2>, 4> v = {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& a = v[k];
    const auto& b = v[(k + 1) % 4];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double length = std::hypot(ex, ey);
    const double ux = ex / length, uy = ey / length;
    const double cross = a[0] * uy - a[1] * ux;  // signed distance of O from the edge's line
    const double p = std::fabs(cross);
    if (!(p > 0.0)) continue;  // the line passes through the foot: it sweeps no angle
    const double t0 = a[0] * ux + a[1] * uy;
    const double psi0 = std::atan(t0 / p), psi1 = std::atan((t0 + length) / p);
    const EdgeIntegrand f{profile, h2, p * p};
    const Rgb edge = adaptive(f, psi0, psi1, gauss(f, psi0, psi1), floor, 0);
    // The polar angle grows along the edge where O lies to its left (cross > 0).
    const double sign = cross > 0.0 ? 1.0 : -1.0;
    for (std::size_t c = 0; c < 3; ++c) sum[c] -= sign * edge[c] / (2.0 * kPi);
  }
  return sum;
}

}  // namespace sss::math
