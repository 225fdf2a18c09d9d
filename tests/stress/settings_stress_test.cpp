// Settings and kernels at their extremes: width 0, denormal and huge; strength and falloff at 0, 1
// and between (falloff 0 hits the 0.001 guard); every tap count; random settings every frame; and
// everything beyond the documented ranges rejected with the previous settings kept.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <limits>

#include "stress_support.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, 1.3f, 0.1f, 10.0f);

sss_settings base_settings() {
  sss_settings s;
  sss_default_settings(&s);
  return s;
}

using SettingsStress = StressTest;

TEST_F(SettingsStress, ExtremeWidthsStrengthsAndFalloffs) {
  category_ = "settings";
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  const float widths[] = {0.0f,
                          -0.0f,
                          std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::min(),
                          1e-30f,
                          1e-6f,
                          0.0015f,
                          0.06f,
                          1.0f,
                          1e3f,
                          1e6f};
  const float units[][3] = {{0.0f, 0.0f, 0.0f},
                            {1.0f, 1.0f, 1.0f},
                            {0.0f, 0.5f, 1.0f},
                            {std::numeric_limits<float>::denorm_min(), 1e-7f, 0.999999f}};
  const StressFrame frame = relief_frame(23, 17, 5, kCamera, 0.5, 2.0, DepthFormat::depth32f);
  for (float width : widths) {
    for (const auto& strength : units) {
      for (const auto& falloff : units) {
        for (int samples : {3, 17, 65}) {
          for (uint32_t flags : {0u, SSS_FOLLOW_SURFACE}) {
            sss_settings s = base_settings();
            s.world_units_per_mm = width;
            for (int c = 0; c < 3; ++c) {
              s.strength[c] = strength[c];
              s.falloff[c] = falloff[c];
            }
            s.taps = samples;
            s.flags = flags;
            ASSERT_EQ(set_settings(s), SSS_OK);
            Expectations e;
            e.identity = width == 0.0f || (strength[0] == 0.0f && strength[1] == 0.0f && strength[2] == 0.0f);
            SCOPED_TRACE(::testing::Message() << "width " << width << " strength " << strength[0] << ' ' << strength[1]
                                              << ' ' << strength[2] << " falloff " << falloff[0] << ' ' << falloff[1]
                                              << ' ' << falloff[2] << " samples " << samples << " flags " << flags);
            ASSERT_TRUE(run_and_check(frame, e));
          }
        }
      }
    }
  }
}

TEST_F(SettingsStress, EveryTapCountKeepsAFlatImageFlatAndItsKernelSumsToOne) {
  category_ = "kernel";
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  StressFrame flat = relief_frame(19, 13, 1, kCamera, 1.0, 1.0, DepthFormat::depth32f);
  for (std::size_t i = 0; i < flat.color.size(); i += 4) {
    flat.color[i] = 0.7f;
    flat.color[i + 1] = 0.35f;
    flat.color[i + 2] = 123.0f;
  }
  const float falloffs[] = {0.0f, 0.001f, 0.3f, 1.0f};
  for (int samples = SSS_MIN_TAPS; samples <= SSS_MAX_TAPS; samples += 2) {
    for (float falloff : falloffs) {
      sss_settings s = base_settings();
      s.world_units_per_mm = 0.3f;
      s.taps = samples;
      s.strength[0] = s.strength[1] = s.strength[2] = 1.0f;
      s.falloff[0] = falloff;
      s.falloff[1] = 1.0f - falloff;
      s.falloff[2] = 0.5f;
      ASSERT_EQ(set_settings(s), SSS_OK);
      Expectations e;
      e.flat = true;
      SCOPED_TRACE(::testing::Message() << "samples " << samples << " falloff " << falloff);
      ASSERT_TRUE(run_and_check(flat, e));
      // The kernel the frame used, from the GL-free API: weights >= 0, each channel sums to 1.
      std::vector<float> taps(static_cast<std::size_t>(samples) * 4);
      ASSERT_EQ(sss_kernel_separable(samples, s.strength, s.falloff, taps.data()), SSS_OK);
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int t = 0; t < samples; ++t) {
          const float w = taps[static_cast<std::size_t>(t) * 4 + c];
          check(std::isfinite(w) && w >= 0.0f, "weight " + std::to_string(w));
          sum += w;
        }
        check(std::fabs(sum - 1.0) <= 1e-6,
              "kernel sum " + std::to_string(sum) + " for " + std::to_string(samples) + " taps");
      }
    }
  }
}

