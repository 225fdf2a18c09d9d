// The canonical scenes: sizes, finite values, depth consistent with distance and projection, mask
// consistent with alpha, determinism, the geometry each scene promises, and GL hygiene of the head
// scenes. Every test runs in a fresh GL 3.3 core context (the fixture), once per backend.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "analytic_scenes.hpp"
#include "calibration.hpp"
#include "gl_fixture.hpp"
#include "head_asset.hpp"
#include "head_scene.hpp"
#include "math/plane_reference.hpp"
#include "math/projection.hpp"
#include "math/surface.hpp"
#include "regions.hpp"
#include "scenes.hpp"
#include "sss/sss.h"
#include "sweep_geometry.hpp"
#include "turn_sweep.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kWidth = 160, kHeight = 90;
constexpr double kPi = 3.14159265358979323846;

size_t pixel_count(const sss_bench::Scene& s) { return static_cast<size_t>(s.width) * static_cast<size_t>(s.height); }

double translucent_fraction(const sss_bench::Scene& s) {
  size_t n = 0;
  for (uint8_t m : s.mask) n += m != 0 ? 1 : 0;
  return static_cast<double>(n) / static_cast<double>(pixel_count(s));
}

bool bit_identical(const sss_bench::Scene& a, const sss_bench::Scene& b) {
  auto same = [](const std::vector<float>& x, const std::vector<float>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0;
  };
  return a.width == b.width && a.height == b.height && same(a.irradiance, b.irradiance) &&
         same(a.distance, b.distance) && same(a.window_depth, b.window_depth) && a.mask == b.mask &&
         std::memcmp(a.projection.data(), b.projection.data(), sizeof a.projection) == 0;
}

// Everything scene.hpp promises, for any scene; `perspective` false: an orthographic one (the turn
// sweep's), with square pixels all the same.
void check_scene(const sss_bench::Scene& s, const std::string& name, int width, int height, bool perspective = true) {
  SCOPED_TRACE(name);
  EXPECT_EQ(s.name, name);
  ASSERT_EQ(s.width, width);
  ASSERT_EQ(s.height, height);
  const size_t n = pixel_count(s);
  ASSERT_EQ(s.irradiance.size(), n * 4);
  ASSERT_EQ(s.distance.size(), n);
  ASSERT_EQ(s.window_depth.size(), n);
  ASSERT_EQ(s.mask.size(), n);
  EXPECT_EQ(s.world_units_per_mm, 0.001f);

  // A perspective (or orthographic) projection with square pixels.
  EXPECT_EQ(s.projection[11], perspective ? -1.0f : 0.0f);
  EXPECT_EQ(s.projection[15], perspective ? 0.0f : 1.0f);
  EXPECT_NEAR(s.projection[5] / s.projection[0], static_cast<double>(width) / height, 1e-5);
  sss::math::Matrix4 m{};
  std::copy(s.projection.begin(), s.projection.end(), m.begin());
  ASSERT_EQ(sss::math::check_projection(m, nullptr), sss::math::ProjectionCheck::ok);

  int bad_values = 0, bad_mask = 0, bad_depth = 0;
  double worst_round_trip = 0;
  for (size_t p = 0; p < n; ++p) {
    const float* e = &s.irradiance[p * 4];
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(e[c]) || e[c] < 0.0f) ++bad_values;
    if (e[3] != 0.0f && e[3] != 1.0f) ++bad_values;
    if ((e[3] > 0.0f) != (s.mask[p] == 1) || s.mask[p] > 1) ++bad_mask;
    const float d = s.distance[p], w = s.window_depth[p];
    if (!std::isfinite(d) || d <= 0.0f || !std::isfinite(w) || w <= 0.0f || w >= 1.0f) {
      ++bad_depth;
      continue;
    }
    const double back = sss::math::distance_from_ndc_z(m, 2.0 * w - 1.0);
    worst_round_trip = std::max(worst_round_trip, std::fabs(back - d) / d);
  }
  EXPECT_EQ(bad_values, 0) << "non-finite or negative irradiance, or alpha neither 0 nor 1";
  EXPECT_EQ(bad_mask, 0) << "mask differs from alpha > 0";
  EXPECT_EQ(bad_depth, 0) << "distance not finite and positive, or window depth outside (0, 1)";
  EXPECT_LT(worst_round_trip, 1e-4) << "distance and window depth disagree through the projection";
}

// x of the edge (pixels from the left) in each row: for a straight edge the coverages of a row sum
// to the edge's x at the row's centre.
std::vector<double> edge_positions(const sss_bench::Scene& s) {
  std::vector<double> x(static_cast<size_t>(s.height), 0.0);
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const double e = s.irradiance[(static_cast<size_t>(j) * s.width + i) * 4];
      x[static_cast<size_t>(j)] += (e - sss_bench::detail::kDark) / (sss_bench::detail::kLit - sss_bench::detail::kDark);
    }
  return x;
}

class SceneTest : public GlTest {};

TEST_F(SceneTest, NamesAndErrors) {
  const std::vector<std::string> expected = {"dot",       "edge-0",    "edge-30",    "edge-45",  "sphere",
                                             "depth-step", "tilted-30", "tilted-60", "tilted-80", "head-close",
                                             "head-mid",  "head-far",  "head-grazing", "head-mixed", "empty"};
  EXPECT_EQ(sss_bench::canonical_scene_names(), expected);
  for (const std::string& name : expected)
    EXPECT_EQ(sss_bench::scene_needs_gl(name), name.rfind("head-", 0) == 0) << name;
  EXPECT_THROW(sss_bench::make_scene("no-such-scene", kWidth, kHeight), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_scene("", kWidth, kHeight), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_scene("dot", 0, kHeight), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_scene("head-close", kWidth, -1), std::invalid_argument);
}

