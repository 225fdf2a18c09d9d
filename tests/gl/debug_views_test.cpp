// The debug views (sss_frame.debug_view): what the passes see, written into the output texture, on
// the GL against the CPU model of the same passes (math::cpu_pass_kernel_filter with
// CpuFilterImage::debug_view). The mask and the tap counts are data: equal value for value, but for
// the few pixels where the walk's float noise puts a tap count one step over, as it puts a tap one
// pixel over (expect_matches_model_up_to_tap_flips: the step differs by an ulp or so between the
// driver's compiler and the model). The depth and the footprint are measures: within the output's
// fp16 rounding (one fp16 step, 2^-10 relative: the GL's and the model's values may round to
// neighbouring steps) and, RGBA32F, within 1e-5 of the model (the walk's ulps). Bad frames are refused by
// name with nothing drawn. The per-pixel profile view is in profile_ids_test.cpp.
//   DebugViews.*  every backend
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "filter_case.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 48, kH = 32;

class DebugViews : public FilterCaseTest {
 protected:
  void SetUp() override {
    FilterCaseTest::SetUp();
    // A relief with the background (alpha 0) around a translucent patch, so the views show both.
    scene_ = make_relief_scene(kW, kH, 3, perspective_matrix(40.0f, 1.5f, 0.1f, 10.0f));
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        if (x < 6 || y > kH - 5) scene_.color[(static_cast<std::size_t>(y) * kW + x) * 4 + 3] = 0.0f;
      }
    }
  }
  FilterCase view_case(uint32_t view, bool half_output) const {
    FilterCase c;
    c.settings = visible_settings(17, SSS_FOLLOW_SURFACE, 0.18f);  // sparse taps at the near pixels
    c.settings.path = SSS_PATH_AUTO;  // any path: a view runs the fragment passes
    c.separate_output = true;
    c.half_color = half_output;  // the output has the colour's format
    c.debug_view = view;
    return c;
  }
  SyntheticScene scene_;
};

// Where the view's values are finite and the output has a value: the pixel's channel c.
float at(const std::vector<float>& image, int x, int y, int c) {
  return image[(static_cast<std::size_t>(y) * kW + x) * 4 + static_cast<std::size_t>(c)];
}

TEST_F(DebugViews, EachViewMatchesTheCpuModel) {
  struct View {
    uint32_t view;
    const char* name;
    bool data;  // equal value for value (else a measure: within the rounding)
  };
  const View views[] = {{SSS_DEBUG_VIEW_MASK, "mask", true},
                        {SSS_DEBUG_VIEW_LINEAR_DEPTH, "linear depth", false},
                        {SSS_DEBUG_VIEW_FOOTPRINT, "footprint", false},
                        {SSS_DEBUG_VIEW_TAPS, "taps", true},
                        {SSS_DEBUG_VIEW_PROFILE, "profile (none: zero)", true},
                        {SSS_DEBUG_VIEW_ALBEDO, "albedo (pre-scatter: one)", true}};
  for (const View& v : views) {
    for (const bool half : {false, true}) {
      SCOPED_TRACE(std::string(v.name) + (half ? ", RGBA16F" : ", RGBA32F"));
      const FilterOutcome o = run_case(scene_, view_case(v.view, half));
      ASSERT_EQ(o.result, SSS_OK);
      if (v.data) {
        expect_matches_model_up_to_tap_flips(o, 0.0f, v.name);
      } else {
        // fp16 output: half an ulp of the value (2^-11 relative); fp32: the walk's float noise.
        const float tolerance = half ? 9.8e-4f : 1e-5f;
        float worst = 0.0f;
        for (std::size_t i = 0; i < o.gpu.size(); ++i) {
          const float d = std::fabs(o.gpu[i] - o.cpu[i]) / std::max(1e-30f, std::fabs(o.cpu[i]));
          if (o.gpu[i] != o.cpu[i] && !(d <= worst)) worst = d;
        }
        std::printf("%s: largest relative difference from the model %.3g\n", v.name, static_cast<double>(worst));
        EXPECT_LE(worst, tolerance);
      }
      // Background pixels (alpha 0) are (0, 0, 0, 1); translucent ones hold the view.
      EXPECT_EQ(at(o.gpu, 2, 2, 0), 0.0f);
      EXPECT_EQ(at(o.gpu, 2, 2, 3), 1.0f);
      const float inside = at(o.gpu, kW / 2, kH / 2, 0);
      switch (v.view) {
        case SSS_DEBUG_VIEW_MASK: EXPECT_EQ(inside, 1.0f); break;
        case SSS_DEBUG_VIEW_LINEAR_DEPTH: EXPECT_GT(inside, 0.1f); break;
        case SSS_DEBUG_VIEW_FOOTPRINT: EXPECT_GT(inside, 0.0f); break;
        case SSS_DEBUG_VIEW_TAPS: EXPECT_GT(inside, 1.0f); break;
        case SSS_DEBUG_VIEW_ALBEDO: EXPECT_EQ(inside, 1.0f); break;
        default: EXPECT_EQ(inside, 0.0f); break;
      }
    }
  }
}

