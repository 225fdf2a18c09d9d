// Images at their extremes: 1x1, 1xN, Nx1, odd sizes, 8192 wide, sub-viewports at the edges, every
// colour and depth format; colours near fp16's largest value (no overflow to Inf in the weighted
// sum), zeros, denormals, negative values and RGBA32F values beyond fp16's range; depth 0, 1,
// negative, infinite and NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "stress_support.hpp"
#include "synthetic_scene.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

const sss::math::Matrix4 kCamera = perspective_matrix(50.0f, 1.0f, 0.1f, 100.0f);

class ImageStress : public StressTest {
 protected:
  void SetUp() override {
    StressTest::SetUp();
    if (HasFatalFailure()) return;
    set_wide_kernel(kCamera, 0.08f, 25);  // taps reach the borders of small images
    add_second_profile(1.5f);              // for the frames with profile ids
  }
};

TEST_F(ImageStress, TinyOddAndVeryWideImagesInEveryFormat) {
  category_ = "images";
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  std::vector<std::pair<int, int>> sizes = {{1, 1}, {1, 2},  {2, 1},   {2, 2},   {1, 37}, {53, 1},
                                            {3, 3}, {7, 13}, {33, 17}, {127, 3}, {4, 65}};
  if (max_size >= 8192) {
    sizes.push_back({8192, 1});
    sizes.push_back({1, 8192});
  } else {
    std::printf("GL_MAX_TEXTURE_SIZE %d: 8192-wide images skipped\n", max_size);
  }
  const DepthFormat formats[] = {
      DepthFormat::depth16,           DepthFormat::depth24, DepthFormat::depth32f, DepthFormat::depth24_stencil8,
      DepthFormat::depth32f_stencil8, DepthFormat::r16f,    DepthFormat::r32f};
  int k = 0;
  for (const auto& size : sizes) {
    for (DepthFormat format : formats) {
      ++k;
      StressFrame f = relief_frame(size.first, size.second, static_cast<uint32_t>(k), kCamera, 0.5, 2.0, format);
      f.half_color = k % 2 == 0;
      f.use_stencil =
          (format == DepthFormat::depth24_stencil8 || format == DepthFormat::depth32f_stencil8) && k % 3 != 0;
      f.separate_output = k % 4 == 1;
      if (k % 5 == 2) f.profile_ids = banded_ids(size.first, size.second);  // per-pixel profiles and objects
      SCOPED_TRACE(::testing::Message() << size.first << "x" << size.second << " " << depth_format_name(format)
                                        << (f.half_color ? " RGBA16F" : " RGBA32F") << (f.use_stencil ? " stencil" : "")
                                        << (f.separate_output ? " separate output" : "")
                                        << (f.profile_ids.empty() ? "" : " profile ids"));
      Expectations e;
      e.flat = size.first == 1 && size.second == 1;  // every tap is the pixel itself
      ASSERT_TRUE(run_and_check(f, e));
      // The same frame through viewports at the corners and edges, one texel wide or tall.
      const int w = size.first, h = size.second;
      const int32_t viewports[][4] = {
          {0, 0, 1, 1}, {w - 1, h - 1, 1, 1}, {0, 0, w, 1}, {0, h - 1, w, 1}, {w / 2, h / 2, w - w / 2, h - h / 2}};
      for (const auto& vp : viewports) {
        if (k % 3 != 0) break;  // a third of the cases; the rest ran whole
        std::memcpy(f.viewport, vp, sizeof f.viewport);
        SCOPED_TRACE(::testing::Message() << "viewport " << vp[0] << "," << vp[1] << " " << vp[2] << "x" << vp[3]);
        ASSERT_TRUE(run_and_check(f, e));
      }
    }
  }
}

StressFrame flat_frame(int width, int height, const float rgba[4], bool half) {
  StressFrame f = relief_frame(width, height, 1, kCamera, 1.0, 1.0, DepthFormat::depth32f);
  for (std::size_t i = 0; i < f.color.size(); ++i) f.color[i] = rgba[i % 4];
  f.half_color = half;
  return f;
}

