// Burley's normalized diffusion (module/src/math/burley_profile.hpp) and the integrals the exact
// reference needs for it (radial_integrals.hpp, radial_plane_reference.hpp): every closed form
// against an independent numerical integration, the energy (= A), and the plane reference against
// the separable one where both apply (Gaussians).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "math/burley_profile.hpp"
#include "math/exact_reference.hpp"
#include "math/kernel_request.hpp"
#include "math/plane_reference.hpp"
#include "math/profile_grid.hpp"
#include "math/radial_integrals.hpp"
#include "math/radial_plane_reference.hpp"

namespace {

using sss::math::BurleyParameters;
using sss::math::BurleyProfile;
using sss::math::Rgb;

constexpr double kPi = 3.14159265358979323846;

// A marble-like and a skin-like profile, and one with a channel at the albedo the fit centres on.
std::vector<BurleyParameters> cases() {
  return {sss::math::burley_default_parameters(),
          sss::math::burley_from_material(sss::math::measured_materials()[5]),  // marble
          BurleyParameters{{0.33, 0.9, 0.05}, {0.2, 4.0, 1.0}}};
}

// Composite Gauss–Legendre (8 nodes per panel) of f over [a, b].
double integrate(const std::function<double(double)>& f, double a, double b, int panels) {
  static constexpr double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                  0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static constexpr double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                  0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double sum = 0.0;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int k = 0; k < 8; ++k) sum += 0.5 * h * w[k] * f(mid + 0.5 * h * x[k]);
  }
  return sum;
}

// ∫∫ R over a rectangle by Duffy's transform, independent of radial_integrals: the rectangle is
// the signed sum of the triangles (0, v_k, v_k+1); on each, p = u·(v_k + t·(v_k+1 − v_k)) with
// Jacobian u·cross(v_k, v_k+1 − v_k), which cancels the 1/r at the centre.
double duffy_rectangle(const BurleyProfile& p, int c, double x0, double x1, double y0, double y1) {
  const double v[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double* a = v[k];
    const double* b = v[(k + 1) % 4];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double jac = a[0] * ey - a[1] * ex;
    sum += jac * integrate(
                     [&](double t) {
                       const double r1 = std::hypot(a[0] + t * ex, a[1] + t * ey);
                       // u·R(u·r1): bounded at u = 0, where R is infinite.
                       return integrate([&](double u) { return u * p.evaluate(u * r1)[static_cast<std::size_t>(c)]; },
                                        0.0, 1.0, 64);
                     },
                     0.0, 1.0, 16);
  }
  return sum;
}

TEST(Burley, DmfpFitIsTheMemosEquation8) {
  EXPECT_DOUBLE_EQ(sss::math::burley_dmfp_scaling(0.33), 3.5);
  EXPECT_NEAR(sss::math::burley_dmfp_scaling(0.83), 3.5 + 100.0 * 0.0625, 1e-12);
  const BurleyProfile p(BurleyParameters{{0.33, 0.83, 0.5}, {1.0, 2.0, 3.0}});
  EXPECT_DOUBLE_EQ(p.shape_mm()[0], 1.0 / 3.5);
  EXPECT_NEAR(p.shape_mm()[1], 2.0 / 9.75, 1e-15);
}

TEST(Burley, MeasuredMaterialsGiveTheDipolesAlbedoAndOneOverSigmaTr) {
  for (const auto& m : sss::math::measured_materials()) {
    const BurleyParameters b = sss::math::burley_from_material(m);
    const Rgb rd = sss::math::DipoleProfile(m).integral();
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(b.albedo[c], rd[c]) << m.name;
      const double st = m.sigma_a_per_mm[c] + m.sigma_s_per_mm[c];
      EXPECT_NEAR(b.dmfp_mm[c] * std::sqrt(3.0 * m.sigma_a_per_mm[c] * st), 1.0, 1e-14) << m.name;
      EXPECT_GT(b.albedo[c], 0.0);
      EXPECT_LE(b.albedo[c], 1.0);
    }
  }
}