// head-mixed: three profile/object pairs beside the background, each covering some pixels, the byte
// non-zero exactly where the mask is, each pair's irradiance from its own albedo; no other scene has
// a profile byte.
TEST_F(SceneTest, MixedSceneHoldsThreeMaterials) {
  const sss_bench::Scene s = sss_bench::make_scene("head-mixed", 320, 180);
  ASSERT_EQ(s.profile.size(), s.mask.size());
  EXPECT_EQ(s.profile_materials, (std::vector<int>{SSS_PROFILE_SKIN_DEON, SSS_PROFILE_MARBLE, SSS_PROFILE_CREAM}));
  std::map<int, int> pixels;
  for (std::size_t i = 0; i < s.mask.size(); ++i) {
    EXPECT_EQ(s.profile[i] != 0, s.mask[i] != 0) << "pixel " << i;
    ++pixels[s.profile[i]];
  }
  EXPECT_EQ(pixels.size(), 4u);
  for (int byte : {0, 0 | 1 << 4, 1 | 2 << 4, 2 | 3 << 4}) EXPECT_GT(pixels[byte], 200) << "byte " << byte;
  for (const char* name : {"head-close", "sphere"}) EXPECT_TRUE(sss_bench::make_scene(name, 32, 18).profile.empty()) << name;
}

