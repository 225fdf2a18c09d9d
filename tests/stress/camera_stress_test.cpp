// Cameras at their extremes: a tiny near plane, a huge or infinite far plane, reversed-Z, fields of
// view near 0 and 180 degrees, extreme aspects, orthographic from tiny to huge, off-centre, the
// [0, 1] clip range; singular and unsupported matrices rejected with the old camera kept; and
// random matrices, which are either rejected or give finite frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "stress_support.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

using sss::math::Matrix4;

Matrix4 perspective(double fovy_degrees, double aspect, double near_plane, double far_plane) {
  const double f = 1.0 / std::tan(fovy_degrees * 3.14159265358979323846 / 360.0);
  Matrix4 m{};
  m[0] = static_cast<float>(f / aspect);
  m[5] = static_cast<float>(f);
  m[11] = -1.0f;
  if (std::isinf(far_plane)) {
    m[10] = -1.0f;
    m[14] = static_cast<float>(-2.0 * near_plane);
  } else {
    m[10] = static_cast<float>((far_plane + near_plane) / (near_plane - far_plane));
    m[14] = static_cast<float>(2.0 * far_plane * near_plane / (near_plane - far_plane));
  }
  return m;
}

// Reversed-Z for the [0, 1] clip range (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)): near -> 1,
// far -> 0; infinite far: m10 = 0, m14 = near.
Matrix4 reversed_zero_to_one(double fovy_degrees, double aspect, double near_plane, double far_plane) {
  Matrix4 m = perspective(fovy_degrees, aspect, near_plane, 1.0);
  if (std::isinf(far_plane)) {
    m[10] = 0.0f;
    m[14] = static_cast<float>(near_plane);
  } else {
    m[10] = static_cast<float>(near_plane / (far_plane - near_plane));
    m[14] = static_cast<float>(far_plane * near_plane / (far_plane - near_plane));
  }
  return m;
}

Matrix4 off_centre(Matrix4 m, float dx, float dy) {
  m[8] = dx;
  m[9] = dy;
  return m;
}

struct Camera {
  const char* name;
  Matrix4 m;
  double near_d, far_d;  // where the scene is put
  bool zero_to_one;
};

std::vector<Camera> cameras() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Camera> list = {
      {"default", perspective(45, 1.5, 0.1, 100), 0.5, 3, false},
      {"near 1e-6", perspective(60, 1, 1e-6, 10), 1e-5, 2, false},
      {"near 1e-7 far 1e7", perspective(60, 1, 1e-7, 1e7), 0.01, 5e6, false},
      {"far 1e9", perspective(60, 1, 0.1, 1e9), 1, 1e8, false},
      {"infinite far", perspective(60, 1.78, 0.05, inf), 0.1, 1e6, false},
      {"infinite far, scene at 1e20", perspective(60, 1, 0.05, inf), 1e19, 1e20, false},
      {"reversed-Z [0,1]", reversed_zero_to_one(50, 1, 0.1, 1000), 0.2, 500, true},
      {"reversed-Z [0,1] infinite", reversed_zero_to_one(50, 1, 0.01, inf), 0.02, 1e5, true},
      {"fov 1e-4 deg", perspective(1e-4, 1, 10, 1e4), 100, 1000, false},
      {"fov 0.01 deg", perspective(0.01, 1, 1, 1e5), 100, 1e4, false},
      {"fov 179 deg", perspective(179, 1, 0.01, 10), 0.02, 5, false},
      {"fov 179.99 deg", perspective(179.99, 1, 0.01, 10), 0.02, 5, false},
      {"aspect 1e-3", perspective(60, 1e-3, 0.1, 10), 0.5, 5, false},
      {"aspect 1e3", perspective(60, 1e3, 0.1, 10), 0.5, 5, false},
      {"off-centre", off_centre(perspective(45, 1, 0.1, 10), 0.9f, -0.9f), 0.5, 5, false},
      {"far off-centre", off_centre(perspective(45, 1, 0.1, 10), -5.0f, 7.0f), 0.5, 5, false},
      {"mirrored x",
       [] {
         Matrix4 m = perspective(45, 1, 0.1, 10);
         m[0] = -m[0];
         return m;
       }(),
       0.5, 5, false},
      {"ortho 1e-4", orthographic_matrix(1e-4f, 1e-4f, 0.1f, 10.0f), 0.5, 5, false},
      {"ortho 1", orthographic_matrix(1.0f, 0.5f, -5.0f, 5.0f), -4, 4, false},
      {"ortho 1e4", orthographic_matrix(1e4f, 1e4f, 1.0f, 1e6f), 10, 1e5, false},
      {"ortho off-centre",
       [] {
         Matrix4 m = orthographic_matrix(2, 2, 0.1f, 10);
         m[12] = 0.7f;
         m[13] = -3.0f;
         return m;
       }(),
       0.5, 5, false},
  };
  return list;
}