// The closed-form CDF against 2π∫ r R(r) dr numerically (r = s² keeps the integrand smooth at 0),
// and the energy: outside + encircled = A, everything = A.
TEST(Burley, ClosedFormEncircledEnergyMatchesNumericalIntegration) {
  for (const BurleyParameters& b : cases()) {
    const BurleyProfile p(b);
    for (double r : {1e-4, 0.01, 0.3, 1.0, 4.0, 20.0}) {
      const Rgb closed = p.encircled(r), out = p.outside(r);
      for (int c = 0; c < 3; ++c) {
        const auto cc = static_cast<std::size_t>(c);
        const double numeric = integrate(
            [&](double s) { return 2.0 * kPi * s * s * p.evaluate(s * s)[cc] * 2.0 * s; }, 0.0, std::sqrt(r), 256);
        EXPECT_NEAR(closed[cc], numeric, 1e-12 * b.albedo[cc]) << r << " mm, channel " << c;
        EXPECT_NEAR(closed[cc] + out[cc], b.albedo[cc], 1e-15);
      }
    }
    const Rgb total = sss::math::encircled_numeric(p, p.support_mm(1e-12));
    // support_mm: the radius the widest channel needs to leave 1e-6 outside; the others leave less.
    const Rgb tail = p.outside(p.support_mm(1e-6));
    double widest = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(p.integral()[c], b.albedo[c]);
      EXPECT_NEAR(total[c], b.albedo[c], 1e-9);
      EXPECT_LE(tail[c], 1e-6 * b.albedo[c] * (1.0 + 1e-9));
      widest = std::max(widest, tail[c] / b.albedo[c]);
    }
    EXPECT_NEAR(widest, 1e-6, 1e-15);
  }
}

// The line profile (K0) against ∫ R(√(x² + y²)) dy numerically (y = x·sinh t), and its integral: A.
TEST(Burley, LineProfileIsTheMarginalAndIntegratesToTheAlbedo) {
  for (const BurleyParameters& b : cases()) {
    const BurleyProfile p(b);
    for (std::size_t c = 0; c < 3; ++c) {
      const double d = p.shape_mm()[c];
      for (double x : {0.01 * d, 0.5 * d, 3.0 * d, 20.0 * d}) {
        const double numeric = 2.0 * integrate(
                                         [&](double t) {
                                           const double y = x * std::sinh(t);
                                           return p.evaluate(std::hypot(x, y))[c] * x * std::cosh(t);
                                         },
                                         0.0, std::asinh(200.0 * d / x), 256);
        EXPECT_NEAR(sss::math::burley_line_profile(p, x)[c], numeric, 1e-10 * numeric) << x << " mm";
      }
      // x = e^u takes the logarithm of K0 at 0 (e^-40 d leaves ~1e-16 below); 200 d, e^{-66} beyond.
      const double total = 2.0 * integrate(
                                     [&](double u) {
                                       const double x = std::exp(u);
                                       return sss::math::burley_line_profile(p, x)[c] * x;
                                     },
                                     std::log(d) - 40.0, std::log(200.0 * d), 512);
      EXPECT_NEAR(total, b.albedo[c], 1e-10);
    }
  }
}

// Cells near and far, the centre one (R infinite inside), one holding the centre off its middle.
TEST(Burley, RectangleIntegralsMatchDuffysQuadrature) {
  const std::vector<std::array<double, 4>> cells = {
      {-0.05, 0.05, -0.05, 0.05}, {0.05, 0.15, -0.05, 0.05}, {-0.3, 0.02, -0.01, 0.5}, {1.0, 1.7, 2.0, 2.2},
      {-4.0, -3.0, 0.5, 6.0}};
  for (const BurleyParameters& b : cases()) {
    const BurleyProfile p(b);
    for (const auto& r : cells) {
      const Rgb v = sss::math::rectangle_integral(p, r[0], r[1], r[2], r[3]);
      for (int c = 0; c < 3; ++c) {
        const double expected = duffy_rectangle(p, c, r[0], r[1], r[2], r[3]);
        EXPECT_NEAR(v[static_cast<std::size_t>(c)], expected, 1e-11 * b.albedo[static_cast<std::size_t>(c)] + 1e-9 * expected)
            << r[0] << " " << r[1] << " " << r[2] << " " << r[3] << ", channel " << c;
      }
    }
  }
}

