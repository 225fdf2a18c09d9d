// The stress suite's harness: frames built from raw values (any float, any size, any format), run
// through sss_apply_frame, and checked against invariants rather than pictures:
//   - the call succeeds;
//   - every pixel whose input is finite comes out finite (no overflow to Inf, no NaN);
//   - a pixel whose input is not finite, or whose alpha is not > 0, or that the stencil rejects,
//     or that lies outside the viewport, keeps its exact value (outside the viewport a separate
//     output keeps what it held);
//   - every blurred channel lies within the range of the finite input values of that channel (the
//     kernel's weights are non-negative and sum to 1; tolerance: two fp16 ulps of the range's ends
//     plus the float sum's rounding);
//   - alpha is never changed;
//   - optionally: the frame is the identity bit for bit, or a flat image stays flat.
// Each test counts its cases and checks into a tally; with SSS_STRESS_REPORT=<file> set, the tally
// is appended there as one line "category cases checks failures" (scripts/run-robustness.sh sums
// them into docs/robustness.md).
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "math/projection.hpp"

namespace sss_test {

enum class DepthFormat { depth16, depth24, depth32f, depth24_stencil8, depth32f_stencil8, r16f, r32f };
const char* depth_format_name(DepthFormat f);
bool is_linear(DepthFormat f);

struct StressFrame {
  int width = 1, height = 1;
  std::vector<float> color;  // RGBA, width·height·4
  bool half_color = true;    // RGBA16F (else RGBA32F)
  std::vector<float> depth;  // one value per pixel: window depth, or view distance (r16f/r32f)
  DepthFormat depth_format = DepthFormat::depth32f;
  std::vector<uint8_t> stencil;  // per pixel (depth*_stencil8 only); empty: all 0
  bool use_stencil = false;      // translucent where stencil == 1 (ref 1, mask 0xFF)
  bool separate_output = false;  // an output texture of the colour's format, pre-filled with kSentinel
  int32_t viewport[4] = {0, 0, 0, 0};
  uint32_t flags = 0;  // SSS_FRAME_*
  // Per pixel, as an R16UI profile_texture (profile in bits 0-3, object above); empty: none.
  std::vector<uint16_t> profile_ids;
  const float* projection = nullptr;  // sss_frame.projection (NULL: the context's camera)
};

constexpr float kSentinel = -3.25f;

struct StressOutcome {
  sss_result result = SSS_OK;
  std::vector<float> input;   // the colour as stored (after the upload's conversion)
  std::vector<float> output;  // the colour texture, or the separate output
};

struct Tally {
  long cases = 0, checks = 0, failures = 0;
};

struct Expectations {
  bool identity = false;  // output == input bit for bit (inside the viewport)
  bool flat = false;      // every blurred pixel within two fp16 ulps of its input
  // Extra pixels that must keep their exact value (e.g. an unusable depth).
  std::function<bool(std::size_t pixel)> kept;
};

// Window depth in [0, 1] (or NDC z with zero_to_one) of a view distance for a projection, in
// double; not clamped.
float window_depth(const sss::math::Matrix4& m, double distance, bool zero_to_one);

// A relief for stress: colour noise in [lo, hi] per channel, alpha 1 with bands of 0.5 and 0 (and
// one pixel of 0 when the image is tiny), distance a tilted plane in [near_d, far_d] with a step,
// stencil 1 on the left 3/4. Depth is filled for `projection` (window depth) or as distance.
StressFrame relief_frame(int width, int height, uint32_t seed, const sss::math::Matrix4& projection, double near_d,
                         double far_d, DepthFormat depth_format, float lo = 0.0f, float hi = 1.0f);

class StressTest : public GlTest {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Runs one frame on sss_ (created in SetUp, camera set by the test) and deletes its textures.
  StressOutcome run(const StressFrame& frame);
  // run() and then check_invariants(); returns false when an invariant failed.
  bool run_and_check(const StressFrame& frame, const Expectations& expect = {});
  // The invariants above; counts checks and failures into tally_ (reports the first few).
  bool check_invariants(const StressFrame& frame, const StressOutcome& outcome, const Expectations& expect);
  bool check(bool ok, const std::string& what);
  // The same, building the message only when the check fails.
  template <typename Message>
  bool check_lazy(bool ok, Message&& what) {
    if (ok) {
      ++tally_.checks;
      return true;
    }
    return check(false, what());
  }

  sss_result set_settings(const sss_settings& s);
  // For a fixture's SetUp: `camera`, and the default settings at `world_units_per_mm` with every
  // strength 1 and `samples` taps (a wide kernel whose taps reach the image's borders).
  void set_wide_kernel(const sss::math::Matrix4& camera, float world_units_per_mm, int samples);
  // The current settings as profile 0 and, as profile 1, the same at `scale` (sss_set_profiles):
  // frames without profile ids are unchanged; with them, index 1 pixels scatter further.
  void add_second_profile(float scale);
  // Ids for a frame: profiles 0 and 1 and two objects in bands (so taps cross between indices).
  static std::vector<uint16_t> banded_ids(int width, int height);

  std::string category_ = "uncategorised";
  Tally tally_;
  int reported_ = 0;
};

// Deterministic seed: SSS_STRESS_SEED when set, else `fallback`. Printed by the tests that use it.
uint32_t stress_seed(uint32_t fallback);

// Appends the tally to $SSS_STRESS_REPORT (if set).
void report_tally(const std::string& category, const Tally& tally);

// Values a float input should be tried with.
std::vector<float> extreme_floats();

}  // namespace sss_test
