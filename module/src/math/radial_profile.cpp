#include "radial_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace sss::math {

namespace {
constexpr double kPi = 3.14159265358979323846;
// The energy fraction extent_mm() leaves outside.
constexpr double kTailFraction = 1e-4;

// %.17g: the text round-trips the double, so equal text means equal value.
std::string exact(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}
}  // namespace

// ---- Defaults of the interface.

double RadialProfile::support_mm(double tail_fraction) const {
  const Rgb total = integral();
  auto inside_all = [&](double r) {
    const Rgb e = encircled_numeric(*this, r);
    for (std::size_t c = 0; c < 3; ++c) {
      if (total[c] > 0.0 && total[c] - e[c] > tail_fraction * total[c]) return false;
    }
    return true;
  };
  double lo = 0.0, hi = std::max(extent_mm(), 1e-3);
  for (int i = 0; i < 40 && !inside_all(hi); ++i) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside_all(mid) ? hi : lo) = mid;
  }
  return hi;
}

Rgb RadialProfile::encircled(double r_mm) const { return encircled_numeric(*this, r_mm); }

Rgb RadialProfile::outside(double r_mm) const {
  const Rgb total = integral(), inside = encircled(r_mm);
  return {total[0] - inside[0], total[1] - inside[1], total[2] - inside[2]};
}

std::string RadialProfile::identity() const {
  std::string text = "profile";
  for (double r = 0.0; r < 1e3; r = r == 0.0 ? 1e-3 : r * 2.0) {
    const Rgb v = evaluate(r);
    text += ";" + exact(v[0]) + "," + exact(v[1]) + "," + exact(v[2]);
  }
  const Rgb t = integral();
  return text + ";total " + exact(t[0]) + "," + exact(t[1]) + "," + exact(t[2]);
}

// ---- Sum of Gaussians.

GaussianSumProfile::GaussianSumProfile(std::vector<GaussianTerm> terms) : terms_(std::move(terms)) {
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const auto& t : terms_) sum += t.weight[c];
    if (sum > 0.0) {
      for (auto& t : terms_) t.weight[c] /= sum;
    }
  }
}

GaussianSumProfile GaussianSumProfile::skin(int count) {
  const auto& all = skin_gaussians();
  const int n = std::clamp(count, 1, static_cast<int>(all.size()));
  return GaussianSumProfile(std::vector<GaussianTerm>(all.begin(), all.begin() + n));
}

Rgb GaussianSumProfile::evaluate(double r_mm) const {
  Rgb out = {0.0, 0.0, 0.0};
  for (const auto& t : terms_) {
    const double g = gaussian_2d(t.variance_mm2, r_mm);
    for (std::size_t c = 0; c < 3; ++c) out[c] += t.weight[c] * g;
  }
  return out;
}

Rgb GaussianSumProfile::integral() const {
  Rgb out = {0.0, 0.0, 0.0};
  for (const auto& t : terms_) {
    for (std::size_t c = 0; c < 3; ++c) out[c] += t.weight[c];
  }
  return out;
}

double GaussianSumProfile::extent_mm() const {
  // A 2D Gaussian leaves exp(-r²/2v) of its energy outside r.
  double v = 0.0;
  for (const auto& t : terms_) {
    if (t.weight[0] > 0.0 || t.weight[1] > 0.0 || t.weight[2] > 0.0) v = std::max(v, t.variance_mm2);
  }
  return std::sqrt(-2.0 * v * std::log(kTailFraction));
}

double GaussianSumProfile::support_mm(double tail_fraction) const {
  double v = 0.0;
  for (const auto& t : terms_) {
    if (t.weight[0] > 0.0 || t.weight[1] > 0.0 || t.weight[2] > 0.0) v = std::max(v, t.variance_mm2);
  }
  return std::sqrt(-2.0 * v * std::log(tail_fraction));
}