TEST_F(SceneTest, EveryScenePromisesWhatSceneHppSays) {
  for (const std::string& name : sss_bench::canonical_scene_names()) {
    const sss_bench::Scene a = sss_bench::make_scene(name, kWidth, kHeight);
    check_scene(a, name, kWidth, kHeight);
    const sss_bench::Scene b = sss_bench::make_scene(name, kWidth, kHeight);
    EXPECT_TRUE(bit_identical(a, b)) << name << " is not deterministic";
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The footprint sweep's planes: everything scene.hpp promises, translucent everywhere at one
// distance, each pixel `footprint` millimetres on the plane (as the references derive it from the
// projection), and the light where scenes.hpp puts it, in millimetres at every footprint.
TEST_F(SceneTest, FootprintPlanesMeasureTheirFootprint) {
  const std::vector<std::string> expected = {"plane-edge-0", "plane-edge-20", "plane-edge-45",
                                             "plane-spot",   "plane-disk",    "plane-albedo"};
  EXPECT_EQ(sss_bench::footprint_scene_names(), expected);
  EXPECT_THROW(sss_bench::make_footprint_scene("dot", 0.1, 64, 64), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_footprint_scene("plane-disk", 0.0, 64, 64), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_footprint_scene("plane-disk", 0.1, 0, 64), std::invalid_argument);
  for (double footprint : {0.05, 0.3, 2.0}) {
    for (const std::string& name : expected) {
      const sss_bench::Scene s = sss_bench::make_footprint_scene(name, footprint, 81, 81);
      check_scene(s, name, 81, 81);
      EXPECT_EQ(s.footprint_mm, footprint);
      EXPECT_EQ(translucent_fraction(s), 1.0) << name;
      EXPECT_TRUE(std::all_of(s.distance.begin(), s.distance.end(), [&](float d) { return d == s.distance[0]; })) << name;
      sss::math::Matrix4 m{};
      std::copy(s.projection.begin(), s.projection.end(), m.begin());
      EXPECT_NEAR(sss::math::plane_pixel_mm_x(m, s.width, s.distance[0], s.world_units_per_mm), footprint, 1e-5 * footprint);
      EXPECT_NEAR(sss::math::plane_pixel_mm_y(m, s.height, s.distance[0], s.world_units_per_mm), footprint, 1e-5 * footprint);
    }
    // The disk's and the spot's light above the dark level is their area in pixels (coverage is
    // exact to 0.1 %), at every footprint; at 2 mm per pixel the spot is a fifth of one pixel.
    for (const auto& [name, radius] : {std::pair<const char*, double>{"plane-spot", sss_bench::detail::kSpotRadiusMm},
                                       {"plane-disk", sss_bench::detail::kDiskRadiusMm}}) {
      if (radius / footprint > 35.0) continue;  // it would not fit in the frame
      const sss_bench::Scene s = sss_bench::make_footprint_scene(name, footprint, 81, 81);
      double light = 0.0;
      for (size_t p = 0; p < pixel_count(s); ++p) {
        light += (s.irradiance[p * 4] - sss_bench::detail::kDark) / (sss_bench::detail::kLit - sss_bench::detail::kDark);
      }
      const double area = kPi * radius * radius / (footprint * footprint);
      EXPECT_NEAR(light, area, 2e-3 * area + 1e-4) << name << " at " << footprint;
    }
    // The straight edges: each row's lit share puts the edge through the centre of pixel (40, 40),
    // x = 40.5 at the centre of row 40, at its angle.
    const sss_bench::Scene edge = sss_bench::make_footprint_scene("plane-edge-20", footprint, 81, 81);
    const std::vector<double> x = edge_positions(edge);
    const double slope = std::tan(20.0 * kPi / 180.0);
    for (int j = 10; j < 71; ++j) EXPECT_NEAR(x[static_cast<size_t>(j)], 40.5 + slope * (j - 40), 1e-6) << j;
  }
  // The albedo detail: per pixel, between the low albedo and 1, not repeating.
  const sss_bench::Scene albedo = sss_bench::make_footprint_scene("plane-albedo", 0.5, 64, 64);
  double lo = 2.0, hi = -1.0;
  for (size_t p = 0; p < pixel_count(albedo); ++p) {
    lo = std::min(lo, static_cast<double>(albedo.irradiance[p * 4]));
    hi = std::max(hi, static_cast<double>(albedo.irradiance[p * 4]));
  }
  EXPECT_GE(lo, sss_bench::detail::kAlbedoLow - 1e-6);
  EXPECT_LT(hi, 1.0);
  EXPECT_GT(hi - lo, 0.7);
  EXPECT_NE(albedo.irradiance[0], albedo.irradiance[4]);
}

TEST_F(SceneTest, OddSizes) {
  for (const char* name : {"dot", "edge-45", "sphere", "head-far"}) {
    check_scene(sss_bench::make_scene(name, 1, 1), name, 1, 1);
    check_scene(sss_bench::make_scene(name, 97, 31), name, 97, 31);
  }
}

TEST_F(SceneTest, EdgesRunThroughTheCentreAtTheirAngles) {
  for (int size = 0; size < 2; ++size) {
    const int width = size == 0 ? kWidth : 333, height = size == 0 ? kHeight : 201;
    for (const double degrees : {0.0, 30.0, 45.0}) {
      const std::string name = "edge-" + std::to_string(static_cast<int>(degrees));
      SCOPED_TRACE(name + " " + std::to_string(width) + "x" + std::to_string(height));
      const sss_bench::Scene s = sss_bench::make_scene(name, width, height);
      // Least-squares line x = a + b * y through the rows' edge positions.
      const std::vector<double> x = edge_positions(s);
      double sy = 0, sx = 0, syy = 0, sxy = 0;
      for (int j = 0; j < height; ++j) {
        const double y = j + 0.5;
        sy += y;
        sx += x[static_cast<size_t>(j)];
        syy += y * y;
        sxy += y * x[static_cast<size_t>(j)];
      }
      const double b = (height * sxy - sy * sx) / (height * syy - sy * sy);
      const double a = (sx - b * sy) / height;
      EXPECT_NEAR(std::atan(b) * 180.0 / kPi, degrees, 0.01) << "top leans right by the angle from the vertical";
      EXPECT_NEAR(a + b * 0.5 * height, 0.5 * width, 0.01) << "through the image centre";
      double worst = 0;
      for (int j = 0; j < height; ++j) worst = std::max(worst, std::fabs(x[static_cast<size_t>(j)] - (a + b * (j + 0.5))));
      EXPECT_LT(worst, 0.01) << "straight";
      // Lit on the left: the first column of the middle row is lit, the last one dark.
      const size_t row = static_cast<size_t>(height / 2) * static_cast<size_t>(width);
      EXPECT_FLOAT_EQ(s.irradiance[row * 4], static_cast<float>(sss_bench::detail::kLit));
      EXPECT_FLOAT_EQ(s.irradiance[(row + static_cast<size_t>(width) - 1) * 4], static_cast<float>(sss_bench::detail::kDark));
    }
  }
}

TEST_F(SceneTest, DotHasItsAreaAtTheCentre) {
  for (const int height : {kHeight, 1080}) {
    const int width = height * 16 / 9;
    const sss_bench::Scene s = sss_bench::make_scene("dot", width, height);
    const double radius_px = sss_bench::detail::kDotRadius * 0.5 * height * s.projection[5] / sss_bench::detail::kPlaneDistance;
    double energy = 0, cx = 0, cy = 0;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const double c = (s.irradiance[(static_cast<size_t>(j) * width + i) * 4] - sss_bench::detail::kDark) /
                         (sss_bench::detail::kLit - sss_bench::detail::kDark);
        energy += c;
        cx += c * (i + 0.5);
        cy += c * (j + 0.5);
      }
    EXPECT_NEAR(energy / (kPi * radius_px * radius_px), 1.0, 0.001) << height;
    EXPECT_NEAR(cx / energy, 0.5 * width, 0.01);
    EXPECT_NEAR(cy / energy, 0.5 * height, 0.01);
  }
}

TEST_F(SceneTest, SphereAndDepthStepCoverTheirAreas) {
  const int width = 320, height = 180;
  const sss_bench::Scene sphere = sss_bench::make_scene("sphere", width, height);
  // The silhouette of a sphere seen from distance D subtends a cone of half-angle asin(R / D).
  const double f = 0.5 * height * sphere.projection[5];
  const double tan_half = std::tan(std::asin(sss_bench::detail::kSphereRadius / sss_bench::detail::kSphereDistance));
  const double disk = kPi * (f * tan_half) * (f * tan_half) / (width * height);
  EXPECT_NEAR(translucent_fraction(sphere), disk, 0.01 * disk);
  float nearest = 1e9f, farthest = 0;
  for (size_t p = 0; p < pixel_count(sphere); ++p) {
    if (sphere.mask[p]) nearest = std::min(nearest, sphere.distance[p]);
    farthest = std::max(farthest, sphere.distance[p]);
  }
  EXPECT_NEAR(nearest, sss_bench::detail::kSphereDistance - sss_bench::detail::kSphereRadius, 1e-3);
  EXPECT_FLOAT_EQ(farthest, static_cast<float>(sss_bench::detail::kSphereBackdropDistance));

  const sss_bench::Scene step = sss_bench::make_scene("depth-step", width, height);
  const double side = 2 * sss_bench::detail::kStepHalfSize * f / sss_bench::detail::kStepNearDistance;
  EXPECT_NEAR(translucent_fraction(step), side * side / (width * height), 0.03 * side * side / (width * height));
  for (size_t p = 0; p < pixel_count(step); ++p) {
    const float expected = static_cast<float>(step.mask[p] ? sss_bench::detail::kStepNearDistance
                                                           : sss_bench::detail::kStepFarDistance);
    ASSERT_EQ(step.distance[p], expected);
    ASSERT_EQ(step.irradiance[p * 4], step.mask[p] ? 0.6f : 4.0f);
  }
}

TEST_F(SceneTest, EmptyHasNothingTranslucent) {
  const sss_bench::Scene s = sss_bench::make_scene("empty", kWidth, kHeight);
  EXPECT_EQ(translucent_fraction(s), 0.0);
  for (size_t p = 0; p < pixel_count(s); ++p) ASSERT_EQ(s.irradiance[p * 4 + 3], 0.0f);
}

TEST_F(SceneTest, HeadCoverageShrinksWithDistance) {
  const auto start = std::chrono::steady_clock::now();
  const sss_bench::Scene close = sss_bench::make_scene("head-close", kWidth, kHeight);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 3.0) << "head-close at 160x90 (including the asset's first load in this process)";
  const sss_bench::Scene mid = sss_bench::make_scene("head-mid", kWidth, kHeight);
  const sss_bench::Scene far = sss_bench::make_scene("head-far", kWidth, kHeight);
  const double c = translucent_fraction(close), m = translucent_fraction(mid), f = translucent_fraction(far);
  EXPECT_GT(c, m);
  EXPECT_GT(m, f);
  EXPECT_GT(f, 0.0);
  // The scan's height is about 1/3 and 1/10 of the frame height at mid and far.
  for (const auto* s : {&mid, &far}) {
    int top = -1, bottom = s->height;
    for (int j = 0; j < s->height; ++j)
      for (int i = 0; i < s->width; ++i)
        if (s->mask[static_cast<size_t>(j) * s->width + i]) {
          top = std::max(top, j);
          bottom = std::min(bottom, j);
        }
    const double fraction = static_cast<double>(top - bottom + 1) / s->height;
    EXPECT_NEAR(fraction, s == &mid ? 1.0 / 3.0 : 1.0 / 10.0, s == &mid ? 0.05 : 0.03) << s->name;
  }
  // The head is in front of the backdrop, which is one plane facing the camera; the head is lit.
  for (const auto* s : {&close, &mid, &far}) {
    float backdrop = -1, head_max = 0, head_irradiance = 0;
    for (size_t p = 0; p < pixel_count(*s); ++p) {
      if (s->mask[p]) {
        head_max = std::max(head_max, s->distance[p]);
        head_irradiance = std::max(head_irradiance, s->irradiance[p * 4]);
      } else {
        if (backdrop < 0) backdrop = s->distance[p];
        ASSERT_EQ(s->distance[p], backdrop) << s->name;
        ASSERT_FLOAT_EQ(s->irradiance[p * 4], 0.05f) << s->name;
      }
    }
    EXPECT_LT(head_max, backdrop) << s->name;
    EXPECT_GT(head_irradiance, 0.2f) << s->name;
  }
}

