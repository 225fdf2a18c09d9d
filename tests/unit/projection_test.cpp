// Depth linearisation and projection checks (math layer).
#include <gtest/gtest.h>

#include <cmath>

#include "math/filter_constants.hpp"
#include "math/projection.hpp"
#include "synthetic_scene.hpp"

namespace {

using sss::math::Matrix4;

Matrix4 perspective(float fovy_deg, float aspect, float near, float far) {
  return sss_test::perspective_matrix(fovy_deg, aspect, near, far);
}

Matrix4 infinite_perspective(float fovy_deg, float aspect, float near) {
  Matrix4 m = perspective(fovy_deg, aspect, near, 1.0f);
  m[10] = -1.0f;
  m[14] = -2.0f * near;
  return m;
}

// Reversed-Z for a [-1, 1] clip range: near maps to +1, far to -1.
Matrix4 reversed_perspective(float fovy_deg, float aspect, float near, float far) {
  Matrix4 m = perspective(fovy_deg, aspect, near, far);
  m[10] = -m[10];
  m[14] = -m[14];
  return m;
}

Matrix4 orthographic(float half_width, float half_height, float near, float far) {
  return sss_test::orthographic_matrix(half_width, half_height, near, far);
}

double ndc_z(const Matrix4& m, double distance) {
  const double z = -distance;
  return (m[10] * z + m[14]) / (m[11] * z + m[15]);
}

void expect_round_trip(const Matrix4& m, double near, double far) {
  ASSERT_EQ(sss::math::check_projection(m, nullptr), sss::math::ProjectionCheck::ok);
  for (double t = 0.0; t <= 1.0; t += 0.125) {
    const double d = near + (far - near) * t;
    EXPECT_NEAR(sss::math::distance_from_ndc_z(m, ndc_z(m, d)), d, 2e-5 * d) << "distance " << d;
  }
}

TEST(Projection, LinearisesPerspectiveOrthographicInfiniteAndReversedDepth) {
  expect_round_trip(perspective(45.0f, 1.5f, 0.1f, 100.0f), 0.1, 100.0);
  expect_round_trip(infinite_perspective(60.0f, 1.0f, 0.05f), 0.05, 50.0);
  expect_round_trip(reversed_perspective(30.0f, 1.0f, 0.1f, 10.0f), 0.1, 10.0);
  expect_round_trip(orthographic(2.0f, 1.0f, 0.5f, 20.0f), 0.5, 20.0);
}

TEST(Projection, ClipWIsTheDistanceForPerspectiveAndOneForOrthographic) {
  EXPECT_NEAR(sss::math::clip_w_from_distance(perspective(45, 1, 0.1f, 10), 3.0), 3.0, 1e-6);
  EXPECT_NEAR(sss::math::clip_w_from_distance(orthographic(1, 1, 0.1f, 10), 3.0), 1.0, 1e-6);
}

TEST(Projection, RejectsSingularAndNonFiniteMatrices) {
  Matrix4 zero{};
  std::string why;
  EXPECT_EQ(sss::math::check_projection(zero, &why), sss::math::ProjectionCheck::invalid);
  EXPECT_NE(why.find("singular"), std::string::npos);
  Matrix4 flat_depth = perspective(45, 1, 0.1f, 10);
  flat_depth[14] = 0.0f;  // z_ndc constant: depth cannot be inverted
  EXPECT_EQ(sss::math::check_projection(flat_depth, &why), sss::math::ProjectionCheck::invalid);
  Matrix4 nan = perspective(45, 1, 0.1f, 10);
  nan[5] = NAN;
  EXPECT_EQ(sss::math::check_projection(nan, &why), sss::math::ProjectionCheck::invalid);
  EXPECT_NE(why.find("projection[5]"), std::string::npos);
  Matrix4 sheared = perspective(45, 1, 0.1f, 10);
  sheared[4] = 0.2f;
  EXPECT_EQ(sss::math::check_projection(sheared, &why), sss::math::ProjectionCheck::unsupported);
}

TEST(FilterConstants, HorizontalScaleIsAspectCorrect) {
  sss::math::FilterSettings s;
  s.world_units_per_mm = 0.02f;
  sss::math::FrameGeometry g;
  g.texture_width = 200;
  g.texture_height = 100;
  g.viewport = {0, 0, 200, 100};
  const auto k = sss::math::compute_pass_constants(s, perspective(40.0f, 2.0f, 0.1f, 10.0f), g);
  // One world unit spans the same number of pixels across and down for square pixels.
  EXPECT_NEAR(k.pixels_per_mm[0], k.pixels_per_mm[1], 1e-4f * k.pixels_per_mm[1]);
  // One millimetre is world_units_per_mm · scale world units.
  const float f = 1.0f / std::tan(20.0f * 3.14159265f / 180.0f);
  EXPECT_NEAR(k.pixels_per_mm[1], f * 0.5f * 100.0f * 0.02f, 1e-4f);
  // Follow-surface reach: eq. (1)'s 2 kernel mm for 17 taps, over separable_scale kernel mm per
  // millimetre, in world units (0.02 per mm).
  EXPECT_NEAR(k.follow_surface_factor, 1.0f / (2.0f / s.separable_scale * 0.02f), 1e-3f);
}

TEST(FilterConstants, LinearisationInFloatMatchesDouble) {
  const Matrix4 m = perspective(45.0f, 1.0f, 0.1f, 100.0f);
  sss::math::FilterSettings s;
  sss::math::FrameGeometry g;
  g.viewport = {0, 0, 4, 4};
  const auto k = sss::math::compute_pass_constants(s, m, g);
  for (double d : {0.2, 1.0, 7.5, 60.0}) {
    const double window = (ndc_z(m, d) + 1.0) / 2.0;
    EXPECT_NEAR(sss::math::linearise_depth(k, static_cast<float>(window)), d, 2e-3 * d * d);
  }
}

}  // namespace
