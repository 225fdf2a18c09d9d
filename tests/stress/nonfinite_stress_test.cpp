// The non-finite input policies of sss_apply_frame, each with frames that would show a NaN or an
// infinity spreading (tests/gl/invariants_test.cpp NonFinitePixelsDoNotSpread has the basic case):
//   - a pixel whose colour or alpha is NaN or infinite keeps its value, and a neighbour that is
//     counts as the centre's colour: every finite pixel of a flat image stays flat (and finite),
//     for each channel, each kind of value, at corners, edges, in rows, under the stencil, in
//     RGBA16F and RGBA32F, written back or into a separate output;
//   - a depth that gives no usable clip w (NaN, infinite, zero, negative distance; the far plane of
//     an infinite projection) leaves the pixel as it is, and a tap at such a depth counts as the
//     centre's colour;
//   - alpha above 1 counts as 1; alpha 0, -0 or negative leaves the pixel as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "stress_support.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
constexpr int kW = 32, kH = 24;

class NonFiniteStress : public StressTest {
 protected:
  void SetUp() override {
    StressTest::SetUp();
    if (HasFatalFailure()) return;
    set_wide_kernel(kCamera, 0.1f, 33);  // taps reach across the whole image
    add_second_profile(2.0f);            // for the frames with profile ids
  }

  // A plane facing the camera at 1.5, one colour everywhere.
  StressFrame plane(DepthFormat format) {
    StressFrame f = relief_frame(kW, kH, 1, kCamera, 1.5, 1.5, format);
    for (std::size_t i = 0; i < f.color.size(); i += 4) {
      f.color[i] = 0.5f;
      f.color[i + 1] = 0.3f;
      f.color[i + 2] = 0.2f;
      f.color[i + 3] = 1.0f;
    }
    return f;
  }
};

TEST_F(NonFiniteStress, NonFiniteColourOrAlphaNeverSpreads) {
  category_ = "non-finite colour";
  const float values[] = {std::nanf(""), -std::nanf(""), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  const int places[][2] = {{0, 0}, {kW - 1, kH - 1}, {kW - 1, 11}, {16, 0}, {16, 12}};
  Expectations flat;
  flat.flat = true;
  int k = 0;
  for (float v : values) {
    for (int channel = 0; channel < 4; ++channel) {
      for (const auto& p : places) {
        ++k;
        StressFrame f = plane(k % 2 ? DepthFormat::depth32f : DepthFormat::depth24_stencil8);
        f.color[(static_cast<std::size_t>(p[1]) * kW + p[0]) * 4 + channel] = v;
        f.half_color = k % 2 == 0;
        f.separate_output = k % 3 == 0;
        f.use_stencil = f.depth_format == DepthFormat::depth24_stencil8 && k % 4 < 2;
        if (k % 5 == 1) f.profile_ids = banded_ids(kW, kH);  // per-pixel profiles: a flat plane stays flat
        SCOPED_TRACE(::testing::Message()
                     << v << " in channel " << channel << " at " << p[0] << "," << p[1]
                     << (f.half_color ? " RGBA16F" : " RGBA32F") << (f.separate_output ? " separate" : "")
                     << (f.use_stencil ? " stencil" : "") << (f.profile_ids.empty() ? "" : " profile ids"));
        ASSERT_TRUE(run_and_check(f, flat));
      }
    }
  }
  // Whole rows and columns, and everything but one pixel.
  for (int layout = 0; layout < 3; ++layout) {
    for (bool half : {true, false}) {
      StressFrame f = plane(DepthFormat::depth32f);
      f.half_color = half;
      for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
          const bool bad = layout == 0 ? y == 7 : layout == 1 ? x == 20 : !(x == 5 && y == 5);
          if (bad)
            f.color[(static_cast<std::size_t>(y) * kW + x) * 4 + static_cast<std::size_t>((x + y) % 3)] = std::nanf("");
        }
      }
      SCOPED_TRACE(::testing::Message() << "layout " << layout << (half ? " RGBA16F" : " RGBA32F"));
      ASSERT_TRUE(run_and_check(f, flat));
    }
  }
}

