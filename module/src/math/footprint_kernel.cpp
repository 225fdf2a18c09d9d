#include "footprint_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sss::math {

namespace {

std::size_t idx(int i) { return static_cast<std::size_t>(i); }

// The radius beyond which every channel holds at most kFootprintTail of its half mass.
double tail_reach(const std::function<Rgb3(double)>& half_cdf, const Rgb3& half_total, double limit) {
  auto inside = [&](double x) {
    const Rgb3 c = half_cdf(x);
    for (std::size_t k = 0; k < 3; ++k) {
      if (half_total[k] > 0.0 && half_total[k] - c[k] > kFootprintTail * half_total[k]) return false;
    }
    return true;
  };
  double lo = 0.0, hi = limit;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

FootprintTable tabulate_footprint_table(const std::function<Rgb3(double x_mm)>& half_cdf, const Rgb3& half_total,
                                        const Rgb3& delta, double reach_mm, double search_limit_mm) {
  FootprintTable t;
  for (std::size_t c = 0; c < 3; ++c) t.delta[c] = static_cast<float>(delta[c]);
  if (reach_mm <= 0.0) reach_mm = tail_reach(half_cdf, half_total, search_limit_mm);
  t.reach_mm = static_cast<float>(reach_mm);
  t.half_cdf.resize(idx(kFootprintEntries));
  const int last = kFootprintEntries - 1;
  for (int j = 0; j < last; ++j) {
    const double u = static_cast<double>(j) / static_cast<double>(last);
    const Rgb3 c = half_cdf(reach_mm * u * u);
    for (std::size_t k = 0; k < 3; ++k) t.half_cdf[idx(j)][k] = static_cast<float>(c[k]);
  }
  for (std::size_t k = 0; k < 3; ++k) t.half_cdf[idx(last)][k] = static_cast<float>(half_total[k]);
  return t;
}

FootprintTable footprint_table_from_taps(const std::vector<KernelTap>& taps) {
  std::vector<KernelTap> side;  // the centre and the taps at positive offsets, increasing
  for (const KernelTap& tap : taps) {
    if (tap.offset_mm >= 0.0f) side.push_back(tap);
  }
  std::sort(side.begin(), side.end(), [](const KernelTap& a, const KernelTap& b) { return a.offset_mm < b.offset_mm; });
  Rgb3 delta{}, total{};
  if (side.empty()) return tabulate_footprint_table([](double) { return Rgb3{}; }, total, delta, 0.0);
  const bool has_centre = side.front().offset_mm == 0.0f;
  if (side.size() == 1 && has_centre) {
    for (std::size_t c = 0; c < 3; ++c) delta[c] = side.front().weight[c];
    return tabulate_footprint_table([](double) { return Rgb3{}; }, total, delta, 0.0);  // reach 0: a delta
  }
  // Knots of the piecewise-linear half-CDF: the cell edges and the mass up to each.
  std::vector<double> knot_mm = {0.0};
  std::vector<Rgb3> knot_cdf = {Rgb3{}};
  Rgb3 running{};
  for (std::size_t i = 0; i < side.size(); ++i) {
    const double o = side[i].offset_mm;
    const double edge = i + 1 < side.size() ? 0.5 * (o + static_cast<double>(side[i + 1].offset_mm)) : o;
    const double share = (i == 0 && has_centre) ? 0.5 : 1.0;  // the centre cell is split by x = 0
    for (std::size_t c = 0; c < 3; ++c) running[c] += share * side[i].weight[c];
    if (edge > knot_mm.back()) {
      knot_mm.push_back(edge);
      knot_cdf.push_back(running);
    } else {
      knot_cdf.back() = running;  // an end tap whose cell stops at its own offset
    }
  }
  total = running;
  auto cdf = [&](double x) {
    if (x >= knot_mm.back()) return total;
    const auto it = std::upper_bound(knot_mm.begin(), knot_mm.end(), x);
    const std::size_t hi = static_cast<std::size_t>(it - knot_mm.begin());
    const std::size_t lo = hi - 1;
    const double f = (x - knot_mm[lo]) / (knot_mm[hi] - knot_mm[lo]);
    Rgb3 out{};
    for (std::size_t c = 0; c < 3; ++c) out[c] = knot_cdf[lo][c] + f * (knot_cdf[hi][c] - knot_cdf[lo][c]);
    return out;
  };
  return tabulate_footprint_table(cdf, total, delta, knot_mm.back());
}

FootprintTable footprint_table_gaussians(const std::vector<LineGaussian>& mixture) {
  Rgb3 delta{}, total{};
  double widest = 0.0;
  for (const LineGaussian& g : mixture) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (g.variance_mm2 > 0.0) {
        total[c] += 0.5 * g.weight[c];  // half of the Gaussian lies at x >= 0
      } else {
        delta[c] += g.weight[c];
      }
    }
    widest = std::max(widest, g.variance_mm2);
  }
  auto cdf = [&](double x) {
    Rgb3 out{};
    for (const LineGaussian& g : mixture) {
      if (g.variance_mm2 <= 0.0) continue;
      const double half = 0.5 * std::erf(x / std::sqrt(2.0 * g.variance_mm2));
      for (std::size_t c = 0; c < 3; ++c) out[c] += g.weight[c] * half;
    }
    return out;
  };
  if (widest <= 0.0) return tabulate_footprint_table(cdf, total, delta, 0.0);
  return tabulate_footprint_table(cdf, total, delta, 0.0, 8.0 * std::sqrt(widest));
}

