// bench.whole_surface: the whole-surface reference (whole_surface.hpp) validated on an irregular
// triangle mesh of a plane, where the answer is known in closed form:
//   - uniform light: every receiver gets its light back (mass 1), exact and analytic terms alike;
//   - a straight light edge with a linear ramp of 1 mm: each term's 1D Gaussian of the ramp, in
//     closed form, where the analytic term (the narrowest, as on the head) sees flat (here linear) light;
//   - halving the sample spacing moves no receiver by more than 2e-3 of the lit level.
// The head's own checks (convergence on the scan) are in sss_whole_surface --check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "whole_surface.hpp"

namespace {

using sss_bench::Point3;

constexpr double kHalfSizeMm = 30.0;   // the plane spans [-30, 30] mm in x and y: 12 mm beyond the reach
constexpr double kGridMm = 2.5;        // its vertices: a grid this far apart, each moved up to ±0.8 mm
constexpr double kLit = 1.0, kDark = 0.02, kRampMm = 1.0;

struct PlaneMesh {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  sss_bench::SurfaceMesh mesh() const {
    sss_bench::SurfaceMesh m;
    m.vertices = vertices.data();
    m.indices = indices.data();
    m.index_count = indices.size();
    return m;
  }
};

// The plane z = 0 in metres, an irregular mesh: jittered vertices, each cell's diagonal at random.
PlaneMesh irregular_plane() {
  PlaneMesh p;
  std::mt19937 random(49);
  std::uniform_real_distribution<double> jitter(-0.8, 0.8);
  const int n = static_cast<int>(2 * kHalfSizeMm / kGridMm) + 1;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool inside = i > 0 && j > 0 && i < n - 1 && j < n - 1;
      const double x = -kHalfSizeMm + i * kGridMm + (inside ? jitter(random) : 0.0);
      const double y = -kHalfSizeMm + j * kGridMm + (inside ? jitter(random) : 0.0);
      p.vertices.insert(p.vertices.end(), {static_cast<float>(x * 1e-3), static_cast<float>(y * 1e-3), 0.0f});
    }
  }
  std::bernoulli_distribution flip(0.5);
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = [n](int a, int b) { return static_cast<std::uint32_t>(b * n + a); };
      if (flip(random)) {
        p.indices.insert(p.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        p.indices.insert(p.indices.end(), {v(i, j), v(i + 1, j), v(i, j + 1), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  }
  return p;
}

// The ramp's light at x (mm): lit left of -0.5 mm, dark right of +0.5 mm, linear between.
double ramp_light(double x_mm) {
  const double s = std::fmin(1.0, std::fmax(0.0, 0.5 - x_mm / kRampMm));
  return kDark + (kLit - kDark) * s;
}

// The ramp seen through a 1D Gaussian of standard deviation sigma (mm) at x: with
// G(z) = z Φ(z) + φ(z) (the integral of Φ up to z), lit share (σ / w) [G((w/2 - x)/σ) - G((-w/2 - x)/σ)].
double ramp_through_gaussian(double x_mm, double sigma_mm) {
  const auto phi = [](double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * 3.14159265358979323846); };
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  const auto g = [&](double z) { return z * cdf(z) + phi(z); };
  const double w = kRampMm;
  const double lit_share = sigma_mm / w * (g((0.5 * w - x_mm) / sigma_mm) - g((-0.5 * w - x_mm) / sigma_mm));
  return kDark + (kLit - kDark) * lit_share;
}

enum class Light { uniform, ramp };

sss_bench::WholeSurfaceReference build(const PlaneMesh& plane, const sss::math::GaussianProfile& profile, int analytic_terms,
                                       double spacing_per_sigma, Light light) {
  sss_bench::WholeSurfaceSettings settings;
  settings.profile = profile;
  settings.analytic_terms = analytic_terms;
  settings.spacing_per_sigma = spacing_per_sigma;
  sss_bench::WholeSurfaceReference reference(settings);
  const sss_bench::SurfaceMesh mesh = plane.mesh();
  for (std::size_t t = 0; t < reference.term_count(); ++t) {
    if (reference.analytic(t)) continue;
    sss_bench::TermSamples s =
        sss_bench::term_samples(mesh, sss_bench::sample_surface(mesh, reference.term_spacing(t), nullptr));
    for (const Point3& p : s.position) {
      const float e = static_cast<float>(light == Light::uniform ? 1.0 : ramp_light(p[0] * 1e3));
      s.light.exact.push_back({e, e, e});
      s.light.pixels.push_back({e, e, e});
      s.light.visible.push_back(1);
    }
    reference.set_samples(t, std::move(s));
  }
  return reference;
}

sss_bench::Receiver receiver_at(double x_mm, double y_mm, Light light) {
  sss_bench::Receiver r;
  r.position = {x_mm * 1e-3, y_mm * 1e-3, 0.0};
  const float e = static_cast<float>(light == Light::uniform ? 1.0 : ramp_light(x_mm));
  r.light = {e, e, e};
  return r;
}

const Point3 kUp = {0.0, 0.0, 1.0};

// The four terms of d'Eon's skin wider than a pixel, all integrated on samples.
sss::math::GaussianProfile wide_terms() {
  sss::math::GaussianProfile all = sss::math::skin_profile_terms();
  return sss::math::GaussianProfile(all.begin() + 2, all.end());
}

TEST(WholeSurface, UniformLightComesBackWhole) {
  const PlaneMesh plane = irregular_plane();
  const sss_bench::WholeSurfaceReference reference = build(plane, sss::math::skin_profile_terms(), 1, 0.4, Light::uniform);
  double worst = 0.0;
  for (double y = -4.0; y <= 4.0; y += 0.37) {
    for (double x = -4.0; x <= 4.0; x += 0.41) {
      const sss_bench::WholeSurfaceValue v = reference.at(receiver_at(x, y, Light::uniform), kUp);
      for (int c = 0; c < 3; ++c) {
        worst = std::fmax(worst, std::fabs(v.exact[static_cast<std::size_t>(c)] - 1.0));
        worst = std::fmax(worst, std::fabs(v.mass[static_cast<std::size_t>(c)] - 1.0));
      }
      EXPECT_EQ(v.opposite_share, 0.0);
    }
  }
  // The centroid rule on a lattice 0.4 of a term's width apart is accurate far beyond this; the
  // cutoff at 4.5 widths drops exp(-4.5²/2) = 4e-5 of each term.
  std::printf("uniform light: worst |M - 1| %.2e\n", worst);
  EXPECT_LT(worst, 1e-3) << "uniform light on the irregular plane";
}

TEST(WholeSurface, RampEdgeGivesEachTermsGaussianOfTheRamp) {
  const PlaneMesh plane = irregular_plane();
  for (const bool with_analytic : {false, true}) {
    const sss::math::GaussianProfile profile = with_analytic ? sss::math::skin_profile_terms() : wide_terms();
    const sss_bench::WholeSurfaceReference reference = build(plane, profile, with_analytic ? 1 : 0, 0.4, Light::ramp);
    double worst = 0.0;
    for (double x = -6.0; x <= 6.0; x += 0.125) {
      // The analytic term takes the light as flat: exact where it is linear, i.e. more than four of
      // its widths (4 x 0.08 mm) from the ramp's two kinks.
      if (with_analytic && std::fabs(std::fabs(x) - 0.5 * kRampMm) < 0.33) continue;
      for (double y : {-1.3, 0.0, 2.1}) {
        const sss_bench::WholeSurfaceValue v = reference.at(receiver_at(x, y, Light::ramp), kUp);
        for (std::size_t c = 0; c < 3; ++c) {
          double expected = 0.0;
          for (const auto& t : profile) expected += t.weight[c] * ramp_through_gaussian(x, std::sqrt(t.variance_mm2));
          worst = std::fmax(worst, std::fabs(v.exact[c] - expected));
        }
      }
    }
    // The light changes within a sub-triangle (0.09 mm for the narrowest sampled term) and the
    // centroid takes its value there: a midpoint rule, second order in the spacing over the ramp.
    std::printf("ramp edge, %s: worst error %.2e\n", with_analytic ? "the narrowest term analytic" : "all sampled", worst);
    EXPECT_LT(worst, 1e-3) << (with_analytic ? "the six terms, one analytic" : "the four wide terms, all sampled");
  }
}

TEST(WholeSurface, HalvingTheSpacingMovesNoReceiverBeyond2e3) {
  const PlaneMesh plane = irregular_plane();
  const sss_bench::WholeSurfaceReference coarse = build(plane, sss::math::skin_profile_terms(), 1, 0.4, Light::ramp);
  const sss_bench::WholeSurfaceReference fine = build(plane, sss::math::skin_profile_terms(), 1, 0.2, Light::ramp);
  double worst = 0.0;
  for (double x = -5.0; x <= 5.0; x += 0.09) {
    const sss_bench::WholeSurfaceValue a = coarse.at(receiver_at(x, 0.3, Light::ramp), kUp);
    const sss_bench::WholeSurfaceValue b = fine.at(receiver_at(x, 0.3, Light::ramp), kUp);
    for (std::size_t c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(a.exact[c] - b.exact[c]) / kLit);
  }
  std::printf("halved spacing: worst change %.2e\n", worst);
  EXPECT_LT(worst, 2e-3);
}

TEST(WholeSurface, SurfaceFacingAwayCountsAsOpposite) {
  // Two parallel planes 2 mm apart facing each other (a slit): a receiver on one sees the other
  // through the air, which the convention counts and opposite_share reports.
  PlaneMesh plane = irregular_plane();
  const std::size_t vertices = plane.vertices.size() / 3;
  const std::size_t indices = plane.indices.size();
  for (std::size_t v = 0; v < vertices; ++v) {
    plane.vertices.insert(plane.vertices.end(), {plane.vertices[v * 3], plane.vertices[v * 3 + 1], 0.002f});
  }
  for (std::size_t i = 0; i < indices; i += 3) {  // reversed winding: facing -z
    plane.indices.insert(plane.indices.end(), {plane.indices[i] + static_cast<std::uint32_t>(vertices),
                                               plane.indices[i + 2] + static_cast<std::uint32_t>(vertices),
                                               plane.indices[i + 1] + static_cast<std::uint32_t>(vertices)});
  }
  const sss_bench::WholeSurfaceReference reference = build(plane, sss::math::skin_profile_terms(), 1, 0.4, Light::uniform);
  const sss_bench::WholeSurfaceValue v = reference.at(receiver_at(0.0, 0.0, Light::uniform), kUp);
  // The other plane at 2 mm holds Σ_t w_t exp(-2²/2v_t) of the mass in red: d'Eon's two widest terms.
  double expected_red = 0.0;
  for (const auto& t : sss::math::skin_profile_terms()) {
    if (t.variance_mm2 > 0.1) expected_red += t.weight[0] * std::exp(-4.0 / (2.0 * t.variance_mm2));
  }
  EXPECT_GT(v.opposite_share, 0.05);
  EXPECT_NEAR(v.mass[0], 1.0 + expected_red, 2e-3);
}

}  // namespace