// The head scenes leave the caller's state as it was, create no lasting object, leave no error,
// and do not depend on that state.
// How far each skin pixel of a head scene turns from its view direction (degrees): its normal from
// its 4-neighbours' positions by central differences (the depth gradient), NaN where one of them
// is not skin or the pixel is on the frame's edge.
std::vector<double> depth_gradient_turns(const sss_bench::Scene& s) {
  sss::math::Matrix4 m{};
  std::copy(s.projection.begin(), s.projection.end(), m.begin());
  std::vector<double> turns(pixel_count(s), std::nan(""));
  const auto at = [&](int x, int y) {
    return sss::math::pixel_position(m, s.width, s.height, x, y, s.distance[static_cast<size_t>(y) * s.width + x]);
  };
  for (int y = 1; y + 1 < s.height; ++y) {
    for (int x = 1; x + 1 < s.width; ++x) {
      const size_t p = static_cast<size_t>(y) * s.width + x;
      if (!s.mask[p] || !s.mask[p - 1] || !s.mask[p + 1] || !s.mask[p - s.width] || !s.mask[p + s.width]) continue;
      const sss::math::Vec3 n = sss::math::cross(at(x + 1, y) - at(x - 1, y), at(x, y + 1) - at(x, y - 1));
      const sss::math::Vec3 position = at(x, y);
      const double c = std::fabs(sss::math::dot(n, position)) / (sss::math::length(n) * sss::math::length(position));
      turns[p] = std::acos(std::min(1.0, c)) * 180.0 / kPi;
    }
  }
  return turns;
}

double median_of(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// head-grazing: the left cheek turned about 70 degrees away, and the frame's interior pixels as
// scenes.cpp states (numbers measured at 320x180; the same on every backend this suite runs).
TEST_F(SceneTest, HeadGrazingTurnsTheCheekAway) {
  const int width = 320, height = 180;
  const sss_bench::Scene s = sss_bench::make_scene("head-grazing", width, height);
  check_scene(s, "head-grazing", width, height);
  sss_bench::detail::Mat4 projection{}, view{};
  sss_bench::detail::head_camera(sss_bench::detail::head_view("head-grazing"), width, height, &projection, &view);
  const std::vector<double> turns = depth_gradient_turns(s);
  const std::vector<uint8_t> interior = sss_bench::region_mask(
      sss_bench::classify_regions(sss_bench::region_input_of(s, sss_bench::profile_reach_mm(sss::math::skin_profile_terms()))),
      sss_bench::Region::interior);
  sss::math::Matrix4 m{};
  std::copy(s.projection.begin(), s.projection.end(), m.begin());
  std::vector<double> cheek, inside;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * width + x;
      if (std::isnan(turns[p])) continue;
      if (interior[p]) inside.push_back(turns[p]);
      // The scan's coordinates: view = R world + t, so world = Rᵀ (view - t).
      const sss::math::Vec3 v = sss::math::pixel_position(m, width, height, x, y, s.distance[p]);
      const double q[3] = {v.x - view[12], v.y - view[13], v.z - view[14]};
      double w[3];
      for (int r = 0; r < 3; ++r) w[r] = view[r * 4] * q[0] + view[r * 4 + 1] * q[1] + view[r * 4 + 2] * q[2];
      if (w[0] > 0.02 && w[0] < 0.07 && w[1] > 0.0 && w[1] < 0.06 && w[2] > 0.03) cheek.push_back(turns[p]);
    }
  }
  ASSERT_GT(cheek.size(), 150u);
  const auto share_60_80 = [](const std::vector<double>& t) {
    return static_cast<double>(std::count_if(t.begin(), t.end(), [](double v) { return v >= 60.0 && v <= 80.0; })) /
           static_cast<double>(t.size());
  };
  EXPECT_NEAR(median_of(cheek), 67.5, 1.5);
  EXPECT_GT(share_60_80(cheek), 0.65);
  EXPECT_NEAR(median_of(inside), 37.6, 1.0);
}