TEST_F(SettingsStress, RandomSettingsEveryFrame) {
  category_ = "settings";
  const uint32_t seed = stress_seed(0x5e771265u);
  std::printf("seed %u (SSS_STRESS_SEED)\n", seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> pick(0, 9);
  ASSERT_EQ(sss_set_camera(sss_, kCamera.data()), SSS_OK);
  // A unit value: mostly uniform, sometimes an end or a denormal.
  auto unit_value = [&]() {
    switch (pick(rng)) {
      case 0:
        return 0.0f;
      case 1:
        return 1.0f;
      case 2:
        return std::numeric_limits<float>::denorm_min();
      default:
        return unit(rng);
    }
  };
  for (int frame = 0; frame < 120; ++frame) {
    sss_settings s = base_settings();
    s.world_units_per_mm = std::pow(10.0f, -8.0f + 14.0f * unit(rng)) * (pick(rng) == 0 ? 0.0f : 1.0f);
    for (int c = 0; c < 3; ++c) {
      s.strength[c] = unit_value();
      s.falloff[c] = unit_value();
    }
    s.taps = 3 + 2 * std::uniform_int_distribution<int>(0, 31)(rng);
    s.flags = pick(rng) < 7 ? SSS_FOLLOW_SURFACE : 0u;
    ASSERT_EQ(set_settings(s), SSS_OK);
    const int w = 1 + pick(rng) * 3, h = 1 + pick(rng) * 2;
    const DepthFormat formats[] = {DepthFormat::depth32f, DepthFormat::depth24_stencil8, DepthFormat::r32f};
    StressFrame f =
        relief_frame(w, h, static_cast<uint32_t>(rng()), kCamera, 0.3, 3.0, formats[frame % 3], -2.0f, 50.0f);
    f.half_color = frame % 2 == 0;
    f.use_stencil = f.depth_format == DepthFormat::depth24_stencil8 && pick(rng) < 5;
    f.separate_output = pick(rng) < 3;
    Expectations e;
    e.identity = s.world_units_per_mm == 0.0f || (s.strength[0] == 0.0f && s.strength[1] == 0.0f && s.strength[2] == 0.0f);
    SCOPED_TRACE(::testing::Message() << "frame " << frame << " width " << s.world_units_per_mm << " samples " << s.taps);
    ASSERT_TRUE(run_and_check(f, e));
  }
}

TEST_F(SettingsStress, ValuesBeyondTheRangesAreRejectedAndThePreviousSettingsStay) {
  category_ = "settings-rejected";
  sss_settings good = base_settings();
  good.world_units_per_mm = 0.01f;
  good.taps = 21;
  ASSERT_EQ(sss_set_settings(sss_, &good), SSS_OK);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
  const float bad_widths[] = {
      -std::numeric_limits<float>::denorm_min(), -1.0f, std::nextafter(1e6f, inf), 1e30f, inf, -inf, nan};
  const float bad_units[] = {
      -std::numeric_limits<float>::denorm_min(), -1.0f, std::nextafter(1.0f, 2.0f), 2.0f, inf, -inf, nan};
  auto expect_rejected = [&](const sss_settings& s, const char* what) {
    ++tally_.cases;
    check(sss_set_settings(sss_, &s) == SSS_ERROR_INVALID_ARGUMENT, std::string(what) + " accepted");
    sss_settings now;
    now.struct_size = sizeof now;
    check(sss_get_settings(sss_, &now) == SSS_OK && now.world_units_per_mm == good.world_units_per_mm && now.taps == good.taps &&
              now.strength[1] == good.strength[1] && now.falloff[2] == good.falloff[2],
          std::string(what) + ": the previous settings did not stay");
  };
  for (float v : bad_widths) {
    sss_settings s = good;
    s.world_units_per_mm = v;
    expect_rejected(s, ("width " + std::to_string(v)).c_str());
  }
  for (float v : bad_units) {
    for (int c = 0; c < 3; ++c) {
      sss_settings s = good;
      s.strength[c] = v;
      expect_rejected(s, "strength");
      s = good;
      s.falloff[c] = v;
      expect_rejected(s, "falloff");
    }
  }
  for (int samples = -70; samples <= 70; ++samples) {
    sss_settings s = good;
    s.taps = samples;
    const bool valid = samples >= SSS_MIN_TAPS && samples <= SSS_MAX_TAPS && samples % 2 != 0;
    if (valid) {
      ++tally_.cases;
      check(sss_set_settings(sss_, &s) == SSS_OK, "samples " + std::to_string(samples) + " rejected");
      ASSERT_EQ(sss_set_settings(sss_, &good), SSS_OK);
    } else {
      expect_rejected(s, ("samples " + std::to_string(samples)).c_str());
    }
  }
  for (int32_t samples : {INT_MIN, INT_MIN + 1, INT_MAX, INT_MAX - 1, 1 << 30}) {
    sss_settings s = good;
    s.taps = samples;
    expect_rejected(s, "samples extreme");
  }
  for (uint32_t bit = 1; bit != 0; bit <<= 1) {
    sss_settings s = good;
    s.flags = bit;
    if ((bit & SSS_SETTINGS_ALL_FLAGS) != 0) continue;
    expect_rejected(s, "flags");
  }
  for (uint32_t size : {0u, 1u, static_cast<uint32_t>(sizeof(sss_settings)) - 1u,
                        static_cast<uint32_t>(sizeof(sss_settings)) + 1u, 0xFFFFFFFFu}) {
    sss_settings s = good;
    s.struct_size = size;
    expect_rejected(s, "struct_size");
  }
  // The GL-free kernel API validates the same way and writes nothing when it fails.
  std::vector<float> taps(SSS_MAX_TAPS * 4, 42.0f);
  const float ok[3] = {0.5f, 0.5f, 0.5f};
  for (float v : bad_units) {
    for (int c = 0; c < 3; ++c) {
      float bad[3] = {0.5f, 0.5f, 0.5f};
      bad[c] = v;
      ++tally_.cases;
      check(sss_kernel_separable(17, bad, ok, taps.data()) == SSS_ERROR_INVALID_ARGUMENT, "kernel strength");
      ++tally_.cases;
      check(sss_kernel_separable(17, ok, bad, taps.data()) == SSS_ERROR_INVALID_ARGUMENT, "kernel falloff");
    }
  }
  for (int32_t samples : {INT_MIN, -1, 0, 1, 2, 4, 64, 66, 67, INT_MAX}) {
    ++tally_.cases;
    check(sss_kernel_separable(samples, ok, ok, taps.data()) == SSS_ERROR_INVALID_ARGUMENT, "kernel samples");
  }
  ++tally_.cases;
  check(sss_kernel_separable(17, nullptr, ok, taps.data()) == SSS_ERROR_INVALID_ARGUMENT, "NULL strength");
  ++tally_.cases;
  check(sss_kernel_separable(17, ok, ok, nullptr) == SSS_ERROR_INVALID_ARGUMENT, "NULL output");
  for (float t : taps) check(t == 42.0f, "a failing sss_kernel_separable wrote its output");
}

}  // namespace
}  // namespace sss_test
