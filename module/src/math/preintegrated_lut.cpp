#include "preintegrated_lut.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

namespace sss::math {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kOrder = kLutQuadratureOrder;  // Gauss–Legendre points per panel
using GaussLegendre = LutQuadratureRule;

// Nodes and weights by Newton's method on P_n (three-term recurrence), computed once.
const GaussLegendre& gauss_legendre() {
  static const GaussLegendre rule = [] {
    GaussLegendre g;
    for (int i = 0; i < kOrder; ++i) {
      double x = std::cos(kPi * (i + 0.75) / (kOrder + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= kOrder; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = kOrder * (x * p1 - p0) / (x * x - 1.0);
        const double step = p1 / derivative;
        x -= step;
        if (std::fabs(step) < 1e-16) break;
      }
      g.node[static_cast<std::size_t>(i)] = x;
      g.weight[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return g;
  }();
  return rule;
}

double saturate(double v) { return std::clamp(v, 0.0, 1.0); }

// Profile distances where the panels split: doubling from 0.01 mm to the support, so each
// Gaussian term (σ from 0.08 to 2.7 mm for skin) spans a few panels of comparable size.
std::vector<double> distance_breaks(double support_mm) {
  std::vector<double> d;
  for (double v = 0.01; v < support_mm; v *= 2.0) d.push_back(v);
  d.push_back(support_mm);
  return d;
}

// Sorted, deduplicated panel ends in [0, end], given candidate interior points.
std::vector<double> panels(std::vector<double> points, double end) {
  points.push_back(0.0);
  points.push_back(end);
  points.erase(std::remove_if(points.begin(), points.end(), [end](double p) { return !(p >= 0.0 && p <= end); }),
               points.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end(), [](double a, double b) { return b - a < 1e-15; }),
               points.end());
  return points;
}

// ∫ over [0, end] of light(x)·w_c(x) and of w_c(x), panel by panel.
template <typename Light, typename Weight>
void integrate(const std::vector<double>& ends, Light light, Weight weight, std::array<double, 3>& lit,
               std::array<double, 3>& total) {
  const GaussLegendre& g = gauss_legendre();
  lit = {0.0, 0.0, 0.0};
  total = {0.0, 0.0, 0.0};
  for (std::size_t p = 0; p + 1 < ends.size(); ++p) {
    const double half = 0.5 * (ends[p + 1] - ends[p]);
    const double mid = 0.5 * (ends[p + 1] + ends[p]);
    for (std::size_t i = 0; i < static_cast<std::size_t>(kOrder); ++i) {
      const double x = mid + half * g.node[i];
      const std::array<double, 3> w = weight(x);
      const double l = light(x);
      for (std::size_t c = 0; c < 3; ++c) {
        lit[c] += g.weight[i] * half * l * w[c];
        total[c] += g.weight[i] * half * w[c];
      }
    }
  }
}

// Inverse of the standard normal CDF by bisection on erfc (monotone, exact to double rounding).
double inverse_normal_cdf(double p) {
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double grid(double lo, double hi, int i, int n) { return n <= 1 ? lo : lo + (hi - lo) * i / (n - 1.0); }

template <typename Row>
void run_rows(int height, int threads, Row row) {
  int n = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  n = std::clamp(n, 1, std::max(1, height));
  if (n == 1) {
    for (int y = 0; y < height; ++y) row(y);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) {
    pool.emplace_back([t, n, height, &row] {
      for (int y = t; y < height; y += n) row(y);  // interleaved: rows differ in cost
    });
  }
  for (std::thread& th : pool) th.join();
}

}  // namespace

namespace {

// D(θ, r) with the profile's support (lut_support_mm) computed by the caller: once per LUT.
std::array<double, 3> diffuse_value(const RadialProfile& profile, double support, double ndotl,
                                    double curvature_per_mm) {
  const double cos_theta = std::clamp(ndotl, -1.0, 1.0);
  if (!(curvature_per_mm > 0.0)) {
    const double flat = saturate(cos_theta);  // r = ∞: no light crosses a lighting change
    return {flat, flat, flat};
  }
  const double r = 1.0 / curvature_per_mm;
  const double theta = std::acos(cos_theta);
  // The ring is folded onto x in [0, X]: x and -x share the weight R(2r·sin(x/2)).
  const double x_end = support >= 2.0 * r ? kPi : 2.0 * std::asin(support / (2.0 * r));
  std::vector<double> points;
  for (double d : distance_breaks(support)) {
    if (d < 2.0 * r) points.push_back(2.0 * std::asin(d / (2.0 * r)));
  }
  // Kinks of saturate(cos(θ ± x)): θ + x = π/2 or 3π/2, θ - x = ±π/2.
  points.insert(points.end(), {0.5 * kPi - theta, 1.5 * kPi - theta, theta - 0.5 * kPi, theta + 0.5 * kPi});
  const std::vector<double> ends = panels(points, x_end);
  std::array<double, 3> lit{}, total{};
  integrate(
      ends, [theta](double x) { return saturate(std::cos(theta + x)) + saturate(std::cos(theta - x)); },
      [&profile, r](double x) { return profile.evaluate(2.0 * r * std::sin(0.5 * x)); }, lit, total);
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < 3; ++c) out[c] = total[c] > 0.0 ? saturate(lit[c] / (2.0 * total[c])) : saturate(cos_theta);
  return out;
}

}  // namespace

double lut_support_mm(const RadialProfile& profile) { return profile.support_mm(kLutTailFraction); }

std::array<double, 3> preintegrated_diffuse(const RadialProfile& profile, double ndotl, double curvature_per_mm) {
  return diffuse_value(profile, lut_support_mm(profile), ndotl, curvature_per_mm);
}

double shadow_penumbra_position(ShadowFilter filter, double s) {
  const double v = saturate(s);
  if (filter == ShadowFilter::box) return v;
  // Φ^-1 is infinite at 0 and 1: the penumbra is taken to end at ±2σ·Φ^-1(1e-6)/2 ≈ ±1.2 widths.
  return 0.5 + 0.25 * inverse_normal_cdf(std::clamp(v, 1e-6, 1.0 - 1e-6));
}

double new_penumbra_value(double fraction, double t) {
  const double f = std::clamp(fraction, 1e-6, 1.0);
  return saturate((t - (0.5 - 0.5 * f)) / f);
}

namespace {

// The unnormalised §1.6 integral: P' at the penumbra position of s, blurred by the profile.
std::array<double, 3> shadow_blur(const RadialProfile& profile, double support, const ShadowLutDesc& desc, double t0,
                                  double q) {
  const double f = std::clamp(desc.new_penumbra, 1e-6, 1.0);
  const double a = 0.5 - 0.5 * f, b = 0.5 + 0.5 * f;
  std::vector<double> points = distance_breaks(support);
  // Kinks of P'(t0 ± y·q).
  for (double edge : {a, b}) points.push_back(std::fabs(edge - t0) / q);
  const std::vector<double> ends = panels(points, support);
  std::array<double, 3> lit{}, total{};
  integrate(
      ends, [&](double y) { return new_penumbra_value(f, t0 + y * q) + new_penumbra_value(f, t0 - y * q); },
      [&profile](double y) { return profile.evaluate(y); }, lit, total);
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < 3; ++c) out[c] = total[c] > 0.0 ? lit[c] / (2.0 * total[c]) : new_penumbra_value(f, t0);
  return out;
}

}  // namespace

namespace {

// The ends of the rescaling: the blurred P' at the positions of s = 0 and s = 1 for one penumbra
// width (q penumbra widths per mm). Shared by a LUT row.
struct ShadowEnds {
  std::array<double, 3> lo{}, hi{};
};

ShadowEnds shadow_ends(const RadialProfile& profile, double support, const ShadowLutDesc& desc, double q) {
  return {shadow_blur(profile, support, desc, shadow_penumbra_position(desc.filter, 0.0), q),
          shadow_blur(profile, support, desc, shadow_penumbra_position(desc.filter, 1.0), q)};
}

double shadow_q(const ShadowLutDesc& desc, double penumbra_world) {
  return desc.world_units_per_mm / std::max(penumbra_world, 1e-300);
}

std::array<double, 3> shadow_value(const RadialProfile& profile, double support, const ShadowLutDesc& desc, double s,
                                   double q, const ShadowEnds& ends) {
  const double t0 = shadow_penumbra_position(desc.filter, s);
  const double f = std::clamp(desc.new_penumbra, 1e-6, 1.0);
  if (!(q > 0.0) || !std::isfinite(q)) {
    const double v = new_penumbra_value(f, t0);
    return {v, v, v};
  }
  const std::array<double, 3> value = shadow_blur(profile, support, desc, t0, q);
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double span = ends.hi[c] - ends.lo[c];
    // A penumbra so narrow that the whole of it sees the same blurred light: nothing to rescale.
    out[c] = span > 1e-6 ? saturate((value[c] - ends.lo[c]) / span) : new_penumbra_value(f, t0);
  }
  return out;
}

}  // namespace