TEST_F(ImageStress, ColoursNearTheLimitsStayFiniteAndInRange) {
  category_ = "colours";
  const float big = 65504.0f, denorm16 = 5.9604645e-08f, denorm32 = std::numeric_limits<float>::denorm_min();
  // Flat images: each stays flat (65504 must not overflow to Inf in the weighted sum).
  const float flats[][4] = {{big, big, big, 1.0f},
                            {-big, big, 0.0f, 1.0f},
                            {0.0f, 0.0f, 0.0f, 1.0f},
                            {denorm16, denorm16, denorm16, 1.0f},
                            {denorm32, 1e-30f, -denorm32, 1.0f},
                            {65000.0f, 1.0f, 0.5f, 1.0f}};
  for (const auto& rgba : flats) {
    for (bool half : {true, false}) {
      for (int samples : {3, 25, 65}) {
        sss_settings s;
        sss_default_settings(&s);
        s.world_units_per_mm = 0.08f;
        s.strength[0] = s.strength[1] = s.strength[2] = 1.0f;
        s.taps = samples;
        ASSERT_EQ(set_settings(s), SSS_OK);
        SCOPED_TRACE(::testing::Message() << "flat " << rgba[0] << " " << rgba[1] << " " << rgba[2]
                                          << (half ? " RGBA16F" : " RGBA32F") << " samples " << samples);
        Expectations e;
        e.flat = true;
        ASSERT_TRUE(run_and_check(flat_frame(24, 16, rgba, half), e));
      }
    }
  }
  // Patterns: the largest value next to zeros and to its negative, checkerboards and stripes; in
  // RGBA32F also values beyond fp16's range (the RGBA16F intermediate overflows there: those pixels
  // keep their own value and do not spread).
  const float patterns[][2] = {{big, 0.0f},
                               {big, -big},
                               {denorm16, 0.0f},
                               {denorm32, -denorm32},
                               {1e5f, 0.0f},
                               {1e30f, 1.0f},
                               {std::numeric_limits<float>::max(), 0.0f},
                               {std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()}};
  int k = 0;
  for (const auto& p : patterns) {
    for (int layout = 0; layout < 3; ++layout) {
      for (bool half : {true, false}) {
        ++k;
        StressFrame f = relief_frame(31, 21, static_cast<uint32_t>(k), kCamera, 0.5, 2.0,
                                     k % 2 ? DepthFormat::depth32f : DepthFormat::r32f);
        f.half_color = half;
        for (int y = 0; y < f.height; ++y) {
          for (int x = 0; x < f.width; ++x) {
            const bool first = layout == 0 ? (x + y) % 2 == 0 : layout == 1 ? x % 5 == 0 : (x == 15 && y == 10);
            for (int c = 0; c < 3; ++c)
              f.color[(static_cast<std::size_t>(y) * f.width + x) * 4 + c] = first ? p[0] : p[1];
          }
        }
        f.separate_output = k % 3 == 0;
        SCOPED_TRACE(::testing::Message() << "pattern " << p[0] << " / " << p[1] << " layout " << layout
                                          << (half ? " RGBA16F" : " RGBA32F"));
        ASSERT_TRUE(run_and_check(f));
      }
    }
  }
  // Random values of every magnitude, including the extremes, per channel.
  const uint32_t seed = stress_seed(0xc0101235u);
  std::printf("seed %u (SSS_STRESS_SEED)\n", seed);
  std::mt19937 rng(seed);
  const std::vector<float> extremes = extreme_floats();
  std::uniform_int_distribution<std::size_t> pick(0, extremes.size() - 1);
  for (int trial = 0; trial < 40; ++trial) {
    StressFrame f = relief_frame(17, 11, static_cast<uint32_t>(rng()), kCamera, 0.5, 2.0, DepthFormat::depth32f);
    f.half_color = trial % 2 == 0;
    for (std::size_t i = 0; i < f.color.size(); ++i) {
      if (rng() % 4 == 0) f.color[i] = extremes[pick(rng)];
    }
    SCOPED_TRACE(::testing::Message() << "random trial " << trial);
    ASSERT_TRUE(run_and_check(f));
  }
}

TEST_F(ImageStress, DepthValuesAtAndBeyondTheirLimits) {
  category_ = "depth";
  const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
  // Hardware depth (the upload clamps what a depth format cannot hold).
  const float window[] = {
      0.0f, 1.0f, 0.5f, std::numeric_limits<float>::denorm_min(), std::nextafter(1.0f, 0.0f), -1.0f, 2.0f,
      inf,  -inf, nan};
  // Linear view distance: anything at all; with a perspective camera, a distance that is not
  // > 0 and finite gives no usable clip w, and the pixel keeps its value.
  const float linear[] = {0.0f,   -0.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
                          1e-30f, 1.0f,  1e30f, std::numeric_limits<float>::max(),
                          inf,    -inf,  nan,   65504.0f,
                          1e5f};
  int k = 0;
  for (DepthFormat format :
       {DepthFormat::depth16, DepthFormat::depth24, DepthFormat::depth32f, DepthFormat::depth24_stencil8,
        DepthFormat::depth32f_stencil8, DepthFormat::r16f, DepthFormat::r32f}) {
    const bool lin = is_linear(format);
    const std::vector<float> values = lin ? std::vector<float>(std::begin(linear), std::end(linear))
                                          : std::vector<float>(std::begin(window), std::end(window));
    for (float v : values) {
      for (int layout = 0; layout < 3; ++layout) {
        ++k;
        StressFrame f = relief_frame(19, 13, static_cast<uint32_t>(k), kCamera, 0.5, 2.0, format);
        std::vector<bool> bad(f.depth.size(), false);
        for (std::size_t i = 0; i < f.depth.size(); ++i) {
          const int x = static_cast<int>(i % f.width), y = static_cast<int>(i / f.width);
          const bool hit = layout == 0 ? true : layout == 1 ? (x + y) % 3 == 0 : (x == 9 && y == 6);
          if (!hit) continue;
          f.depth[i] = v;
          bad[i] = true;
        }
        Expectations e;
        if (format == DepthFormat::r32f && !(v > 0.0f && std::isfinite(v))) {
          e.kept = [bad](std::size_t i) { return static_cast<bool>(bad[i]); };
        }
        SCOPED_TRACE(::testing::Message() << depth_format_name(format) << " depth " << v << " layout " << layout);
        ASSERT_TRUE(run_and_check(f, e));
      }
    }
  }
}

}  // namespace
}  // namespace sss_test