std::array<float, 3> footprint_half_cdf(const FootprintTable& table, float x_mm) {
  return footprint_half_cdf_at_fraction(table, x_mm / table.reach_mm);
}

float footprint_midpoint_scale(const FootprintTable& table, float step) { return 0.5f / (table.reach_mm * step); }

std::array<float, 3> footprint_half_cdf_at_fraction(const FootprintTable& table, float fraction) {
  const int last = kFootprintEntries - 1;
  // As the shaders: u = sqrt(min(x / reach, 1)) · (N − 1), linear between the two entries around u.
  const float u = std::sqrt(std::min(fraction, 1.0f)) * static_cast<float>(last);
  const int j = std::min(static_cast<int>(u), last - 1);
  const float f = u - static_cast<float>(j);
  const auto& a = table.half_cdf[idx(j)];
  const auto& b = table.half_cdf[idx(j + 1)];
  return {a[0] * (1.0f - f) + b[0] * f, a[1] * (1.0f - f) + b[1] * f, a[2] * (1.0f - f) + b[2] * f};
}

std::vector<float> footprint_spacing(int half_taps, FootprintLayout layout) {
  std::vector<float> s(idx(half_taps));
  for (int i = 1; i <= half_taps; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(half_taps);
    s[idx(i - 1)] = static_cast<float>(layout == FootprintLayout::cubic ? t * t * t : t * t * std::sqrt(t));
  }
  return s;
}

int first_jittered_tap(float jitter, int half_taps) {
  const long moved = std::lround(static_cast<double>(jitter) * static_cast<double>(half_taps));
  return moved > 0 ? half_taps - static_cast<int>(moved) + 1 : kNoJitter;
}

FootprintTaps footprint_taps(const FootprintTable& table, const std::vector<float>& spacing, float step,
                             int jitter_from, float noise) {
  FootprintTaps out;
  const int half = static_cast<int>(spacing.size());
  bool sparse = false;
  // Bounded so that positions stay far inside int range whatever the step (they are clamped to the
  // viewport afterwards anyway).
  const float reach_px = std::min(table.reach_mm * step, 1.0e6f);
  if (reach_px <= static_cast<float>(half) + 0.5f) {
    out.count = std::max(static_cast<int>(std::ceil(reach_px - 0.5f)), 0);
    for (int i = 0; i < out.count; ++i) out.position[idx(i)] = i + 1;
  } else {
    sparse = true;
    out.count = half;
    int previous = 0;
    for (int i = 0; i < half; ++i) {
      const int p = std::max(previous + 1, static_cast<int>(std::floor(reach_px * spacing[idx(i)] + 0.5f)));
      out.position[idx(i)] = p;
      previous = p;
    }
  }
  const std::array<float, 3>& total = table.half_cdf.back();
  // The centre's cell ends at the midpoint between it (position 0) and the first tap; each tap's at
  // the midpoint to the next.
  const float scale = out.count > 0 ? footprint_midpoint_scale(table, step) : 0.0f;
  std::array<float, 3> below =
      out.count > 0 ? footprint_half_cdf_at_fraction(table, static_cast<float>(out.position[0]) * scale) : total;
  for (std::size_t c = 0; c < 3; ++c) out.weight[0][c] = 2.0f * below[c] + table.delta[c];
  for (int i = 0; i < out.count; ++i) {
    const std::array<float, 3> upto =
        i + 1 < out.count
            ? footprint_half_cdf_at_fraction(
                  table, static_cast<float>(out.position[idx(i)] + out.position[idx(i + 1)]) * scale)
            : total;
    for (std::size_t c = 0; c < 3; ++c) out.weight[idx(i + 1)][c] = upto[c] - below[c];
    below = upto;
  }
  if (sparse && jitter_from <= out.count) {
    // In float, as the shaders: the positions are small integers, so every value here is exact.
    std::array<int, kMaxFootprintHalfTaps> cell = out.position;
    for (int i = std::max(jitter_from, 1); i <= out.count; ++i) {
      const float p = static_cast<float>(cell[idx(i - 1)]);
      const float inner = i > 1 ? static_cast<float>(cell[idx(i - 2)]) : 0.0f;
      const float lo = std::floor(0.5f * (inner + p)) + 1.0f;
      const float hi = i < out.count ? std::floor(0.5f * (p + static_cast<float>(cell[idx(i)]))) : p + (p - lo);
      out.position[idx(i - 1)] = static_cast<int>(lo + std::min(std::floor(noise * (hi - lo + 1.0f)), hi - lo));
    }
  }
  return out;
}

}  // namespace sss::math
