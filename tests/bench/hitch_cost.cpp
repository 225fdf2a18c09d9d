#include "hitch_cost.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "counting_loader.hpp"
#include "host_gl_util.hpp"
#include "state_cost.hpp"
#include "sss/sss.h"
#include "timing.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

constexpr int kRepeats = 5, kSteadyFrames = 5;

// A perspective camera (fovy 45°, the frame's aspect, near 0.1, far 10), column-major.
std::vector<float> camera(int width, int height) {
  const float f = 2.4142135f;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return {f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, -1.020202f, -1, 0, 0, -0.2020202f, 0};
}

struct Frame {
  GLuint color = 0, depth = 0;
  sss_frame frame{};
};

// A plane at view distance 1 with a pattern in its colour (the blur has something to do), described.
Frame make_frame(int width, int height) {
  Frame f;
  std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) {
    const float x = static_cast<float>(i % static_cast<std::size_t>(width));
    rgba[i * 4 + 0] = 0.5f + 0.5f * std::sin(0.3f * x);
    rgba[i * 4 + 1] = 0.3f;
    rgba[i * 4 + 2] = 0.2f;
    rgba[i * 4 + 3] = 1.0f;
  }
  const std::vector<float> depth(static_cast<std::size_t>(width) * height, 0.9091f);  // NDC of distance 1
  f.color = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_FLOAT);
  f.depth = make_texture(GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT);
  glBindTexture(GL_TEXTURE_2D, f.color);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
  glBindTexture(GL_TEXTURE_2D, f.depth);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  f.frame.struct_size = sizeof f.frame;
  f.frame.color_texture = f.color;
  f.frame.depth_texture = f.depth;
  f.frame.color_format = GL_RGBA16F;
  f.frame.depth_format = GL_DEPTH_COMPONENT32F;
  f.frame.texture_width = width;
  f.frame.texture_height = height;
  return f;
}

sss_context* create(void* (*get_proc_address)(const char*, void*), void* user, uint32_t flags) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.flags = flags;
  desc.get_proc_address = get_proc_address;
  desc.get_proc_address_user = user;
  sss_context* ctx = nullptr;
  if (sss_create(&desc, &ctx) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  return ctx;
}

void check(sss_context* ctx, sss_result r, const char* call) {
  if (r != SSS_OK) throw std::runtime_error(std::string("hitch cost: ") + call + ": " + sss_last_error(ctx));
}

double timed_ms(const std::function<void()>& call) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  call();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The settings before and after the change: the defaults on the plain fragment path, then the
// masked path with jittered taps, which needs programs the first never built (the stencil mark,
// the jittered blur variants) and a target (the mask's stencil buffer).
sss_settings settings_before() {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.01f;  // a few pixels per millimetre on this plane: the taps have work
  // Pinned: the default (SSS_PATH_AUTO) times its candidate paths in its first frames on a GPU and
  // reads those timer queries back, which would count as the steady frame's queries here.
  s.path = SSS_PATH_FRAGMENT;
  return s;
}
sss_settings settings_after() {
  sss_settings s = settings_before();
  s.path = SSS_PATH_FRAGMENT_MASKED;
  s.jitter = 0.33f;
  return s;
}

// One fresh context through the change, with or without sss_prepare between it and the first frame.
void one_change(const GlLoader& loader, Frame& f, const std::vector<float>& projection, bool prepare, HitchCost* out,
                std::vector<double>* first, std::vector<double>* prepares, std::vector<double>* steady) {
  sss_context* ctx = create(loader.get_proc_address, loader.user, 0);
  try {
    const sss_settings before = settings_before(), after = settings_after();
    check(ctx, sss_set_settings(ctx, &before), "sss_set_settings");
    check(ctx, sss_set_camera(ctx, projection.data()), "sss_set_camera");
    for (int i = 0; i < 3; ++i) check(ctx, sss_apply_frame(ctx, &f.frame), "sss_apply_frame");
    check(ctx, sss_set_settings(ctx, &after), "sss_set_settings");
    if (prepare) {
      sss_prepare_desc d = {};
      d.struct_size = sizeof d;
      d.width = out->width;
      d.height = out->height;
      d.color_format = GL_RGBA16F;
      d.depth_format = GL_DEPTH_COMPONENT32F;
      prepares->push_back(timed_ms([&] { check(ctx, sss_prepare(ctx, &d), "sss_prepare"); }));
    }
    first->push_back(timed_ms([&] { check(ctx, sss_apply_frame(ctx, &f.frame), "sss_apply_frame"); }));
    if (prepare) {
      for (int i = 0; i < kSteadyFrames; ++i) {
        steady->push_back(timed_ms([&] { check(ctx, sss_apply_frame(ctx, &f.frame), "sss_apply_frame"); }));
      }
    }
  } catch (...) {
    sss_destroy(ctx);
    throw;
  }
  sss_destroy(ctx);
}