using CameraStress = StressTest;

TEST_F(CameraStress, ExtremeCamerasGiveFiniteFramesWithinRange) {
  category_ = "cameras";
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.02f;
  for (const Camera& cam : cameras()) {
    SCOPED_TRACE(cam.name);
    ASSERT_EQ(sss_set_camera(sss_, cam.m.data()), SSS_OK) << sss_last_error(sss_);
    for (DepthFormat format : {DepthFormat::depth32f, DepthFormat::depth24_stencil8, DepthFormat::r32f}) {
      for (float width : {1e-6f, 0.02f, 50.0f}) {
        s.world_units_per_mm = std::min(1e6f, width * static_cast<float>(cam.far_d > 1e3 ? cam.far_d * 1e-3 : 1.0));
        ASSERT_EQ(set_settings(s), SSS_OK);
        StressFrame f = relief_frame(21, 15, 7, cam.m, cam.near_d, cam.far_d, format);
        if (cam.zero_to_one && !is_linear(format)) {
          for (std::size_t i = 0; i < f.depth.size(); ++i) {
            // relief_frame wrote (ndc + 1) / 2; this camera's depth is ndc itself.
            f.depth[i] = 2.0f * f.depth[i] - 1.0f;
          }
          f.flags = SSS_FRAME_DEPTH_ZERO_TO_ONE;
        }
        SCOPED_TRACE(::testing::Message() << depth_format_name(format) << " width " << s.world_units_per_mm);
        ASSERT_TRUE(run_and_check(f));
      }
    }
  }
}

TEST_F(CameraStress, SingularAndUnsupportedMatricesAreRejectedAndTheOldCameraStays) {
  category_ = "cameras-rejected";
  const Matrix4 good = perspective(45, 1, 0.1, 10);
  ASSERT_EQ(sss_set_camera(sss_, good.data()), SSS_OK);
  const StressFrame frame = relief_frame(9, 7, 2, good, 0.5, 5, DepthFormat::depth32f);
  const StressOutcome reference = run(frame);
  auto expect = [&](const Matrix4& m, sss_result code, const std::string& what) {
    ++tally_.cases;
    check(sss_set_camera(sss_, m.data()) == code,
          what + ": expected " + sss_result_string(code) + ", got " + sss_last_error(sss_));
  };
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity()};
  for (int i = 0; i < 16; ++i) {
    for (float v : specials) {
      Matrix4 m = good;
      m[static_cast<std::size_t>(i)] = v;
      expect(m, SSS_ERROR_INVALID_ARGUMENT, "element " + std::to_string(i) + " = " + std::to_string(v));
    }
  }
  Matrix4 m{};
  expect(m, SSS_ERROR_INVALID_ARGUMENT, "all zero");
  for (int i : {0, 5}) {
    m = good;
    m[static_cast<std::size_t>(i)] = 0.0f;
    expect(m, SSS_ERROR_INVALID_ARGUMENT, "zero scale " + std::to_string(i));
  }
  m = good;
  m[10] = 0.0f;
  m[14] = 0.0f;
  expect(m, SSS_ERROR_INVALID_ARGUMENT, "depth row zero");
  m = good;
  m[11] = 0.0f;
  m[15] = 0.0f;
  expect(m, SSS_ERROR_INVALID_ARGUMENT, "w row zero");
  m = good;
  m[10] = 2.0f;
  m[14] = 0.0f;
  m[11] = 0.0f;
  m[15] = 0.0f;
  expect(m, SSS_ERROR_INVALID_ARGUMENT, "w = 0 everywhere");
  m = good;
  m[10] = 2.0f;  // proportional rows: m10·m15 - m14·m11 = 2·2 - 4·1 = 0
  m[14] = 4.0f;
  m[11] = 1.0f;
  m[15] = 2.0f;
  expect(m, SSS_ERROR_INVALID_ARGUMENT, "proportional depth and w rows");
  for (int i : {3, 7}) {
    m = good;
    m[static_cast<std::size_t>(i)] = 0.25f;
    expect(m, SSS_ERROR_UNSUPPORTED, "w depends on x or y (" + std::to_string(i) + ")");
  }
  for (int i : {1, 4}) {
    m = good;
    m[static_cast<std::size_t>(i)] = 0.25f;
    expect(m, SSS_ERROR_UNSUPPORTED, "shear (" + std::to_string(i) + ")");
  }
  // The old camera stayed: the frame is the same as before all that.
  const StressOutcome after = run(frame);
  check(after.result == SSS_OK && after.output == reference.output, "the camera changed after rejected matrices");
}

