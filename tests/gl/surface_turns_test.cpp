// The passes on surfaces turned away from the camera (module/src/math/pass_surface.hpp): on the GL,
// every path and mode (the cross-bilateral one too) against the CPU model and against the exact 2D
// reference on a turned plane; a slope that follow-surface leaves alone; a step it still stops.
//
// The plane: orthographic, 108x108 pixels of 0.25 mm facing the camera, turned 60 degrees about an
// axis 30 degrees off screen x (so the vertical pass is sheared), a shadow edge along the axis and a
// per-pixel albedo. Before the passes walked the surface (one step from the centre's depth on both
// axes, follow-surface by the raw depth difference) the sum of Gaussians left 0.33 of the needed
// change undone there and the default 0.24 (the CPU model, tests/unit/surface_turns_test.cpp); the
// bounds below are 0.08 and 0.18.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "filter_case.hpp"
#include "kernel_of.hpp"
#include "math/exact_reference.hpp"
#include "metrics.hpp"
#include "regions.hpp"

namespace sss_test {
namespace {

constexpr int kSide = 108;
constexpr double kPixelMm = 0.25;
constexpr float kTolerance = 3e-3f;  // GL against the CPU model: matches_cpu_model_test.cpp says why

sss::math::Matrix4 plane_camera() {
  const float half = static_cast<float>(0.5 * kSide * kPixelMm * 1e-3);
  return orthographic_matrix(half, half, 0.01f, 10.0f);
}

// Physical skin in metres, 17 taps, follow-surface on, the path asked for.
sss_settings skin(uint32_t path) {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.001f;
  s.path = path;
  return s;
}

sss_settings sum_of_gaussians(uint32_t path) {
  sss_settings s = skin(path);
  kernel_of(s).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
  kernel_of(s).rank = 6;
  return s;
}

class SurfaceTurns : public FilterCaseTest {
 protected:
  void SetUp() override {
    FilterCaseTest::SetUp();
    plane_ = make_turned_plane_scene(kSide, kSide, 60.0, 30.0, 0.5, plane_camera(), 11, &plane_distance_);
  }

  // The interior miss (pixels beyond the profile's reach from the frame's edge) of `result` against
  // the exact 2D reference of the plane, computed once.
  sss_bench::Miss miss(const std::vector<float>& result, const std::vector<float>& input) {
    const double reach_mm = sss_bench::profile_reach_mm(sss::math::skin_profile_terms());
    const int border = static_cast<int>(std::ceil(reach_mm / kPixelMm)) + 1;
    const sss::math::PixelRegion interior{border, border, kSide - 2 * border, kSide - 2 * border};
    if (reference_.empty()) {
      sss::math::ExactInput in;
      in.width = kSide;
      in.height = kSide;
      in.irradiance = input.data();
      in.distance_f64 = plane_distance_.data();
      in.projection = plane_.projection;
      in.world_units_per_mm = 0.001;
      reference_.assign(static_cast<std::size_t>(kSide) * kSide * 3, 0.0);
      sss::math::exact_surface_convolution(in, sss::math::skin_profile_terms(), interior, reference_.data());
    }
    std::vector<uint8_t> mask(static_cast<std::size_t>(kSide) * kSide, 0);
    for (int y = interior.y; y < interior.y + interior.height; ++y) {
      for (int x = interior.x; x < interior.x + interior.width; ++x) mask[static_cast<std::size_t>(y) * kSide + x] = 1;
    }
    return sss_bench::miss_share(sss_bench::RgbImage::from_rgba(result.data(), kSide, kSide),
                                 sss_bench::RgbImage::from_rgb(reference_.data(), kSide, kSide),
                                 sss_bench::RgbImage::from_rgba(input.data(), kSide, kSide), mask.data());
  }