std::array<double, 3> preintegrated_shadow(const RadialProfile& profile, const ShadowLutDesc& desc, double s,
                                           double penumbra_world) {
  const double q = shadow_q(desc, penumbra_world);
  const double support = lut_support_mm(profile);
  const ShadowEnds ends = q > 0.0 && std::isfinite(q) ? shadow_ends(profile, support, desc, q) : ShadowEnds{};
  return shadow_value(profile, support, desc, s, q, ends);
}

const LutQuadratureRule& lut_quadrature_rule() { return gauss_legendre(); }

double diffuse_lut_ndotl(const DiffuseLutDesc& desc, int x) { return grid(-1.0, 1.0, x, desc.width); }
double diffuse_lut_curvature(const DiffuseLutDesc& desc, int y) {
  return grid(desc.curvature_min_per_mm, desc.curvature_max_per_mm, y, desc.height);
}
double shadow_lut_value(const ShadowLutDesc& desc, int x) { return grid(0.0, 1.0, x, desc.width); }
double shadow_lut_penumbra(const ShadowLutDesc& desc, int y) {
  return grid(desc.penumbra_min, desc.penumbra_max, y, desc.height);
}

void generate_diffuse_lut(const RadialProfile& profile, const DiffuseLutDesc& desc, int threads, float* out_rgba) {
  const double support = lut_support_mm(profile);
  run_rows(desc.height, threads, [&](int y) {
    const double k = diffuse_lut_curvature(desc, y);
    float* row = out_rgba + static_cast<std::size_t>(y) * static_cast<std::size_t>(desc.width) * 4;
    for (int x = 0; x < desc.width; ++x) {
      const std::array<double, 3> d = diffuse_value(profile, support, diffuse_lut_ndotl(desc, x), k);
      float* texel = row + static_cast<std::size_t>(x) * 4;
      for (std::size_t c = 0; c < 3; ++c) texel[c] = static_cast<float>(d[c]);
      texel[3] = 1.0f;
    }
  });
}