// Off the plane too (h > 0), against the Gaussians' erf closed form (exact_reference.hpp).
TEST(Burley, RectangleIntegralsOfGaussiansMatchTheirClosedForm) {
  const auto& skin = sss::math::deon_skin_profile();
  for (double h : {0.0, 0.1, 1.5}) {
    for (const auto& r : std::vector<std::array<double, 4>>{{-0.1, 0.1, -0.1, 0.1}, {0.3, 0.9, -2.0, 0.4}, {2.0, 2.5, 3.0, 4.0}}) {
      const Rgb v = sss::math::rectangle_integral(skin, r[0], r[1], r[2], r[3], h);
      Rgb expected{};
      for (const auto& t : skin.terms()) {
        const double i = sss::math::gaussian_rectangle_integral(t.variance_mm2, 0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]),
                                                                h * h, r[1] - r[0], r[3] - r[2]);
        for (std::size_t c = 0; c < 3; ++c) expected[c] += t.weight[c] * i;
      }
      for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(v[c], expected[c], 1e-13) << h << " mm above, channel " << c;
    }
  }
}

// The plane reference for radial profiles gives the separable one's numbers for d'Eon's Gaussians.
TEST(RadialPlaneReference, MatchesTheSeparableReferenceForGaussians) {
  const int w = 24, h = 20;
  std::vector<float> e(static_cast<std::size_t>(w * h * 4));
  for (int i = 0; i < w * h; ++i) {
    for (int c = 0; c < 3; ++c) e[static_cast<std::size_t>(i * 4 + c)] = (i % 7 == 0 || i / w > 12) ? 1.0f + static_cast<float>(c) : 0.05f;
  }
  const sss::math::PlaneInput in{w, h, e.data(), 0.3, 0.25};
  std::vector<double> separable(static_cast<std::size_t>(w * h * 3)), radial(separable.size(), -1.0);
  sss::math::convolve_fronto_parallel_plane(in, sss::math::skin_profile_terms(), separable.data());
  sss::math::convolve_plane_radial(in, sss::math::deon_skin_profile(), {2, 3, 18, 15}, radial.data(), 2);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool inside = x >= 2 && x < 20 && y >= 3 && y < 18;
      for (int c = 0; c < 3; ++c) {
        const auto i = static_cast<std::size_t>((y * w + x) * 3 + c);
        if (inside) {
          EXPECT_NEAR(radial[i], separable[i], 1e-12) << x << "," << y;
        } else {
          EXPECT_EQ(radial[i], -1.0);  // outside the receivers: not written
        }
      }
    }
  }
}

// A kernel built once serves frames of its pixel size and no others (the benchmark shares one per
// footprint); stride picks the reference grid of sss_bench.
TEST(RadialPlaneReference, SharedKernelAndStride) {
  const BurleyProfile p(cases()[0]);
  std::vector<float> e(static_cast<std::size_t>(16 * 12 * 4), 1.0f);
  e[static_cast<std::size_t>((5 * 16 + 7) * 4)] = 9.0f;
  const sss::math::PlaneInput in{16, 12, e.data(), 0.1, 0.1};
  std::vector<double> once(16 * 12 * 3, -1.0), shared(once.size(), -1.0);
  sss::math::convolve_plane_radial(in, p, {0, 0, 16, 12}, once.data(), 1, 3);
  const sss::math::RadialPixelKernel k(p, 0.1, 0.1, 20, 12);
  sss::math::convolve_plane_radial(in, k, {0, 0, 16, 12}, shared.data(), 2, 3);
  EXPECT_EQ(once, shared);
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 16; ++x) EXPECT_EQ(once[static_cast<std::size_t>((y * 16 + x) * 3)] >= 0.0, x % 3 == 1 && y % 3 == 1);
  }
  const sss::math::RadialPixelKernel other(p, 0.1, 0.2, 20, 12), small(p, 0.1, 0.1, 15, 12);
  EXPECT_THROW(sss::math::convolve_plane_radial(in, other, {0, 0, 16, 12}, shared.data()), std::invalid_argument);
  EXPECT_THROW(sss::math::convolve_plane_radial(in, small, {0, 0, 16, 12}, shared.data()), std::invalid_argument);
  EXPECT_THROW(sss::math::convolve_plane_radial(in, k, {0, 0, 17, 12}, shared.data()), std::invalid_argument);
}

