// sss_get_stats: counters (always), GPU measurements (SSS_CREATE_STATS), and the queries leaving the
// host's own queries and the listed state alone. Runs on every backend, egl-gles included (there the
// pixel count is unavailable and says so).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "filter_case.hpp"
#include "gl_state_snapshot.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

bool is_gles_backend() { return sss_headless_backend_is_gles(test_backend()) != 0; }

const sss::math::Matrix4 kCamera = perspective_matrix(40.0f, 48.0f / 32.0f, 0.1f, 10.0f);

class Stats : public FilterCaseTest {
 protected:
  // A flat 48x32 plane, translucent (alpha 1) only in a 10x7 rectangle at (20, 9): the pixels the
  // filter blurs in place are exactly those 70.
  void make_masked_plane() {
    SyntheticScene scene = make_flat_scene(48, 32, {0.6f, 0.3f, 0.2f, 0.0f}, 1.5f, kCamera);
    for (int y = 9; y < 16; ++y) {
      for (int x = 20; x < 30; ++x) scene.color[(static_cast<std::size_t>(y) * 48 + x) * 4 + 3] = 1.0f;
    }
    color_ = make_rgba16f(48, 32, scene.color);
    depth_ = make_depth32f(48, 32, scene.window_depth);
    projection_ = scene.projection;
  }
  sss_frame frame() const {
    sss_frame f = frame_of(color_, depth_);
    FilterCase c;
    c.half_color = true;
    describe_frame(c, 48, 32, &f);  // needed on ES 3.0, checked elsewhere
    return f;
  }
  void start(uint32_t flags) {
    sss_ = create_sss(flags);
    ASSERT_NE(sss_, nullptr);
    sss_settings s;
    sss_default_settings(&s);
    s.world_units_per_mm = 0.02f;
    // The plain fragment path: the counts below are its two passes a frame, and its timer queries
    // are the ones read. The default (SSS_PATH_AUTO) adds the masked path's mark and copy on a
    // software rasteriser, and on a GPU its trial frames hold GL_TIME_ELAPSED (compute_path_test.cpp).
    s.path = SSS_PATH_FRAGMENT;
    ASSERT_EQ(sss_set_settings(sss_, &s), SSS_OK);
    ASSERT_EQ(sss_set_camera(sss_, projection_.data()), SSS_OK);
  }
  sss_stats stats() const {
    sss_stats st = {};
    st.struct_size = sizeof st;
    EXPECT_EQ(sss_get_stats(sss_, &st), SSS_OK) << sss_last_error(sss_);
    return st;
  }
  // Applies `f` and waits for the GL to finish it; keeps the wall-clock time that took (ms), which
  // holds all of the frame's GPU work: none of it can start before its commands are given.
  void timed_frame(const sss_frame& f) {
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
    glFinish();
    wall_ms_.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  // The GPU times reported for the measured frame: finite, above zero (a pass that blurs pixels
  // takes time), and together within the wall-clock time around that frame (its passes run one
  // after the other inside it). The allowance is the timers' resolution, not a margin for noise:
  // GL_TIME_ELAPSED counts in ns from a GPU clock of 1 MHz or more (one tick at each end of each of
  // the two queries, at most 4 us) and steady_clock in ns; 10 us covers both.
  void expect_gpu_times_within_the_wall_clock(const sss_stats& st) {
    ASSERT_NE(st.measured & SSS_STATS_GPU_TIME, 0u);
    ASSERT_GE(st.measured_frame, 1u);
    ASSERT_LE(st.measured_frame, wall_ms_.size());
    constexpr double kResolutionMs = 0.01;
    const double wall = wall_ms_[st.measured_frame - 1];
    for (double ms : st.gpu_time_ms) {
      EXPECT_TRUE(std::isfinite(ms));
      EXPECT_GT(ms, 0.0);
    }
    EXPECT_LE(st.gpu_time_ms[0] + st.gpu_time_ms[1], wall + kResolutionMs)
        << "GPU time of frame " << st.measured_frame << " above the wall-clock time around it";
    std::printf("frame %llu: GPU time horizontal %.4f ms + vertical %.4f ms, wall clock %.4f ms\n",
                static_cast<unsigned long long>(st.measured_frame), st.gpu_time_ms[0], st.gpu_time_ms[1], wall);
  }
  std::vector<double> wall_ms_;  // of each timed_frame, in order
  GLuint color_ = 0, depth_ = 0;
  sss::math::Matrix4 projection_{};
};

TEST_F(Stats, CountersAndVariantWithoutTheFlagAndNoMeasurements) {
  make_masked_plane();
  start(0);
  sss_stats st = stats();
  EXPECT_EQ(st.frames, 0u);
  EXPECT_EQ(st.glsl_variant, static_cast<uint32_t>(is_gles() ? SSS_GLSL_300_ES : SSS_GLSL_420_CORE));  // llvmpipe: GL 4.5
  const sss_frame f = frame();
  for (int i = 0; i < 3; ++i) ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  glFinish();
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK);
  st = stats();
  EXPECT_EQ(st.frames, 4u);
  EXPECT_EQ(st.last_frame_passes, 3u);  // the inputs, horizontal and vertical blur, no stencil: no copies
  EXPECT_EQ(st.passes, 12u);
  EXPECT_EQ(st.measured, 0u) << "measurements without SSS_CREATE_STATS";
  EXPECT_EQ(st.measured_frame, 0u);
  // A failed frame counts nothing.
  sss_frame bad = f;
  bad.color_texture = 0;
  EXPECT_EQ(sss_apply_frame(sss_, &bad), SSS_ERROR_INVALID_TEXTURE);
  EXPECT_EQ(stats().frames, 4u);
}

