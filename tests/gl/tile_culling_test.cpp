// The masked path's tile culling (SSS_PATH_FRAGMENT_MASKED; module/src/gl/tile_marks.cpp, the rule
// in module/src/math/tile_culling.hpp): its draws cover only bands of 16x16 tiles holding
// translucent pixels (the passes) or within their rows and columns (the inputs the taps read).
// What can go wrong is a tap reading a texel the inputs draw did not write this frame, or a pixel
// outside the bands keeping an earlier frame's culling mark. So each case runs after a frame that
// filled every target with other colours, every pixel translucent, on a frame whose few
// translucent pixels sit at tile corners, at the frame's last partial row and column, alone and in
// a cluster, with kernels reaching over several tiles: the result must be the plain fragment
// path's bit for bit (the same shader on the same pixels), and the CPU model's within
// MatchesCpuModel's tolerance (3e-3 relative: one RGBA16F rounding of the intermediate flipped by
// float reordering, carried into the output).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "filter_case.hpp"
#include "kernel_of.hpp"
#include "math/filter_constants.hpp"
#include "math/pass_kernel.hpp"
#include "math/tile_culling.hpp"

namespace sss_test {
namespace {

constexpr float kTolerance = 3e-3f;
// 10 x 17 tiles, the last of each partial; 5 bands of 4 rows of tiles, the last partial. Bands 1 and
// 3 hold no translucent pixel: the inputs draw reaches them only through the columns' marks.
constexpr int kWidth = 150, kHeight = 260;

// The relief scene (colours and depths everywhere, so the taps read real neighbours) with alpha 0
// but at a few sparse places.
SyntheticScene sparse_scene() {
  SyntheticScene s = make_relief_scene(kWidth, kHeight, 5,
                                       perspective_matrix(40.0f, static_cast<float>(kWidth) / kHeight, 0.1f, 10.0f));
  for (std::size_t i = 3; i < s.color.size(); i += 4) s.color[i] = 0.0f;
  const auto translucent = [&s](int x, int y, float alpha) {
    s.color[(static_cast<std::size_t>(y) * kWidth + x) * 4 + 3] = alpha;
  };
  translucent(16, 16, 1.0f);           // the first pixel of a tile (band 0's second row of tiles)
  translucent(15, 63, 0.8f);           // the last pixel of a tile, next to band 1 (empty)
  translucent(kWidth - 1, 150, 1.0f);  // the last, partial column of tiles (band 2)
  translucent(40, kHeight - 1, 0.6f);  // the last, partial row of tiles (band 4, partial)
  for (int y = 128; y < 132; ++y) {
    for (int x = 100; x < 104; ++x) translucent(x, y, 0.9f);  // a cluster at band 2's first row
  }
  return s;
}

// Wide kernels: at the relief's distances they reach over several tiles (checked below).
sss_settings wide(uint32_t path) {
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.4f);
  s.path = path;
  return s;
}

using TileCulling = FilterCaseTest;

TEST_F(TileCulling, SparsePixelsAfterAFullFrameGiveThePlainResultBitForBit) {
  const SyntheticScene scene = sparse_scene();
  {  // the case means something: the taps of the sparse pixels leave their tiles
    sss::math::FilterSettings fs;
    fs.world_units_per_mm = wide(0).world_units_per_mm;
    const sss::math::PassKernel kernel = sss::math::build_pass_kernel(fs);
    sss::math::FrameGeometry g;
    g.texture_width = kWidth;
    g.texture_height = kHeight;
    g.viewport = {0, 0, kWidth, kHeight};
    const auto constants = sss::math::compute_pass_constants(fs, scene.projection, g, kernel.reach_mm);
    float least = 1e30f;
    for (std::size_t i = 0; i < scene.distance.size(); ++i) {
      if (scene.color[i * 4 + 3] > 0.0f) {
        least = std::min(least, kernel.reach_mm * constants.pixels_per_mm[1] * scene.color[i * 4 + 3] /
                                    scene.distance[i]);
      }
    }
    std::printf("the narrowest kernel of a translucent pixel reaches %.1f pixels\n", static_cast<double>(least));
    ASSERT_GT(least, 2.0f * sss::math::kTileSize);
  }
  struct Variant {
    const char* name;
    bool half_color, separate, region, two_terms, jitter;
    DepthKind depth;
  };
  for (const Variant& v : {Variant{"RGBA32F in place", false, false, false, false, false, DepthKind::depth32f},
                           Variant{"RGBA16F in place", true, false, false, false, false, DepthKind::depth32f},
                           Variant{"RGBA32F into an output", false, true, false, false, false, DepthKind::depth32f},
                           Variant{"RGBA16F region into an output", true, true, true, false, false,
                                   DepthKind::depth32f},
                           Variant{"RGBA32F region in place, linear depth", false, false, true, false, false,
                                   DepthKind::linear_r32f},
                           Variant{"two kernel terms into an output", false, true, false, true, false,
                                   DepthKind::depth32f},
                           Variant{"jittered taps in place", true, false, false, false, true, DepthKind::depth32f}}) {
    SCOPED_TRACE(v.name);
    FilterCase c;
    c.half_color = v.half_color;
    c.separate_output = v.separate;
    c.depth = v.depth;
    c.use_region = v.region;
    c.region = {3, 5, 139, 251};  // odd offsets: the tiles start at the region's corner
    std::vector<float> results[2];
    for (int masked = 0; masked < 2; ++masked) {
      c.settings = wide(masked ? SSS_PATH_FRAGMENT_MASKED : SSS_PATH_FRAGMENT);
      if (v.two_terms) {
        kernel_of(c.settings).family = SSS_KERNEL_SUM_OF_GAUSSIANS;
        kernel_of(c.settings).rank = 2;
      }
      if (v.jitter) c.settings.jitter = 0.5f;
      c.stale_frame_first = masked != 0;
      const FilterOutcome o = run_case(scene, c);
      ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
      EXPECT_EQ(last_path(), masked ? uint32_t{SSS_PATH_FRAGMENT_MASKED} : uint32_t{SSS_PATH_FRAGMENT});
      const float difference = largest_relative_difference(o.gpu, o.cpu);
      std::printf("%s, %s: GPU vs CPU model %.3g\n", v.name, masked ? "masked after a full frame" : "plain",
                  static_cast<double>(difference));
      EXPECT_LE(difference, kTolerance);
      EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // it blurred
      results[masked] = o.gpu;
    }
    EXPECT_EQ(results[1], results[0]) << "the masked path after a full frame differs from the plain path";
  }
}

// The half-resolution path keeps the same bands (module/src/gl/half_resolution_passes.cpp), and its reduction
// and half-size passes the same tiles at 8 texels a side, wherever the rectangle starts on even
// coordinates. The same sparse frame after a full one must be its CPU model's within
// HalfResolution.MatchesTheCpuModel's tolerance (3e-3), with pixels upsampled and pixels left to
// the full-size passes; a region at odd offsets takes the whole-rectangle draws, a region at even
// ones the bands.
TEST_F(TileCulling, TheHalfResolutionPathOnSparsePixelsAfterAFullFrameMatchesItsCpuModel) {
  SyntheticScene scene = sparse_scene();
  for (int x = 60; x < 63; ++x) {  // kernels of a few pixels: the full-size passes take them
    scene.color[(static_cast<std::size_t>(200) * kWidth + x) * 4 + 3] = 0.003f;
  }
  struct Variant {
    const char* name;
    bool half_color, separate, region;
    std::array<int32_t, 4> region_rect;
  };
  for (const Variant& v : {Variant{"RGBA32F in place", false, false, false, {}},
                           Variant{"RGBA16F in place", true, false, false, {}},
                           Variant{"RGBA32F into an output", false, true, false, {}},
                           Variant{"RGBA16F region at even offsets into an output", true, true, true, {4, 6, 140, 250}},
                           Variant{"RGBA32F region at even offsets in place", false, false, true, {2, 0, 146, 259}},
                           Variant{"RGBA16F region at odd offsets in place", true, false, true, {3, 5, 139, 251}}}) {
    SCOPED_TRACE(v.name);
    FilterCase c;
    c.settings = wide(SSS_PATH_HALF_RESOLUTION);
    c.half_color = v.half_color;
    c.separate_output = v.separate;
    c.use_region = v.region;
    c.region = v.region_rect;
    c.stale_frame_first = true;
    const FilterOutcome o = run_case(scene, c);
    ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(last_path(), uint32_t{SSS_PATH_HALF_RESOLUTION});
    const float difference = largest_relative_difference(o.gpu, o.cpu);
    std::printf("half resolution, %s, after a full frame: GPU vs CPU model %.3g; %lld pixels upsampled, %lld at full "
                "size\n",
                v.name, static_cast<double>(difference), o.upsampled, o.full_size);
    EXPECT_LE(difference, kTolerance);
    EXPECT_GT(largest_relative_difference(o.gpu, o.input), 0.02f);  // it blurred
    EXPECT_GT(o.upsampled, 10);  // the half-size draws served pixels
    EXPECT_GT(o.full_size, 0);   // and the full-size passes others
  }
}

// A frame with no translucent pixel at all after a full one: nothing drawn, nothing changed (in
// place the colour keeps every bit; into an output it is copied), on the masked and half paths.
TEST_F(TileCulling, AnEmptyFrameAfterAFullOneChangesNothing) {
  SyntheticScene scene = sparse_scene();
  for (std::size_t i = 3; i < scene.color.size(); i += 4) scene.color[i] = 0.0f;
  for (const uint32_t path : {uint32_t{SSS_PATH_FRAGMENT_MASKED}, uint32_t{SSS_PATH_HALF_RESOLUTION}}) {
    for (const bool separate : {false, true}) {
      SCOPED_TRACE(separate ? "into an output" : "in place");
      SCOPED_TRACE(path == SSS_PATH_HALF_RESOLUTION ? "half resolution" : "masked");
      FilterCase c;
      c.settings = wide(path);
      c.separate_output = separate;
      c.stale_frame_first = true;
      const FilterOutcome o = run_case(scene, c);
      ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
      EXPECT_EQ(o.gpu, o.input);
    }
  }
}

}  // namespace
}  // namespace sss_test