TEST_F(SceneTest, HeadSceneRestoresGlStateAndDeletesItsObjects) {
  const sss_bench::Scene reference = sss_bench::make_scene("head-close", kWidth, kHeight);

  // Odd caller state: its own framebuffer, program, VAO, buffer, textures on the units used.
  GLuint user_textures[4] = {0, 0, 0, 0}, framebuffer = 0, vertex_array = 0, buffer = 0;
  glGenTextures(4, user_textures);
  for (GLuint unit = 0; unit < 4; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, user_textures[unit]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  }
  glActiveTexture(GL_TEXTURE5);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, user_textures[0], 0);
  glGenVertexArrays(1, &vertex_array);
  glBindVertexArray(vertex_array);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const GLuint program = make_host_program(false);
  glUseProgram(program);
  glViewport(3, 5, 17, 11);
  glEnable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 1, 2, 2);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT_AND_BACK);
  glEnable(GL_CLIP_DISTANCE0);
  glDepthFunc(GL_NEVER);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glPolygonOffset(3.0f, 7.0f);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_PACK_ROW_LENGTH, 5);
  glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  struct Probe {
    GLenum pname;
    int count;
  };
  const Probe probes[] = {{GL_DRAW_FRAMEBUFFER_BINDING, 1}, {GL_READ_FRAMEBUFFER_BINDING, 1}, {GL_CURRENT_PROGRAM, 1},
                          {GL_VERTEX_ARRAY_BINDING, 1},     {GL_ARRAY_BUFFER_BINDING, 1},     {GL_ACTIVE_TEXTURE, 1},
                          {GL_VIEWPORT, 4},                 {GL_SCISSOR_BOX, 4},              {GL_CULL_FACE_MODE, 1},
                          {GL_DEPTH_FUNC, 1},               {GL_PACK_ALIGNMENT, 1},           {GL_UNPACK_ALIGNMENT, 1},
                          {GL_UNPACK_ROW_LENGTH, 1},        {GL_PACK_ROW_LENGTH, 1},          {GL_CLAMP_READ_COLOR, 1},
                          {GL_ELEMENT_ARRAY_BUFFER_BINDING, 1}, {GL_DRAW_BUFFER0, 1},         {GL_READ_BUFFER, 1}};
  auto snapshot = [&]() {
    std::vector<GLint> v;
    for (const Probe& p : probes) {
      GLint value[4] = {-1, -1, -1, -1};
      glGetIntegerv(p.pname, value);
      v.insert(v.end(), value, value + p.count);
    }
    for (GLenum cap : {GL_BLEND, GL_SCISSOR_TEST, GL_CULL_FACE, GL_CLIP_DISTANCE0, GL_DEPTH_TEST, GL_POLYGON_OFFSET_FILL})
      v.push_back(glIsEnabled(cap));
    GLboolean masks[5] = {0, 0, 0, 0, 0};
    glGetBooleanv(GL_COLOR_WRITEMASK, masks);
    glGetBooleanv(GL_DEPTH_WRITEMASK, masks + 4);
    v.insert(v.end(), masks, masks + 5);
    GLfloat floats[6] = {0, 0, 0, 0, 0, 0};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, floats);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, floats + 4);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, floats + 5);
    for (GLfloat x : floats) v.push_back(static_cast<GLint>(x * 1000));
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (GLuint unit = 0; unit < 4; ++unit) {
      glActiveTexture(GL_TEXTURE0 + unit);
      GLint bound = -1;
      glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
      v.push_back(bound);
    }
    glActiveTexture(static_cast<GLenum>(active));
    return v;
  };
  // Which names 1..512 are live objects of each kind.
  auto live_objects = []() {
    std::vector<bool> live;
    for (GLuint name = 1; name <= 512; ++name) {
      live.push_back(glIsTexture(name) == GL_TRUE);
      live.push_back(glIsBuffer(name) == GL_TRUE);
      live.push_back(glIsFramebuffer(name) == GL_TRUE);
      live.push_back(glIsVertexArray(name) == GL_TRUE);
      live.push_back(glIsProgram(name) == GL_TRUE);
      live.push_back(glIsShader(name) == GL_TRUE);
    }
    return live;
  };
  const std::vector<GLint> before = snapshot();
  const std::vector<bool> objects_before = live_objects();
  const sss_bench::Scene odd = sss_bench::make_scene("head-close", kWidth, kHeight);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(snapshot(), before);
  EXPECT_EQ(live_objects(), objects_before) << "a GL object was left behind";
  EXPECT_TRUE(bit_identical(odd, reference)) << "the result depends on the caller's GL state";

  glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glDisable(GL_CLIP_DISTANCE0);
  glUseProgram(0);
  glDeleteProgram(program);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vertex_array);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(4, user_textures);
}

