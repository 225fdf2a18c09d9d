#include "profile_grid.hpp"

#include <cmath>

#include "radial_integrals.hpp"

namespace sss::math {

namespace {
// 6-point Gauss-Legendre nodes and weights on [-1, 1]: exact for polynomials of degree 11, enough for
// the smooth profile over one cell (cells are at most a few percent of the profile's extent wide).
constexpr std::array<double, 6> kNodes = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                          0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr std::array<double, 6> kWeights = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                            0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
}  // namespace

TapGrid make_tap_grid(int taps, double radius_mm, TapSpacing spacing) {
  TapGrid g;
  const int half = taps / 2;
  g.offsets_mm.resize(static_cast<std::size_t>(taps));
  for (int i = 0; i < taps; ++i) {
    // Symmetric integer steps keep the centre exactly 0.
    const double t = half == 0 ? 0.0 : radius_mm * static_cast<double>(i - half) / static_cast<double>(half);
    g.offsets_mm[static_cast<std::size_t>(i)] =
        spacing == TapSpacing::quadratic ? std::copysign(t * t / radius_mm, t) : t;
  }
  g.edges_mm.resize(static_cast<std::size_t>(taps) + 1);
  g.edges_mm.front() = -radius_mm;
  g.edges_mm.back() = radius_mm;
  for (std::size_t i = 1; i < static_cast<std::size_t>(taps); ++i) {
    g.edges_mm[i] = 0.5 * (g.offsets_mm[i - 1] + g.offsets_mm[i]);
  }
  if (taps == 1) g.edges_mm = {-radius_mm, radius_mm};
  return g;
}

ProfileMatrix discretise_profile(const RadialProfile& profile, const TapGrid& grid) {
  ProfileMatrix m;
  m.grid = grid;
  const int n = grid.size();
  for (auto& c : m.cells) c.assign(static_cast<std::size_t>(n * n), 0.0);
  // The quadrature points along one axis, shared by rows and columns.
  std::vector<double> x, wx;
  for (int i = 0; i < n; ++i) {
    const double a = grid.edges_mm[static_cast<std::size_t>(i)], b = grid.edges_mm[static_cast<std::size_t>(i) + 1];
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      x.push_back(0.5 * (a + b) + 0.5 * (b - a) * kNodes[k]);
      wx.push_back(0.5 * (b - a) * kWeights[k]);
    }
  }
  const std::size_t q = kNodes.size();
  // By symmetry only i <= j is integrated.
  for (int i = 0; i < n; ++i) {
    for (int j = i; j < n; ++j) {
      Rgb sum{};
      if (profile.singular_at_centre()) {
        // Gauss–Legendre cannot follow R to infinity at the centre: the cells' exact integrals.
        const auto e = [&grid](int k) { return grid.edges_mm[static_cast<std::size_t>(k)]; };
        sum = rectangle_integral(profile, e(i), e(i + 1), e(j), e(j + 1));
      }
      for (std::size_t a = 0; a < q && !profile.singular_at_centre(); ++a) {
        for (std::size_t b = 0; b < q; ++b) {
          const std::size_t ia = static_cast<std::size_t>(i) * q + a, jb = static_cast<std::size_t>(j) * q + b;
          const Rgb v = profile.evaluate(std::hypot(x[ia], x[jb]));
          const double w = wx[ia] * wx[jb];
          for (std::size_t c = 0; c < 3; ++c) sum[c] += w * v[c];
        }
      }
      for (std::size_t c = 0; c < 3; ++c) {
        m.cells[c][static_cast<std::size_t>(i * n + j)] = sum[c];
        m.cells[c][static_cast<std::size_t>(j * n + i)] = sum[c];
      }
    }
  }
  for (std::size_t c = 0; c < 3; ++c) {
    double total = 0.0;
    for (double v : m.cells[c]) total += v;
    m.totals[c] = total;
    if (total > 0.0) {
      for (double& v : m.cells[c]) v /= total;
    }
  }
  return m;
}

}  // namespace sss::math