void generate_shadow_lut(const RadialProfile& profile, const ShadowLutDesc& desc, int threads, float* out_rgba) {
  const double support = lut_support_mm(profile);
  run_rows(desc.height, threads, [&](int y) {
    const double q = shadow_q(desc, shadow_lut_penumbra(desc, y));
    const ShadowEnds ends =
        q > 0.0 && std::isfinite(q) ? shadow_ends(profile, support, desc, q) : ShadowEnds{};  // once a row
    float* row = out_rgba + static_cast<std::size_t>(y) * static_cast<std::size_t>(desc.width) * 4;
    for (int x = 0; x < desc.width; ++x) {
      const std::array<double, 3> p = shadow_value(profile, support, desc, shadow_lut_value(desc, x), q, ends);
      float* texel = row + static_cast<std::size_t>(x) * 4;
      for (std::size_t c = 0; c < 3; ++c) texel[c] = static_cast<float>(p[c]);
      texel[3] = 1.0f;
    }
  });
}

std::string diffuse_lut_key(const RadialProfile& profile, const DiffuseLutDesc& desc) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "diffuse;%d;%d;%.17g;%.17g;", desc.width, desc.height,
                desc.curvature_min_per_mm, desc.curvature_max_per_mm);
  return buffer + profile.identity();
}

std::string shadow_lut_key(const RadialProfile& profile, const ShadowLutDesc& desc) {
  char buffer[320];
  std::snprintf(buffer, sizeof buffer, "shadow;%d;%d;%.17g;%.17g;%.17g;%.17g;%d;", desc.width, desc.height,
                desc.penumbra_min, desc.penumbra_max, desc.world_units_per_mm, desc.new_penumbra,
                static_cast<int>(desc.filter));
  return buffer + profile.identity();
}

std::uint64_t lut_hash(const std::string& key) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char ch : key) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace sss::math