// The albedo view of a texturing mode: A_post at every pixel the passes run (the floored albedo,
// or its square root), the CPU model's value for value, and (0, 0, 0, 1) where they do not.
TEST_F(DebugViews, TheAlbedoViewShowsWhatThePassesDivideBy) {
  std::vector<float> albedo(static_cast<std::size_t>(kW) * kH * 4, 1.0f);
  for (std::size_t i = 0; i < albedo.size(); ++i) {
    if (i % 4 != 3) albedo[i] = (i / 4) % 3 == 0 ? 0.25f : ((i / 4) % 3 == 1 ? 0.5625f : 0.001f);  // half-exact
  }
  for (const uint32_t mode : {SSS_TEXTURING_POST_SCATTER, SSS_TEXTURING_PRE_AND_POST_SCATTER}) {
    SCOPED_TRACE(mode);
    FilterCase c = view_case(SSS_DEBUG_VIEW_ALBEDO, false);
    c.settings.texturing = mode;
    c.albedo = albedo;
    const FilterOutcome o = run_case(scene_, c);
    ASSERT_EQ(o.result, SSS_OK);
    expect_matches_model_up_to_tap_flips(o, 0.0f, "albedo view");
    const std::size_t i = (static_cast<std::size_t>(kH / 2) * kW + kW / 2);
    const float expected = mode == SSS_TEXTURING_POST_SCATTER ? std::max(albedo[i * 4], 1.0f / 256.0f)
                                                              : std::sqrt(std::max(albedo[i * 4], 1.0f / 256.0f));
    EXPECT_EQ(at(o.gpu, kW / 2, kH / 2, 0), expected);
    EXPECT_EQ(at(o.gpu, 2, 2, 0), 0.0f);
    TearDown();
    SetUp();
  }
}

// The taps view against the passes' own rule: at most the settings' taps, odd, and more where the
// footprint is finer (the footprint and taps views of one frame agree with each other).
TEST_F(DebugViews, TheTapsFollowTheFootprint) {
  const FilterOutcome footprint = run_case(scene_, view_case(SSS_DEBUG_VIEW_FOOTPRINT, false));
  TearDown();
  SetUp();
  const FilterOutcome taps = run_case(scene_, view_case(SSS_DEBUG_VIEW_TAPS, false));
  ASSERT_EQ(footprint.result, SSS_OK);
  ASSERT_EQ(taps.result, SSS_OK);
  int translucent = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      for (int axis = 0; axis < 2; ++axis) {
        const float n = at(taps.gpu, x, y, axis), mm = at(footprint.gpu, x, y, axis);
        if (n == 0.0f) continue;  // left alone
        ++translucent;
        EXPECT_LE(n, 17.0f);
        EXPECT_EQ(std::fmod(n, 2.0f), 1.0f);
        EXPECT_GT(mm, 0.0f);
      }
    }
  }
  EXPECT_GT(translucent, kW * kH);  // both axes of most pixels
}

