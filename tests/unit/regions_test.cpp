// Where the benchmark measures errors (tests/bench/regions.hpp): the profile's reach, and the
// border / silhouette / interior split on frames whose answer is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "math/exact_reference.hpp"
#include "math/plane_reference.hpp"
#include "regions.hpp"
#include "synthetic_scene.hpp"

namespace {

using sss_bench::Region;

// The tail share of one term is exp(-r²/2v) times its weight; of a profile, the largest channel's sum.
TEST(Regions, TailShareOfTheProfile) {
  const sss::math::GaussianProfile one = {{2.0, {0.5, 0.25, 1.0}}};
  EXPECT_DOUBLE_EQ(sss_bench::profile_tail_share(one, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(sss_bench::profile_tail_share(one, 3.0), std::exp(-9.0 / 4.0));
  const sss::math::GaussianProfile two = {{1.0, {0.5, 0.0, 0.0}}, {4.0, {0.5, 0.0, 0.0}}};
  EXPECT_DOUBLE_EQ(sss_bench::profile_tail_share(two, 2.0), 0.5 * std::exp(-2.0) + 0.5 * std::exp(-0.5));
}

// The reach leaves exactly the tail share beyond it in the widest channel, and more just inside.
TEST(Regions, ReachLeavesTheTailShareBeyondIt) {
  const auto profile = sss::math::skin_profile_terms();
  const double reach = sss_bench::profile_reach_mm(profile);
  EXPECT_LE(sss_bench::profile_tail_share(profile, reach), sss_bench::kReachTail);
  EXPECT_GT(sss_bench::profile_tail_share(profile, reach - 1e-6), sss_bench::kReachTail);
  // Red's widest term (7.41 mm², weight 0.078) alone puts it near sqrt(2 v ln(w / tail)) = 8.0 mm.
  EXPECT_NEAR(reach, std::sqrt(2.0 * 7.41 * std::log(0.078 / 1e-3)), 0.05);
  EXPECT_THROW(sss_bench::profile_reach_mm(profile, 0.0), std::invalid_argument);
  EXPECT_THROW(sss_bench::profile_reach_mm(profile, 1.0), std::invalid_argument);
}

struct Frame {
  int width = 60, height = 40;
  std::vector<uint8_t> mask;
  std::vector<float> distance;
  std::array<float, 16> projection{};
  double pixel_mm = 0.0;

  Frame() {
    mask.assign(static_cast<std::size_t>(width) * height, 1);
    distance.assign(mask.size(), 0.5f);  // metres
    const sss::math::Matrix4 m = sss_test::perspective_matrix(30.0f, static_cast<float>(width) / static_cast<float>(height), 0.1f, 10.0f);
    std::copy(m.begin(), m.end(), projection.begin());
    pixel_mm = sss::math::plane_pixel_mm_y(m, height, 0.5, 0.001);
  }
  sss_bench::RegionInput input(double reach_px) const {
    sss_bench::RegionInput in;
    in.width = width;
    in.height = height;
    in.mask = mask.data();
    in.distance = distance.data();
    in.projection = projection;
    in.world_units_per_mm = 0.001;
    in.reach_mm = reach_px * pixel_mm;
    return in;
  }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

// A plane filling the frame: border exactly where a centre is nearer the frame edge than the reach
// (the edge half a pixel beyond the outermost centres), interior everywhere else, no silhouette.
TEST(Regions, ThePlaneFillingTheFrameHasABorderAndAnInterior) {
  const Frame f;
  const auto regions = sss_bench::classify_regions(f.input(4.25));
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x) {
      const double to_edge = std::min({x + 0.5, f.width - x - 0.5, y + 0.5, f.height - y - 0.5});
      EXPECT_EQ(regions[f.at(x, y)], static_cast<uint8_t>(to_edge < 4.25 ? Region::border : Region::interior)) << x << "," << y;
    }
  }
  EXPECT_NEAR(sss_bench::median_footprint_mm(f.input(1.0)), f.pixel_mm, 1e-6 * f.pixel_mm);  // x and y differ by float rounding
}

// A hole (non-translucent) and a depth step inside the frame: silhouette within the reach of
// either (Euclidean, between centres), interior beyond; non-translucent pixels are in no region.
TEST(Regions, SilhouettesAreHolesAndDepthSteps) {
  Frame f;
  f.mask[f.at(20, 20)] = 0;  // a one-pixel hole
  // Columns x >= 45 lie 10 cm behind: a depth step along x = 44.5, far beyond four pixel widths.
  for (int y = 0; y < f.height; ++y) {
    for (int x = 45; x < f.width; ++x) f.distance[f.at(x, y)] = 0.6f;
  }
  const double reach = 3.5;
  const auto regions = sss_bench::classify_regions(f.input(reach));
  EXPECT_EQ(regions[f.at(20, 20)], static_cast<uint8_t>(Region::none));
  EXPECT_EQ(regions[f.at(23, 20)], static_cast<uint8_t>(Region::silhouette));  // 3 px from the hole
  EXPECT_EQ(regions[f.at(22, 22)], static_cast<uint8_t>(Region::silhouette));  // 2.83 px
  EXPECT_EQ(regions[f.at(23, 22)], static_cast<uint8_t>(Region::interior));    // 3.61 px > 3.5
  EXPECT_EQ(regions[f.at(24, 20)], static_cast<uint8_t>(Region::interior));    // 4 px
  // Both sides of the step are silhouette pixels (each is next to the other), so the reach counts
  // from x = 44 on the near side and x = 45 on the far side.
  EXPECT_EQ(regions[f.at(41, 20)], static_cast<uint8_t>(Region::silhouette));  // 3 px from 44
  EXPECT_EQ(regions[f.at(40, 20)], static_cast<uint8_t>(Region::interior));    // 4 px
  // Far side: at 0.6 m each pixel covers more millimetres, so the same reach is fewer pixels
  // (3.5 · 0.5 / 0.6 = 2.92): 47 is 2 px from 45, 48 is 3 px.
  EXPECT_EQ(regions[f.at(47, 20)], static_cast<uint8_t>(Region::silhouette));
  EXPECT_EQ(regions[f.at(48, 20)], static_cast<uint8_t>(Region::interior));
  // A slope is no step: the plane turned 45 degrees about the vertical axis meets the view rays at
  // 45 ± 22 degrees (the horizontal half field of view), so its depth changes by at most
  // tan 67° = 2.4 pixel widths per pixel, under the four of a step. Along the ray through a pixel
  // (x_ndc), X = x_ndc d / m0 and the plane is d = 0.5 + X tan θ, so d = 0.5 / (1 - x_ndc tan θ / m0).
  // (Turned 60 degrees, its receding side meets the rays at 82 degrees: silhouette, rightly.)
  Frame sloped;
  const double tan_theta = std::tan(45.0 * 3.14159265358979323846 / 180.0);
  for (int y = 0; y < sloped.height; ++y) {
    for (int x = 0; x < sloped.width; ++x) {
      const double x_ndc = 2.0 * (x + 0.5) / sloped.width - 1.0;
      sloped.distance[sloped.at(x, y)] = static_cast<float>(0.5 / (1.0 - x_ndc * tan_theta / sloped.projection[0]));
    }
  }
  const auto smooth = sss_bench::classify_regions(sloped.input(2.0));
  EXPECT_EQ(std::count(smooth.begin(), smooth.end(), static_cast<uint8_t>(Region::silhouette)), 0);
  for (int y = 0; y < sloped.height; ++y) {
    for (int x = 0; x < sloped.width; ++x) {
      const double x_ndc = 2.0 * (x + 0.5) / sloped.width - 1.0;
      sloped.distance[sloped.at(x, y)] = static_cast<float>(0.5 / (1.0 - x_ndc * std::sqrt(3.0) / sloped.projection[0]));
    }
  }
  const auto grazing = sss_bench::classify_regions(sloped.input(2.0));
  EXPECT_GT(std::count(grazing.begin(), grazing.end(), static_cast<uint8_t>(Region::silhouette)), 0);
  // Only on the receding side (x_ndc > 0), where the rays graze the plane.
  for (int y = 0; y < sloped.height; ++y) EXPECT_NE(grazing[sloped.at(10, y)], static_cast<uint8_t>(Region::silhouette));
  EXPECT_THROW(sss_bench::classify_regions(f.input(0.0)), std::invalid_argument);
}

}  // namespace