// Queries per steady described frame through the counting loader.
double steady_queries(const GlLoader& loader, Frame& f, const std::vector<float>& projection, uint32_t flags) {
  sss_context* ctx = create(sss_test::counting_loader(loader.get_proc_address), loader.user, flags);
  double per_frame = 0.0;
  try {
    const sss_settings s = settings_before();
    check(ctx, sss_set_settings(ctx, &s), "sss_set_settings");
    check(ctx, sss_set_camera(ctx, projection.data()), "sss_set_camera");
    for (int i = 0; i < 2; ++i) check(ctx, sss_apply_frame(ctx, &f.frame), "sss_apply_frame");
    sss_test::reset_call_counts();
    for (int i = 0; i < kSteadyFrames; ++i) check(ctx, sss_apply_frame(ctx, &f.frame), "sss_apply_frame");
    per_frame = static_cast<double>(sss_test::call_counts().total_queries()) / kSteadyFrames;
  } catch (...) {
    sss_destroy(ctx);
    throw;
  }
  sss_destroy(ctx);
  return per_frame;
}

}  // namespace

HitchCost measure_hitch_cost(const GlLoader& loader, int width, int height) {
  HitchCost cost;
  cost.width = width;
  cost.height = height;
  cost.repeats = kRepeats;
  cost.change = "the plain fragment path to the masked one with jittered taps (new programs and a stencil buffer)";
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  Frame f = make_frame(width, height);
  const std::vector<float> projection = camera(width, height);
  const auto cleanup = [&] {
    reset_pass_state(viewport);
    const GLuint textures[2] = {f.color, f.depth};
    glDeleteTextures(2, textures);
  };
  try {
    std::vector<double> unprepared, prepared, prepares, steady;
    for (int r = 0; r < kRepeats; ++r) {
      one_change(loader, f, projection, false, &cost, &unprepared, nullptr, nullptr);
      one_change(loader, f, projection, true, &cost, &prepared, &prepares, &steady);
    }
    cost.first_frame_unprepared_ms = median(unprepared);
    cost.first_frame_prepared_ms = median(prepared);
    cost.prepare_ms = median(prepares);
    cost.steady_frame_ms = median(steady);
    cost.steady_queries_restore = steady_queries(loader, f, projection, 0);
    cost.steady_queries_no_restore = steady_queries(loader, f, projection, SSS_CREATE_NO_STATE_RESTORE);
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
  return cost;
}

void record_hitch_cost(const GlLoader& loader, int width, int height, RunInfo* info) {
  const HitchCost hitch = measure_hitch_cost(loader, width, height);
  info->hitch_width = hitch.width;
  info->hitch_height = hitch.height;
  info->hitch_repeats = hitch.repeats;
  info->hitch_change = hitch.change;
  info->first_frame_unprepared_ms = hitch.first_frame_unprepared_ms;
  info->first_frame_prepared_ms = hitch.first_frame_prepared_ms;
  info->prepare_ms = hitch.prepare_ms;
  info->steady_frame_ms = hitch.steady_frame_ms;
  info->steady_queries_restore = hitch.steady_queries_restore;
  info->steady_queries_no_restore = hitch.steady_queries_no_restore;
  std::printf("sss_bench: first frame after a settings change: %.2f ms unprepared, %.2f ms after sss_prepare "
              "(%.2f ms); steady frame %.2f ms; GL queries per steady frame %.1f (%.1f without the restore)\n",
              hitch.first_frame_unprepared_ms, hitch.first_frame_prepared_ms, hitch.prepare_ms, hitch.steady_frame_ms,
              hitch.steady_queries_restore, hitch.steady_queries_no_restore);
}

}  // namespace sss_bench