// The tiles view: the masked path's marks and bands on a frame with translucency in two tiles of
// one row only, where each kind of pixel shows (a marked tile; a tile of its band the passes'
// span crosses; a tile only the inputs draw covers, in that band's row or in another band's column;
// a tile nothing covers). Data: equal value for value with the CPU form of the rule
// (math::write_tile_view), at a rectangle whose size is no multiple of a tile, and at an offset one.
TEST_F(DebugViews, TheTilesViewShowsWhatTheMaskedPathDraws) {
  constexpr int kTile = 16, kBand = 4;  // sss::math::kTileSize, kTileBand (the rule's own numbers)
  constexpr int w = 7 * kTile - 5, h = 5 * kTile + 3;  // partial tiles on the right and the top
  SyntheticScene scene = make_relief_scene(w, h, 5, perspective_matrix(40.0f, 1.5f, 0.1f, 10.0f));
  // Translucent in tile (2, 1) and in tile (4, 1), with (3, 1) between them empty.
  const auto translucent = [&](int x, int y) {
    const int column = x / kTile, row = y / kTile;
    return row == 1 && (column == 2 || (column == 4 && x % kTile == 7 && y % kTile == 9));
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) scene.color[(static_cast<std::size_t>(y) * w + x) * 4 + 3] = translucent(x, y) ? 1.0f : 0.0f;
  }
  const auto pixel = [&](const std::vector<float>& image, int tx, int ty) {
    const std::size_t i = (static_cast<std::size_t>(ty * kTile + 3) * w + static_cast<std::size_t>(tx * kTile + 3)) * 4;
    return std::vector<float>(image.begin() + static_cast<std::ptrdiff_t>(i), image.begin() + static_cast<std::ptrdiff_t>(i + 4));
  };
  for (const bool half : {false, true}) {
    SCOPED_TRACE(half ? "RGBA16F" : "RGBA32F");
    FilterCase c = view_case(SSS_DEBUG_VIEW_TILES, half);
    c.settings.path = SSS_PATH_FRAGMENT;  // any path shows the masked path's tiles
    const FilterOutcome o = run_case(scene, c);
    ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(o.gpu, o.cpu);
    using V = std::vector<float>;
    EXPECT_EQ(pixel(o.gpu, 2, 1), (V{1, 1, 1, 1}));  // marked: the passes and the inputs draw
    EXPECT_EQ(pixel(o.gpu, 4, 1), (V{1, 1, 1, 1}));  // marked by one pixel
    EXPECT_EQ(pixel(o.gpu, 3, 1), (V{1, 1, 0, 1}));  // inside the passes' span of its band
    EXPECT_EQ(pixel(o.gpu, 3, 0), (V{1, 1, 0, 1}));  // same band, another row of tiles
    EXPECT_EQ(pixel(o.gpu, 0, 1), (V{0, 1, 0, 1}));  // the inputs draw's whole rows of the band
    EXPECT_EQ(pixel(o.gpu, 2, kBand), (V{0, 1, 0, 1}));  // another band: the marked columns' span
    EXPECT_EQ(pixel(o.gpu, 0, kBand), (V{0, 0, 0, 1}));  // nothing draws there
    TearDown();
    SetUp();
  }
  // A viewport at an offset: the tiles start at its corner; outside it the output keeps its value.
  FilterCase c = view_case(SSS_DEBUG_VIEW_TILES, false);
  c.viewport = {5, 3, w - 9, h - 7};
  const FilterOutcome o = run_case(scene, c);
  ASSERT_EQ(o.result, SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(o.gpu, o.cpu);
}

TEST_F(DebugViews, BadFramesAreRefusedByNameAndNothingIsDrawn) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene_.projection.data()), SSS_OK);
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.18f);
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  const GLuint color = make_rgba32f(kW, kH, scene_.color);
  const GLuint depth = make_depth32f(kW, kH, scene_.window_depth);
  const std::vector<float> sentinel(static_cast<std::size_t>(kW) * kH * 4, -2.0f);
  const GLuint output = make_rgba32f(kW, kH, sentinel);
  const auto expect_refused = [&](sss_frame f, sss_result code, const char* part) {
    SCOPED_TRACE(part);
    describe_frame(&f, GL_RGBA32F, f.output_texture != 0 ? GL_RGBA32F : 0, GL_DEPTH_COMPONENT32F, kW, kH);
    EXPECT_EQ(sss_apply_frame(sss_, &f), code);
    EXPECT_NE(std::string(sss_last_error(sss_)).find(part), std::string::npos) << sss_last_error(sss_);
    EXPECT_EQ(read_rgba(color, kW, kH), scene_.color);
    EXPECT_EQ(read_rgba(output, kW, kH), sentinel);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  };
  sss_frame f = frame_of(color, depth, output);
  f.debug_view = SSS_DEBUG_VIEW_LAST + 1;
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "frame->debug_view = 8");
  f = frame_of(color, depth);
  f.debug_view = SSS_DEBUG_VIEW_MASK;
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "needs an output_texture");
  f = frame_of(color, depth, output);
  f.debug_view = SSS_DEBUG_VIEW_TAPS;
  f.flags = SSS_FRAME_REGION;
  f.region[2] = kW;
  f.region[3] = kH;
  expect_refused(f, SSS_ERROR_INVALID_ARGUMENT, "SSS_FRAME_REGION");
  f = frame_of(color, depth, output);
  f.debug_view = SSS_DEBUG_VIEW_TILES;
  const sss_stencil stencil = {depth, 1, 0xFF};
  f.stencil = &stencil;
  expect_refused(f, SSS_ERROR_UNSUPPORTED, "SSS_DEBUG_VIEW_TILES) with a stencil");
  s.mode = SSS_MODE_CROSS_BILATERAL;
  ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
  f = frame_of(color, depth, output);
  f.debug_view = SSS_DEBUG_VIEW_MASK;
  expect_refused(f, SSS_ERROR_UNSUPPORTED, "cross-bilateral");
}

}  // namespace
}  // namespace sss_test