Rgb GaussianSumProfile::outside(double r_mm) const {
  Rgb out{};
  for (const auto& t : terms_) {
    const double g = std::exp(-r_mm * r_mm / (2.0 * t.variance_mm2));
    for (std::size_t c = 0; c < 3; ++c) out[c] += t.weight[c] * g;
  }
  return out;
}

std::string GaussianSumProfile::identity() const {
  std::string text = "gaussian-sum";
  for (const auto& t : terms_) {
    text += ";" + exact(t.variance_mm2) + ":" + exact(t.weight[0]) + "," + exact(t.weight[1]) + "," + exact(t.weight[2]);
  }
  return text;
}

const GaussianSumProfile& deon_skin_profile() {
  static const GaussianSumProfile profile = GaussianSumProfile::skin(6);
  return profile;
}

// ---- Dipole.

double fresnel_diffuse_reflectance(double eta) {
  return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

DipoleProfile::DipoleProfile(const MaterialCoefficients& m) {
  const double fdr = fresnel_diffuse_reflectance(m.eta);
  const double a = (1.0 + fdr) / (1.0 - fdr);  // internal reflection of the boundary
  for (std::size_t c = 0; c < 3; ++c) {
    const double sigma_t = m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c];
    Channel& ch = ch_[c];
    ch.albedo = m.sigma_s_per_mm[c] / sigma_t;
    ch.sigma_tr = std::sqrt(3.0 * m.sigma_a_per_mm[c] * sigma_t);
    ch.z_r = 1.0 / sigma_t;                      // the real source one mean free path deep
    ch.z_v = ch.z_r * (1.0 + 4.0 * a / 3.0);  // its mirror image above the extrapolated boundary
  }
}

Rgb DipoleProfile::evaluate(double r_mm) const {
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Channel& ch = ch_[c];
    const double dr = std::sqrt(r_mm * r_mm + ch.z_r * ch.z_r);
    const double dv = std::sqrt(r_mm * r_mm + ch.z_v * ch.z_v);
    const double real = ch.z_r * (ch.sigma_tr * dr + 1.0) * std::exp(-ch.sigma_tr * dr) / (dr * dr * dr);
    const double virt = ch.z_v * (ch.sigma_tr * dv + 1.0) * std::exp(-ch.sigma_tr * dv) / (dv * dv * dv);
    out[c] = ch.albedo / (4.0 * kPi) * (real + virt);
  }
  return out;
}

Rgb DipoleProfile::encircled(double r_mm) const {
  // d/dd[-exp(-σd)/d] = (σd + 1) exp(-σd)/d², and r dr = d dd: each source integrates in closed form.
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Channel& ch = ch_[c];
    double sum = 0.0;
    for (double z : {ch.z_r, ch.z_v}) {
      const double d = std::sqrt(r_mm * r_mm + z * z);
      sum += std::exp(-ch.sigma_tr * z) - z * std::exp(-ch.sigma_tr * d) / d;
    }
    out[c] = 0.5 * ch.albedo * sum;
  }
  return out;
}

Rgb DipoleProfile::integral() const {
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const Channel& ch = ch_[c];
    out[c] = 0.5 * ch.albedo * (std::exp(-ch.sigma_tr * ch.z_r) + std::exp(-ch.sigma_tr * ch.z_v));
  }
  return out;
}

double DipoleProfile::extent_mm() const { return support_mm(kTailFraction); }

double DipoleProfile::support_mm(double tail_fraction) const {
  const Rgb total = integral();
  double extent = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    // total - encircled rather than 1 - encircled/total: the tail itself, so 1e-9 stays resolvable.
    auto outside = [&](double r) { return (total[c] - encircled(r)[c]) / total[c]; };
    double lo = 0.0, hi = ch_[c].z_v;
    while (outside(hi) > tail_fraction) hi *= 2.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (outside(mid) > tail_fraction ? lo : hi) = mid;
    }
    extent = std::max(extent, hi);
  }
  return extent;
}

