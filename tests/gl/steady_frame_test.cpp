// A steady frame allocates nothing (issue: "nothing allocated per frame"): once the programs,
// targets and kernel exist, sss_apply_frame with the same inputs makes no heap allocation on the
// module's side, for the separable path (fixed and adaptive taps, with a region) and the
// cross-bilateral mode. Counted by replacing the global operator new for this test binary; the count
// is only kept while a test switches it on, so every other test runs as before. Not under
// AddressSanitizer, whose own operator new (and its new/delete mismatch checks) the GL tests keep.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "filter_case.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

#if !defined(__SANITIZE_ADDRESS__)
#define SSS_COUNT_ALLOCATIONS 1
// The replacements pair malloc with free, which GCC cannot see through the operator names.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop
#endif

using namespace host_gl;

namespace sss_test {
namespace {

using SteadyFrame = FilterCaseTest;

// Allocations made by `frames` calls of `apply` after two warm-up calls.
template <typename Apply>
long allocations_per_steady_frames(Apply apply, int frames) {
  apply();
  apply();
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < frames; ++i) apply();
  g_counting = false;
  return g_allocations.load();
}

TEST_F(SteadyFrame, AllocatesNothing) {
#if !defined(SSS_COUNT_ALLOCATIONS)
  GTEST_SKIP() << "operator new is AddressSanitizer's in this build";
#endif
  const SyntheticScene scene = make_relief_scene(32, 24, 5, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  const GLuint color = make_rgba32f(32, 24, scene.color);
  const GLuint output = make_rgba32f(32, 24, scene.color);
  const GLuint depth = make_depth32f(32, 24, scene.window_depth);
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  struct Case {
    const char* name;
    uint32_t settings_flags, mode, frame_flags;
    GLuint output;
    uint32_t path = SSS_PATH_FRAGMENT;
  };
  const Case cases[] = {
      {"separable, in place", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, 0u, 0u},
      {"separable, separate output", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, 0u, output},
      {"a region, separate output", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE,
       SSS_FRAME_REGION, output},
      {"cross-bilateral, in place", 0u, SSS_MODE_CROSS_BILATERAL, 0u, 0u},
      {"compute path, in place", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, 0u, 0u, SSS_PATH_COMPUTE},
      {"compute path, a region, separate output", SSS_FOLLOW_SURFACE,
       SSS_MODE_SEPARABLE, SSS_FRAME_REGION, output, SSS_PATH_COMPUTE},
      {"automatic path, in place (after its decision)", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, 0u, 0u, SSS_PATH_AUTO},
      {"masked fragment path, in place", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, 0u, 0u, SSS_PATH_FRAGMENT_MASKED},
      {"half-resolution path, a region, separate output", SSS_FOLLOW_SURFACE, SSS_MODE_SEPARABLE, SSS_FRAME_REGION,
       output, SSS_PATH_HALF_RESOLUTION},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    sss_settings s = visible_settings(17, c.settings_flags, 0.045f);
    s.mode = c.mode;
    s.path = c.path;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK) << sss_last_error(sss_);
    sss_frame f = frame_of(color, depth, c.output);
    f.flags = c.frame_flags;
    f.region[0] = 3;
    f.region[1] = 2;
    f.region[2] = 20;
    f.region[3] = 18;
    if (is_gles()) {
      FilterCase description;
      describe_frame(description, 32, 24, &f);
    }
    sss_result last = SSS_OK;
    const long n = allocations_per_steady_frames([&] { last = sss_apply_frame(sss_, &f); }, 10);
    EXPECT_EQ(last, SSS_OK) << sss_last_error(sss_);
    EXPECT_EQ(n, 0) << "heap allocations in 10 steady frames";
  }
  // The count is real: settings that change every call rebuild the kernel, which allocates.
  sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
  const long rebuilds = allocations_per_steady_frames(
      [&] {
        s.taps = s.taps == 17 ? 19 : 17;
        EXPECT_EQ(sss_set_settings(sss_, &s), SSS_OK);
      },
      4);
  EXPECT_GT(rebuilds, 0);
}

}  // namespace
}  // namespace sss_test