TEST_F(Stats, BadArguments) {
  make_masked_plane();
  start(0);
  sss_stats st = {};
  st.struct_size = sizeof st - 1;
  EXPECT_EQ(sss_get_stats(sss_, &st), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("stats->struct_size"), std::string::npos);
  EXPECT_EQ(sss_get_stats(sss_, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  st.struct_size = sizeof st;
  EXPECT_EQ(sss_get_stats(nullptr, &st), SSS_ERROR_INVALID_ARGUMENT);
}

TEST_F(Stats, PixelsTouchedOnAKnownMaskAndNonNegativeTimes) {
  make_masked_plane();
  start(SSS_CREATE_STATS);
  const sss_frame f = frame();
  // Results are read without stalling, at the next frame once the GPU is done: finish in between.
  for (int i = 0; i < 3; ++i) timed_frame(f);
  const sss_stats st = stats();
  EXPECT_EQ(st.frames, 3u);
  if (st.measured != 0) {
    EXPECT_GE(st.measured_frame, 1u);
    EXPECT_LE(st.measured_frame, 2u);  // never the frame not yet looked at
  } else {
    EXPECT_EQ(st.measured_frame, 0u);  // ES on llvmpipe: no sample count, no trusted timer
  }
  if (is_gles()) {
    EXPECT_EQ(st.measured & SSS_STATS_PIXELS, 0u) << "OpenGL ES has no sample count";
  } else {
    ASSERT_NE(st.measured & SSS_STATS_PIXELS, 0u);
    EXPECT_EQ(st.pixels_touched, 70u);  // the 10x7 translucent rectangle, nothing else
  }
  if ((st.measured & SSS_STATS_GPU_TIME) != 0) {
    expect_gpu_times_within_the_wall_clock(st);
  } else {
    EXPECT_EQ(st.gpu_time_ms[0], 0.0);
    EXPECT_EQ(st.gpu_time_ms[1], 0.0);
    std::printf("GPU time: unavailable on this context\n");
  }
  // The module trusts GL_TIME_ELAPSED on a GPU, not on a software rasteriser (llvmpipe's timer keeps
  // one tile's time).
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos) {
    EXPECT_EQ(st.measured & SSS_STATS_GPU_TIME, 0u) << "llvmpipe's GL_TIME_ELAPSED is not to be trusted";
  } else if (!is_gles()) {
    EXPECT_NE(st.measured & SSS_STATS_GPU_TIME, 0u) << "a GPU's timer (" << renderer << ") is trusted";
  }
}

// A GPU whose timer the module trusts: llvmpipe under another name (its times are a tile's, but
// they go through the same queries, ring and read-back as a real GPU's).
TEST_F(Stats, GpuTimesWhereTheTimerIsTrustedAreReadWithoutStalling) {
  make_masked_plane();
  loader_override_ = loader_telling(GL_RENDERER, "Test GPU (a hardware renderer, as told by the test)",
                                    is_gles_backend() ? es30_get_proc_address : sss_headless_get_proc_address);
  start(SSS_CREATE_STATS);
  const sss_frame f = frame();
  timed_frame(f);
  EXPECT_EQ(stats().measured_frame, 0u) << "frame 1's results are read back by a later frame, not by sss_get_stats";
  timed_frame(f);
  ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK);
  const sss_stats st = stats();
  ASSERT_NE(st.measured & SSS_STATS_GPU_TIME, 0u) << "desktop GL and ES with GL_EXT_disjoint_timer_query time passes";
  EXPECT_EQ(st.measured_frame, 2u);  // frame 3 looked, and frame 2 was finished
  // llvmpipe's times (one tile's) are below the frame's, never above it.
  expect_gpu_times_within_the_wall_clock(st);
  if (!is_gles()) {
    ASSERT_NE(st.measured & SSS_STATS_PIXELS, 0u);
    EXPECT_EQ(st.pixels_touched, 70u);
  }
  std::printf("GPU time through the queries: horizontal %.4f ms, vertical %.4f ms (frame %llu; llvmpipe: one tile)\n",
              st.gpu_time_ms[0], st.gpu_time_ms[1], static_cast<unsigned long long>(st.measured_frame));
}