// Random projections: each element 0 (4 in 10), an extreme float (2 in 10) or a random magnitude in
// [1e-6, 1e6] of either sign; `supported_shape` zeroes the elements a supported matrix has zero (no
// shear, w from z alone), so that many are accepted.
class RandomMatrices {
 public:
  explicit RandomMatrices(uint32_t seed) : rng_(seed), extremes_(extreme_floats()), pick_extreme_(0, extremes_.size() - 1) {}
  Matrix4 next(bool supported_shape) {
    Matrix4 m{};
    for (float& v : m) {
      const int k = pick_(rng_);
      v = k < 4 ? 0.0f : k < 6 ? extremes_[pick_extreme_(rng_)] : unit() * std::pow(10.0f, 6.0f * unit());
    }
    if (supported_shape) m[1] = m[2] = m[3] = m[4] = m[6] = m[7] = 0.0f;
    return m;
  }
  float unit() { return unit_(rng_); }  // in [-1, 1)
  uint32_t bits() { return static_cast<uint32_t>(rng_()); }

 private:
  std::mt19937 rng_;
  std::vector<float> extremes_;
  std::uniform_int_distribution<std::size_t> pick_extreme_;
  std::uniform_int_distribution<int> pick_{0, 9};
  std::uniform_real_distribution<float> unit_{-1.0f, 1.0f};
};

TEST_F(CameraStress, RandomMatricesAreRejectedOrGiveFiniteFrames) {
  category_ = "cameras-random";
  const uint32_t seed = stress_seed(0xca3e7a5u);
  std::printf("seed %u (SSS_STRESS_SEED)\n", seed);
  RandomMatrices random(seed);
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.05f;
  ASSERT_EQ(set_settings(s), SSS_OK);
  int accepted = 0, frames = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Matrix4 m = random.next(trial % 2 == 0);  // half of them in the supported shape
    ++tally_.cases;
    const sss_result r = sss_set_camera(sss_, m.data());
    check(r == SSS_OK || r == SSS_ERROR_INVALID_ARGUMENT || r == SSS_ERROR_UNSUPPORTED,
          std::string("sss_set_camera gave ") + sss_result_string(r));
    if (r != SSS_OK) continue;
    ++accepted;
    if (frames >= 150) continue;
    ++frames;
    // Raw depth anywhere in [0, 1] (whatever distance that means for this matrix), or linear.
    const DepthFormat format = frames % 2 ? DepthFormat::depth32f : DepthFormat::r32f;
    StressFrame f = relief_frame(11, 9, random.bits(), m, 0.0, 1.0, format);
    if (!is_linear(format)) {
      for (std::size_t i = 0; i < f.depth.size(); ++i) f.depth[i] = 0.5f + 0.5f * random.unit();
    }
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    ASSERT_TRUE(run_and_check(f));
  }
  std::printf("%d of 4000 random matrices accepted; %d frames run\n", accepted, frames);
  EXPECT_GT(accepted, 100);
}

// The same random matrices carried by the frame (sss_frame.projection): each is refused with the
// code sss_set_camera gives it, leaving the colour as it was, or gives the image sss_set_camera's
// camera gives, bit for bit.
TEST_F(CameraStress, RandomMatricesInTheFrameAgreeWithTheCamera) {
  category_ = "cameras-in-the-frame";
  const uint32_t seed = stress_seed(0x5eed41u);
  std::printf("seed %u (SSS_STRESS_SEED)\n", seed);
  RandomMatrices random(seed);
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.05f;
  s.path = SSS_PATH_FRAGMENT;  // one path for both runs of a matrix
  ASSERT_EQ(set_settings(s), SSS_OK);
  int accepted = 0, refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Matrix4 m = random.next(trial % 2 == 0);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    StressFrame f = relief_frame(9, 7, random.bits(), m, 0.0, 1.0, DepthFormat::r32f);
    f.projection = m.data();
    ++tally_.cases;
    const StressOutcome carried = run(f);
    const sss_result camera = sss_set_camera(sss_, m.data());
    check(carried.result == camera, std::string("the frame's projection gave ") + sss_result_string(carried.result) +
                                         ", sss_set_camera " + sss_result_string(camera));
    if (camera != SSS_OK) {
      ++refused;
      check(carried.output == carried.input, "a refused projection changed the colour");
      continue;
    }
    ++accepted;
    f.projection = nullptr;
    const StressOutcome set = run(f);
    check(set.result == SSS_OK && set.output == carried.output, "the frame's projection gave another image");
  }
  std::printf("%d accepted, %d refused\n", accepted, refused);
  EXPECT_GT(accepted, 10);
  EXPECT_GT(refused, 10);
}

}  // namespace
}  // namespace sss_test