  SyntheticScene plane_;
  std::vector<double> plane_distance_;
  std::vector<double> reference_;
};

void print_miss(const char* what, const sss_bench::Miss& m) {
  std::printf("%s: interior miss %.3f (r %.3f, g %.3f, b %.3f)\n", what, m.pooled, m.channel[0], m.channel[1],
              m.channel[2]);
}

TEST_F(SurfaceTurns, ATurnedPlaneMatchesTheCpuModelOnEveryPath) {
  for (const PathCase& p : kEveryPath) {
    SCOPED_TRACE(p.name);
    FilterCase c;
    c.settings = path_case_settings(skin(SSS_PATH_FRAGMENT), p.path, p.mode, p.two_terms);
    c.half_color = true;
    const FilterOutcome o = run_case(plane_, c);
    ASSERT_EQ(o.result, SSS_OK);
    const float difference = largest_relative_difference(o.gpu, o.cpu);
    std::printf("%s: GPU vs CPU model %.3g\n", p.name, difference);
    EXPECT_LE(difference, kTolerance);
    EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f) << "it blurred";
    TearDown();
    SetUp();
  }
}

TEST_F(SurfaceTurns, ATurnedPlaneIsNearlyExactOnTheGl) {
  FilterCase c;
  c.half_color = true;
  c.settings = sum_of_gaussians(SSS_PATH_FRAGMENT);
  const FilterOutcome sog = run_case(plane_, c);
  ASSERT_EQ(sog.result, SSS_OK);
  c.settings = skin(SSS_PATH_FRAGMENT);
  const FilterOutcome standard = run_case(plane_, c);
  ASSERT_EQ(standard.result, SSS_OK);
  const sss_bench::Miss m_sog = miss(sog.gpu, sog.input), m_default = miss(standard.gpu, standard.input);
  print_miss("sum of Gaussians", m_sog);
  print_miss("default", m_default);
  EXPECT_LE(m_sog.pooled, 0.08);
  EXPECT_LE(m_default.pooled, 0.18);
  for (std::size_t ch = 0; ch < 3; ++ch) {
    EXPECT_LT(m_sog.channel[ch], 1.0) << "channel " << ch << " worse than doing nothing";
    EXPECT_LT(m_default.channel[ch], 1.0) << "channel " << ch << " worse than doing nothing";
  }
}

TEST_F(SurfaceTurns, ASlopeIsNotFaded) {
  // Follow-surface on and off give the same image bit for bit on the plane: every tap lies on its
  // surface (within the ramp's slack). Before, the raw depth difference of the 60-degree slope faded
  // the taps (up to 1.7 mm of depth per millimetre across), which changed most pixels.
  FilterCase c;
  c.half_color = true;
  c.settings = skin(SSS_PATH_FRAGMENT);
  const FilterOutcome followed = run_case(plane_, c);
  c.settings.flags &= ~static_cast<uint32_t>(SSS_FOLLOW_SURFACE);
  const FilterOutcome plain = run_case(plane_, c);
  ASSERT_EQ(followed.result, SSS_OK);
  ASSERT_EQ(plain.result, SSS_OK);
  EXPECT_GT(largest_relative_difference(followed.gpu, followed.input), 0.02f) << "it blurred";
  EXPECT_EQ(0, std::memcmp(followed.gpu.data(), plain.gpu.data(), followed.gpu.size() * sizeof(float)));
}

TEST_F(SurfaceTurns, AStepStillStopsTheLight) {
  // The turned plane's upper half moved 10 mm towards the camera, 5 mm off the lower half's plane
  // (the view direction is 60 degrees from the normal): a step a little past the default kernel's
  // reach (4.7 mm) across a surface whose depth changes by 1.7 mm per millimetre. The lit side of
  // the edge lies in the lower half; the light that reaches the upper half's dark pixels next to
  // the step with follow-surface must be a small part of what reaches them without.
  SyntheticScene s = plane_;
  const double lift_z = 10e-3;
  for (int y = kSide / 2; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kSide + x;
      s.distance[i] -= static_cast<float>(lift_z);
      for (int ch = 0; ch < 3; ++ch) s.color[i * 4 + static_cast<std::size_t>(ch)] = 0.02f;  // dark above the step
    }
  }
  compute_window_depth(&s);
  FilterCase c;
  c.settings = skin(SSS_PATH_FRAGMENT);
  const FilterOutcome followed = run_case(s, c);
  c.settings.flags &= ~static_cast<uint32_t>(SSS_FOLLOW_SURFACE);
  const FilterOutcome plain = run_case(s, c);
  ASSERT_EQ(followed.result, SSS_OK);
  ASSERT_EQ(plain.result, SSS_OK);
  double leaked = 0.0, unstopped = 0.0;  // red light gained by the dark rows just above the step
  for (int y = kSide / 2; y < kSide / 2 + 4; ++y) {
    for (int x = kSide / 4; x < 3 * kSide / 4; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * kSide + x) * 4;
      leaked += followed.gpu[i] - followed.input[i];
      unstopped += plain.gpu[i] - plain.input[i];
    }
  }
  std::printf("light gained above the step: %.4g with follow-surface, %.4g without\n", leaked, unstopped);
  EXPECT_GT(unstopped, 1.0) << "without follow-surface the light crosses the step";
  EXPECT_LT(leaked, 0.1 * unstopped);
  EXPECT_LE(largest_relative_difference(followed.gpu, followed.cpu), kTolerance);
}

}  // namespace
}  // namespace sss_test