// A uniformly lit plane: the centre receives A less what the frame loses past its edge, which the
// closed-form CDF bounds (the frame square lies between its inscribed and circumscribed disks).
TEST(RadialPlaneReference, BurleyConservesEnergyOnAUniformPlane) {
  const int n = 41;
  const double pixel = 0.2;
  std::vector<float> e(static_cast<std::size_t>(n * n * 4), 1.0f);
  for (const BurleyParameters& b : cases()) {
    const BurleyProfile p(b);
    const sss::math::PlaneInput in{n, n, e.data(), pixel, pixel};
    std::vector<double> out(static_cast<std::size_t>(n * n * 3));
    sss::math::convolve_plane_radial(in, p, {n / 2, n / 2, 1, 1}, out.data(), 2);
    const double half = 0.5 * n * pixel;
    const Rgb inner = p.encircled(half), outer = p.encircled(std::sqrt(2.0) * half);
    const Rgb square = sss::math::rectangle_integral(p, -half, half, -half, half);
    for (std::size_t c = 0; c < 3; ++c) {
      const double m = out[static_cast<std::size_t>((n / 2 * n + n / 2) * 3) + c];
      EXPECT_NEAR(m, square[c], 1e-12);  // the cells add up to the frame's rectangle
      EXPECT_GE(m, inner[c] - 1e-13);
      EXPECT_LE(m, outer[c] + 1e-13);
    }
  }
}

// The kernel families' grid integrates Burley's cells exactly: Gauss–Legendre sampling of the 1/r
// (what discretise_profile did before) misses the marble centre cell by 11 %.
TEST(Burley, ProfileGridCellsAreExactAtTheCentre) {
  const BurleyProfile p(cases()[1]);
  const auto grid = sss::math::make_tap_grid(17, 4.0, sss::math::TapSpacing::quadratic);
  const auto m = sss::math::discretise_profile(p, grid);
  const int mid = 8;
  for (int c = 0; c < 3; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const auto e = [&](int k) { return grid.edges_mm[static_cast<std::size_t>(k)]; };
    const double centre = duffy_rectangle(p, c, e(mid), e(mid + 1), e(mid), e(mid + 1));
    const double side = duffy_rectangle(p, c, e(mid + 1), e(mid + 2), e(mid), e(mid + 1));
    EXPECT_NEAR(m.at(c, mid, mid) * m.totals[cc], centre, 1e-10 * centre);
    EXPECT_NEAR(m.at(c, mid + 1, mid) * m.totals[cc], side, 1e-10 * side);
    // The grid's square holds the energy between the CDF at its half-width and at its corner.
    EXPECT_GE(m.totals[cc], p.encircled(4.0)[cc]);
    EXPECT_LE(m.totals[cc], p.encircled(4.0 * std::sqrt(2.0))[cc]);
  }
}

TEST(Burley, MakeProfileBuildsItFromARequest) {
  sss::math::ProfileRequest r;
  r.material = sss::math::kProfileBurley;
  r.burley = cases()[2];
  const auto p = sss::math::make_profile(r);
  EXPECT_TRUE(p->singular_at_centre());
  EXPECT_EQ(p->integral()[1], 0.9);
  sss::math::ProfileRequest other = r;
  EXPECT_TRUE(sss::math::same_profile_request(r, other));
  other.burley.dmfp_mm[2] = 1.5;
  EXPECT_FALSE(sss::math::same_profile_request(r, other));
  EXPECT_NE(p->identity(), sss::math::make_profile(other)->identity());
}

}  // namespace