// Both backends render the same head scene (both are llvmpipe).
TEST_F(SceneTest, HeadSceneIsTheSameOnOsmesaAndEgl) {
  const sss_bench::Scene here = sss_bench::make_scene("head-close", kWidth, kHeight);
  sss_headless_desc desc = {};
  desc.backend = test_backend() == SSS_HEADLESS_OSMESA ? SSS_HEADLESS_EGL_SURFACELESS : SSS_HEADLESS_OSMESA;
  desc.major = 3;
  desc.minor = 3;
  desc.core_profile = 1;
  sss_headless* other = nullptr;
  char error[512] = "";
  if (sss_headless_create(&desc, &other, error, sizeof error) != 0) GTEST_SKIP() << "no second backend: " << error;
  std::string missing;
  sss_bench::Scene there;
  if (host_gl::load(sss_headless_get_proc_address, other, &missing)) there = sss_bench::make_scene("head-close", kWidth, kHeight);
  sss_headless_destroy(other);
  ASSERT_EQ(sss_headless_make_current(headless_), 0);
  ASSERT_TRUE(host_gl::load(sss_headless_get_proc_address, headless_, &missing)) << missing;
  ASSERT_TRUE(missing.empty()) << missing;
  EXPECT_TRUE(bit_identical(here, there));
}

TEST_F(SceneTest, AssetDirectoryComesFromTheEnvironment) {
  const char* previous = std::getenv("SSS_ASSET_DIR");
  const std::string saved = previous != nullptr ? previous : "";
  ::setenv("SSS_ASSET_DIR", "/nonexistent-sss-assets", 1);
  EXPECT_EQ(sss_bench::asset_dir(), "/nonexistent-sss-assets");
  try {
    sss_bench::make_scene("head-far", kWidth, kHeight);
    ADD_FAILURE() << "no exception for a missing asset";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-sss-assets/lee-perry-smith-head/head.glb"), std::string::npos)
        << e.what();
  }
  if (previous != nullptr)
    ::setenv("SSS_ASSET_DIR", saved.c_str(), 1);
  else
    ::unsetenv("SSS_ASSET_DIR");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_NE(std::string(sss_bench::head_attribution()).find("Lee Perry-Smith"), std::string::npos);
}

// A clone alone renders the head: without SSS_ASSET_DIR the scan comes from assets/ in the source
// tree (not from a folder beside it), and its README there carries the attribution the code prints.
TEST_F(SceneTest, TheHeadShipsWithTheProjectAndItsAttribution) {
  const char* previous = std::getenv("SSS_ASSET_DIR");
  const std::string saved = previous != nullptr ? previous : "";
  ::unsetenv("SSS_ASSET_DIR");
  const std::string dir = sss_bench::asset_dir();
  if (previous != nullptr) ::setenv("SSS_ASSET_DIR", saved.c_str(), 1);
  const std::filesystem::path shipped = std::filesystem::path(SSS_SOURCE_DIR) / "assets";
  EXPECT_TRUE(std::filesystem::equivalent(dir, shipped)) << dir << " is not " << shipped;
  EXPECT_TRUE(std::filesystem::is_regular_file(shipped / "lee-perry-smith-head" / "head.glb"));
  std::ifstream readme(shipped / "lee-perry-smith-head" / "README.md");
  ASSERT_TRUE(readme.good());
  // The attribution as one line of words: the README wraps it.
  std::string text, word;
  while (readme >> word) text += (text.empty() ? "" : " ") + word;
  EXPECT_NE(text.find(sss_bench::head_attribution()), std::string::npos) << sss_bench::head_attribution();
}