TEST_F(Stats, TheHostsActiveQueriesAndTheListedStateStayAsTheyWere) {
  make_masked_plane();
  start(SSS_CREATE_STATS);
  const sss_frame f = frame();
  // The host measures its frame around sss_apply with queries of the targets the module uses
  // (desktop: GL_TIME_ELAPSED and GL_SAMPLES_PASSED; ES: a GL_ANY_SAMPLES_PASSED of its own).
  GLuint host[2] = {0, 0};
  glGenQueries(2, host);
  const GLenum targets[2] = {is_gles() ? GLenum(GL_ANY_SAMPLES_PASSED) : GLenum(GL_TIME_ELAPSED),
                             is_gles() ? GLenum(0) : GLenum(GL_SAMPLES_PASSED)};
  for (int i = 0; i < 2; ++i) {
    if (targets[i] != 0) glBeginQuery(targets[i], host[i]);
  }
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const Snapshot before = take_snapshot(is_gles());
  for (int i = 0; i < 3; ++i) ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK) << sss_last_error(sss_);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(describe_differences(before, take_snapshot(is_gles())), "");
  for (int i = 0; i < 2; ++i) {
    if (targets[i] == 0) continue;
    GLint current = 0;
    glGetQueryiv(targets[i], GL_CURRENT_QUERY, &current);
    EXPECT_EQ(static_cast<GLuint>(current), host[i]) << "the host's query of target 0x" << std::hex << targets[i];
    glEndQuery(targets[i]);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glFinish();
  GLuint available = 0;
  glGetQueryObjectuiv(host[0], GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, 1u);
  glDeleteQueries(2, host);
  // No query of the module's is left active on a target the host left free.
  if (is_gles()) {
    GLint current = -1;
    glGetQueryiv(GL_ANY_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
    EXPECT_EQ(current, 0);
  } else {
    ASSERT_EQ(sss_apply_frame(sss_, &f), SSS_OK);
    for (GLenum target : {GLenum(GL_TIME_ELAPSED), GLenum(GL_SAMPLES_PASSED)}) {
      GLint current = -1;
      glGetQueryiv(target, GL_CURRENT_QUERY, &current);
      EXPECT_EQ(current, 0);
    }
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace sss_test