std::string DipoleProfile::identity() const {
  std::string text = "dipole";
  for (const Channel& ch : ch_) {
    text += ";" + exact(ch.albedo) + "," + exact(ch.sigma_tr) + "," + exact(ch.z_r) + "," + exact(ch.z_v);
  }
  return text;
}

// ---- Tabulated.

TabulatedProfile::TabulatedProfile(std::vector<double> radii_mm, std::vector<Rgb> values)
    : radii_(std::move(radii_mm)), values_(std::move(values)) {
  if (radii_.size() != values_.size() || radii_.empty()) {
    throw std::invalid_argument("TabulatedProfile: radii and values must be non-empty and of equal length");
  }
  for (std::size_t i = 0; i < radii_.size(); ++i) {
    if (!(radii_[i] >= 0.0) || (i > 0 && !(radii_[i] > radii_[i - 1]))) {
      throw std::invalid_argument("TabulatedProfile: radii must be >= 0 and strictly increasing");
    }
  }
}

Rgb TabulatedProfile::evaluate(double r_mm) const {
  if (r_mm <= radii_.front()) return values_.front();
  if (r_mm > radii_.back()) return {0.0, 0.0, 0.0};
  const auto it = std::upper_bound(radii_.begin(), radii_.end(), r_mm);
  const std::size_t hi = std::min<std::size_t>(static_cast<std::size_t>(it - radii_.begin()), radii_.size() - 1);
  const std::size_t lo = hi - 1;
  const double t = (r_mm - radii_[lo]) / (radii_[hi] - radii_[lo]);
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) out[c] = (1.0 - t) * values_[lo][c] + t * values_[hi][c];
  return out;
}

Rgb TabulatedProfile::integral() const {
  Rgb out{};
  for (std::size_t c = 0; c < 3; ++c) {
    // The constant disk inside the first radius, then 2π∫ r (a + b r) dr per linear segment.
    double sum = 0.5 * values_.front()[c] * radii_.front() * radii_.front();
    for (std::size_t i = 0; i + 1 < radii_.size(); ++i) {
      const double r0 = radii_[i], r1 = radii_[i + 1];
      const double b = (values_[i + 1][c] - values_[i][c]) / (r1 - r0);
      const double a = values_[i][c] - b * r0;
      sum += a * (r1 * r1 - r0 * r0) / 2.0 + b * (r1 * r1 * r1 - r0 * r0 * r0) / 3.0;
    }
    out[c] = 2.0 * kPi * sum;
  }
  return out;
}

std::string TabulatedProfile::identity() const {
  std::string text = "table";
  for (std::size_t i = 0; i < radii_.size(); ++i) {
    text += ";" + exact(radii_[i]) + ":" + exact(values_[i][0]) + "," + exact(values_[i][1]) + "," + exact(values_[i][2]);
  }
  return text;
}

// ---- Generic.

Rgb encircled_numeric(const RadialProfile& p, double r_mm) {
  // r = s² packs the samples near the centre, where measured and dipole profiles peak; Simpson.
  const int n = 4000;
  const double smax = std::sqrt(std::max(r_mm, 0.0));
  const double h = smax / n;
  Rgb sum{};
  // i = 0 is r = 0, whose term 2πr·R(r)·2s is 0 (s = 0) but would read R(0), infinite for Burley.
  for (int i = 1; i <= n; ++i) {
    const double s = h * i;
    const double r = s * s;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const Rgb v = p.evaluate(r);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += w * 2.0 * kPi * r * v[c] * 2.0 * s;
  }
  for (auto& s : sum) s *= h / 3.0;
  return sum;
}

double radius_enclosing(const RadialProfile& p, double fraction) {
  const Rgb total = p.integral();
  double lo = 0.0, hi = p.extent_mm();
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    const Rgb e = encircled_numeric(p, mid);
    bool all = true;
    for (std::size_t c = 0; c < 3; ++c) all = all && (total[c] <= 0.0 || e[c] >= fraction * total[c]);
    (all ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace sss::math