// The normal map's green channel convention, checked on the asset itself (see head_scene.cpp):
//  - the map is the gradient field of a height field only with +green towards -v (up the image):
//    the curl of the implied gradient is far smaller that way;
//  - the mesh's bitangent cross(N, T) * w points towards +v (and T towards +u);
// so the shader, which builds its frame from (T, bitangent), must invert green.
TEST_F(SceneTest, NormalMapGreenConvention) {
  const sss_bench::detail::HeadAsset& asset = sss_bench::detail::head_asset();
  const sss_bench::detail::HeadImage& map = asset.normal;
  const int w = map.width, h = map.height, k = map.components;
  // Slopes at half resolution (box 2x2), where the curl test separates the two readings clearly.
  const int hw = w / 2, hh = h / 2;
  std::vector<double> p(static_cast<size_t>(hw * hh)), q(p.size()), z(p.size());
  for (int y = 0; y < hh; ++y)
    for (int x = 0; x < hw; ++x) {
      double n[3] = {0, 0, 0}, zmin = 1;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const uint8_t* t = &map.pixels[(static_cast<size_t>(2 * y + dy) * w + (2 * x + dx)) * k];
          double c[3];
          for (int i = 0; i < 3; ++i) c[i] = 2.0 * t[i] / 255.0 - 1.0;
          for (int i = 0; i < 3; ++i) n[i] += c[i] / 4;
          zmin = std::min(zmin, c[2]);
        }
      const size_t i = static_cast<size_t>(y * hw + x);
      p[i] = -n[0] / std::max(n[2], 0.2);  // dh/du with red towards +u
      q[i] = n[1] / std::max(n[2], 0.2);   // dh/dv if +green points towards -v
      z[i] = zmin;
    }
  double curl_up = 0, curl_down = 0;
  for (int y = 1; y < hh - 1; ++y)
    for (int x = 1; x < hw - 1; ++x) {
      const size_t i = static_cast<size_t>(y * hw + x);
      if (z[i] < 0.3) continue;
      const double dp_dv = (p[i + static_cast<size_t>(hw)] - p[i - static_cast<size_t>(hw)]) / 2;  // rows run down (+v)
      const double dq_du = (q[i + 1] - q[i - 1]) / 2;
      curl_up += (dp_dv - dq_du) * (dp_dv - dq_du);
      curl_down += (dp_dv + dq_du) * (dp_dv + dq_du);
    }
  EXPECT_GT(curl_down, 2.0 * curl_up) << "+green is not towards -v (up the image)";

  // The mesh's frame against the texture-space derivatives of each triangle.
  size_t bitangent_down = 0, tangent_right = 0, triangles = 0;
  const float* v = asset.vertices.data();
  const size_t stride = sss_bench::detail::HeadAsset::kFloatsPerVertex;
  for (size_t t = 0; t + 2 < asset.indices.size(); t += 3) {
    const float* a = v + asset.indices[t] * stride;
    const float* b = v + asset.indices[t + 1] * stride;
    const float* c = v + asset.indices[t + 2] * stride;
    const double du1 = b[6] - a[6], dv1 = b[7] - a[7], du2 = c[6] - a[6], dv2 = c[7] - a[7];
    const double det = du1 * dv2 - du2 * dv1;
    if (std::fabs(det) < 1e-12) continue;
    double dpdu[3], dpdv[3];
    for (int i = 0; i < 3; ++i) {
      const double e1 = b[i] - a[i], e2 = c[i] - a[i];
      dpdu[i] = (e1 * dv2 - e2 * dv1) / det;
      dpdv[i] = (e2 * du1 - e1 * du2) / det;
    }
    const double n[3] = {a[3], a[4], a[5]}, tg[3] = {a[8], a[9], a[10]}, sign = a[11] < 0 ? -1.0 : 1.0;
    const double bt[3] = {(n[1] * tg[2] - n[2] * tg[1]) * sign, (n[2] * tg[0] - n[0] * tg[2]) * sign,
                          (n[0] * tg[1] - n[1] * tg[0]) * sign};
    bitangent_down += bt[0] * dpdv[0] + bt[1] * dpdv[1] + bt[2] * dpdv[2] > 0 ? 1 : 0;
    tangent_right += tg[0] * dpdu[0] + tg[1] * dpdu[1] + tg[2] * dpdu[2] > 0 ? 1 : 0;
    ++triangles;
  }
  ASSERT_GT(triangles, 1000u);
  EXPECT_GT(tangent_right, triangles * 99 / 100);
  EXPECT_GT(bitangent_down, triangles * 99 / 100) << "the bitangent no longer points towards +v";
  EXPECT_EQ(sss_bench::detail::kNormalMapGreenSign, -1.0f);
}

// The turn sweep's planes: what scene.hpp promises (an orthographic projection for half of them);
// every translucent pixel on the plane it reports, turned by its angle; orthographic: translucent
// everywhere with pixels of the footprint; the shadow edge through the centre and the spot's light.
TEST_F(SceneTest, TurnedPlanesLieOnTheirPlane) {
  const int side = 96;
  const double footprint = 0.2;
  for (bool orthographic : {true, false}) {
    for (double turn : {0.0, 60.0, 75.0}) {
      for (double axis : {0.0, 45.0}) {
        sss_bench::PlaneGeometry plane;
        const sss_bench::Scene s = sss_bench::make_turned_plane_scene(footprint, turn, axis, orthographic, side, side, &plane);
        const std::string name = "turned-" + std::to_string(static_cast<int>(turn)) + "-about-" +
                                 std::to_string(static_cast<int>(axis)) + (orthographic ? "-orthographic" : "-perspective");
        check_scene(s, name, side, side, !orthographic);
        SCOPED_TRACE(name);
        EXPECT_NEAR(plane.normal[2], std::cos(turn * kPi / 180.0), 1e-12);
        sss::math::Matrix4 m{};
        std::copy(s.projection.begin(), s.projection.end(), m.begin());
        const sss::math::Vec3 n{plane.normal[0], plane.normal[1], plane.normal[2]};
        const sss::math::Vec3 point{plane.point[0], plane.point[1], plane.point[2]};
        double off_plane = 0.0, dark = 0.0, lit = 0.0, brightest = 0.0;
        for (int y = 0; y < side; ++y)
          for (int x = 0; x < side; ++x) {
            const size_t p = static_cast<size_t>(y) * side + x;
            if (s.mask[p] == 0) continue;
            const sss::math::Vec3 at = sss::math::pixel_position(m, side, side, x, y, s.distance[p]);
            off_plane = std::max(off_plane, std::fabs(sss::math::dot(n, at - point)) / s.distance[p]);
            const double e = s.irradiance[p * 4];
            dark += e <= sss_bench::detail::kDark ? 1.0 : 0.0;
            lit += e >= sss_bench::detail::kAlbedoLow * sss_bench::detail::kLit ? 1.0 : 0.0;
            brightest = std::max(brightest, e);
          }
        EXPECT_LT(off_plane, 1e-6);  // the float distances' rounding
        const double translucent = translucent_fraction(s) * side * side;
        EXPECT_GT(dark, 0.3 * translucent);  // the edge through the centre (the backdrop takes a side's part)
        EXPECT_GT(lit, 0.3 * translucent);
        if (turn <= 60.0) {
          EXPECT_GT(brightest, 1.5);  // a few whole pixels of the spot at 4.0 times an albedo
        }
        if (!orthographic) continue;
        EXPECT_EQ(translucent_fraction(s), 1.0);
        const auto f = sss::math::turned_plane_footprint(m, side, side, point, n, s.world_units_per_mm, 3, 5);
        EXPECT_NEAR(f.a_mm * f.b_mm, footprint * footprint / std::cos(turn * kPi / 180.0), 1e-5 * footprint * footprint);
      }
    }
  }
  // The narrow perspective camera sees no horizon at 75 degrees: the plane fills the frame.
  EXPECT_EQ(translucent_fraction(sss_bench::make_turned_plane_scene(footprint, 75.0, 0.0, false, side, side)), 1.0);
  EXPECT_THROW(sss_bench::make_turned_plane_scene(0.0, 30.0, 0.0, true, side, side), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_turned_plane_scene(0.2, 90.0, 0.0, true, side, side), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_turned_plane_scene(0.2, 30.0, 0.0, true, 2, side), std::invalid_argument);
}