TEST_F(NonFiniteStress, UnusableDepthNeverSpreads) {
  category_ = "non-finite depth";
  const float values[] = {
      std::nanf(""), std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 0.0f, -0.0f,
      -1.5f};
  Expectations e;
  e.flat = true;
  for (float v : values) {
    for (int layout = 0; layout < 3; ++layout) {
      StressFrame f = plane(DepthFormat::r32f);
      std::vector<bool> bad(f.depth.size(), false);
      for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
          const bool hit = layout == 0 ? (x == 16 && y == 12) : layout == 1 ? y == 3 : (x * 7 + y * 3) % 5 == 0;
          if (!hit) continue;
          const std::size_t i = static_cast<std::size_t>(y) * kW + x;
          f.depth[i] = v;
          bad[i] = true;
        }
      }
      e.kept = [bad](std::size_t i) { return static_cast<bool>(bad[i]); };
      SCOPED_TRACE(::testing::Message() << "linear depth " << v << " layout " << layout);
      ASSERT_TRUE(run_and_check(f, e));
    }
  }
  // Hardware depth 1 under an infinite far plane: clip w is infinite there.
  sss::math::Matrix4 infinite = kCamera;
  infinite[10] = -1.0f;
  infinite[14] = -0.2f;
  ASSERT_EQ(sss_set_camera(sss_, infinite.data()), SSS_OK);
  StressFrame f = relief_frame(kW, kH, 1, infinite, 1.5, 1.5, DepthFormat::depth32f);
  for (std::size_t i = 0; i < f.color.size(); i += 4) {
    f.color[i] = 0.5f;
    f.color[i + 1] = 0.3f;
    f.color[i + 2] = 0.2f;
    f.color[i + 3] = 1.0f;
  }
  std::vector<bool> far(f.depth.size(), false);
  for (std::size_t i = 0; i < f.depth.size(); i += 5) {
    f.depth[i] = 1.0f;
    far[i] = true;
  }
  e.kept = [far](std::size_t i) { return static_cast<bool>(far[i]); };
  ASSERT_TRUE(run_and_check(f, e));
}

TEST_F(NonFiniteStress, AlphaAboveOneCountsAsOneAndNonPositiveAlphaKeepsThePixel) {
  category_ = "alpha";
  const StressFrame base = relief_frame(kW, kH, 9, kCamera, 0.5, 2.0, DepthFormat::depth32f);
  StressFrame one = base, above = base;
  for (std::size_t i = 3; i < one.color.size(); i += 4) {
    one.color[i] = 1.0f;
    above.color[i] = (i / 4) % 2 ? 7.0f : 65504.0f;
  }
  for (bool half : {true, false}) {
    one.half_color = above.half_color = half;
    const StressOutcome a = run(one), b = run(above);
    ASSERT_TRUE(check_invariants(one, a, {}));
    ASSERT_TRUE(check_invariants(above, b, {}));
    for (std::size_t i = 0; i < a.output.size(); ++i) {
      if (i % 4 == 3) continue;
      check(std::memcmp(&a.output[i], &b.output[i], sizeof(float)) == 0,
            "alpha above 1 did not count as 1 at component " + std::to_string(i));
    }
  }
  const float non_positive[] = {0.0f, -0.0f, -std::numeric_limits<float>::denorm_min(), -0.5f, -65504.0f};
  for (float alpha : non_positive) {
    StressFrame f = base;
    for (std::size_t i = 3; i < f.color.size(); i += 8) f.color[i] = alpha;  // every other pixel
    SCOPED_TRACE(::testing::Message() << "alpha " << alpha);
    ASSERT_TRUE(run_and_check(f));  // the invariants keep pixels with alpha not > 0 bit for bit
  }
}

}  // namespace
}  // namespace sss_test