// Every frame of the default turn sweep (turn_sweep.hpp: its footprints, turns, axes and both
// projections, framed as sss_bench_turns frames them) keeps interior pixels to score, and the
// perspective camera's corner rays are kTurnedPlaneSpreadDegrees off its axis, so every pixel sees
// the plane within that of its turn (analytic_scenes.cpp: turned_plane_fovy_degrees).
TEST_F(SceneTest, TurnSweepPlanesKeepAnInterior) {
  const sss_bench::turns::Options sweep;
  const double reach_mm = sss_bench::profile_reach_mm(sss::math::skin_profile_terms());
  for (double footprint : sweep.footprints) {
    const int side = sss_bench::sweep_frame_side(footprint, sss_bench::kCalibrationInteriorPx, reach_mm);
    for (const std::string& projection : sweep.projections) {
      for (double turn : sweep.turns) {
        for (double axis : sweep.axes) {
          const sss_bench::Scene s =
              sss_bench::make_turned_plane_scene(footprint, turn, axis, projection == "orthographic", side, side);
          SCOPED_TRACE(s.name + " at " + std::to_string(footprint) + " mm/px");
          const std::vector<uint8_t> interior = sss_bench::region_mask(
              sss_bench::classify_regions(sss_bench::region_input_of(s, reach_mm)), sss_bench::Region::interior);
          EXPECT_GT(std::count(interior.begin(), interior.end(), uint8_t{1}), 0);
          if (projection == "orthographic") continue;
          // The corner ray's angle off the axis: x / m[0] and y / m[5] at NDC (1, 1) and z = -1.
          const double corner = std::hypot(1.0 / s.projection[0], 1.0 / s.projection[5]);
          EXPECT_NEAR(std::atan(corner) * 180.0 / kPi, sss_bench::detail::kTurnedPlaneSpreadDegrees, 1e-4);
        }
      }
    }
  }
}

// The turn sweep's curved scenes: what scene.hpp promises; the cylinder shaded and dark on either side
// of its terminator before the backdrop; the sphere's nearest point where a facing pixel measures the
// footprint. Both need a clear change where they are scored: around the image centre, the cast
// shadow's edge leaves lit and dark pixels, and the per-pixel albedo makes neighbours differ.
TEST_F(SceneTest, TurnSweepCylinderAndSphere) {
  for (double footprint : {0.1, 1.0}) {
    const int side = footprint < 0.5 ? 244 : 84;  // the sweep's frames
    const sss_bench::Scene cylinder = sss_bench::make_cylinder_scene(footprint, side, side);
    check_scene(cylinder, "cylinder", side, side);
    const double ambient_only = 0.85 * 0.03 + 1e-6;  // red: albedo times the ambient term, at most
    size_t shaded = 0, unlit = 0;
    for (size_t p = 0; p < pixel_count(cylinder); ++p) {
      if (cylinder.mask[p] == 0) continue;
      (cylinder.irradiance[p * 4] > ambient_only ? shaded : unlit) += 1;
    }
    EXPECT_GT(shaded, pixel_count(cylinder) / 5) << footprint;
    EXPECT_GT(unlit, pixel_count(cylinder) / 5) << footprint;
    const sss_bench::Scene sphere = sss_bench::make_footprint_sphere_scene(footprint, side, side);
    check_scene(sphere, "sphere-40mm", side, side);
    sss::math::Matrix4 m{};
    std::copy(sphere.projection.begin(), sphere.projection.end(), m.begin());
    const float nearest = *std::min_element(sphere.distance.begin(), sphere.distance.end());
    EXPECT_NEAR(sss::math::plane_pixel_mm_y(m, side, nearest, sphere.world_units_per_mm), footprint, 0.01 * footprint);
    for (const sss_bench::Scene* s : {&cylinder, &sphere}) {
      SCOPED_TRACE(s->name + " at " + std::to_string(footprint) + " mm/px");
      // The central 64x64 pixels (the sweep's interior at the coarse footprints).
      size_t lit = 0, dark = 0, pairs = 0, differing = 0;
      for (int y = side / 2 - 32; y < side / 2 + 32; ++y) {
        for (int x = side / 2 - 32; x < side / 2 + 32; ++x) {
          const size_t p = static_cast<size_t>(y) * static_cast<size_t>(side) + static_cast<size_t>(x);
          const float e = s->irradiance[p * 4], right = s->irradiance[(p + 1) * 4];
          (e > ambient_only ? lit : dark) += 1;
          if (e > 2.0 * ambient_only && right > 2.0 * ambient_only) {
            ++pairs;
            differing += std::fabs(e - right) > 0.2 * std::max(e, right) ? 1 : 0;
          }
        }
      }
      EXPECT_GT(lit, 64u * 64u / 5);
      EXPECT_GT(dark, 64u * 64u / 5);
      EXPECT_GT(differing, pairs / 3);  // two random albedos in [0.25, 1) differ so 67 % of the time
    }
  }
  EXPECT_THROW(sss_bench::make_cylinder_scene(-1.0, 84, 84), std::invalid_argument);
  EXPECT_THROW(sss_bench::make_footprint_sphere_scene(20.0, 84, 84), std::invalid_argument);  // through the backdrop
}

}  // namespace
}  // namespace sss_test
