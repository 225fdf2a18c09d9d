#include "state_cost.hpp"

#include <chrono>
#include <stdexcept>
#include <vector>

#include "host_gl_util.hpp"
#include "sss/sss.h"
#include "timing.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

constexpr int kSize = 16, kCalls = 200, kBatches = 7, kWarmup = 20;

double time_calls(const GlLoader& loader, uint32_t flags, GLuint color, GLuint depth, const float* projection) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.flags = flags;
  desc.get_proc_address = loader.get_proc_address;
  desc.get_proc_address_user = loader.user;
  sss_context* ctx = nullptr;
  if (sss_create(&desc, &ctx) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  sss_settings s;
  sss_default_settings(&s);
  // Width 0 written back in place draws nothing (the identity), so a call is its validation, the
  // texture queries and the state save and restore: the difference between the two contexts is the
  // restore alone, not buried under the software rasteriser's per-draw cost.
  s.world_units_per_mm = 0.0f;
  sss_frame frame = {};
  frame.struct_size = sizeof frame;
  frame.color_texture = color;
  frame.depth_texture = depth;
  bool ok = sss_set_settings(ctx, &s) == SSS_OK && sss_set_camera(ctx, projection) == SSS_OK;
  for (int i = 0; i < kWarmup && ok; ++i) ok = sss_apply_frame(ctx, &frame) == SSS_OK;
  std::vector<double> per_call;
  for (int b = 0; b < kBatches && ok; ++b) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kCalls && ok; ++i) ok = sss_apply_frame(ctx, &frame) == SSS_OK;
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    per_call.push_back(std::chrono::duration<double, std::micro>(end - start).count() / kCalls);
  }
  const std::string error = ok ? "" : sss_last_error(ctx);
  sss_destroy(ctx);
  if (!ok) throw std::runtime_error("state cost: " + error);
  return median(per_call);
}

}  // namespace

StateCost measure_state_cost(const GlLoader& loader) {
  const std::vector<float> rgba(kSize * kSize * 4, 0.5f);
  const std::vector<float> depth_values(kSize * kSize, 0.5f);
  const GLuint color = make_texture(GL_RGBA16F, kSize, kSize, GL_RGBA, GL_FLOAT);
  const GLuint depth = make_texture(GL_DEPTH_COMPONENT32F, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT);
  glBindTexture(GL_TEXTURE_2D, color);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, rgba.data());
  glBindTexture(GL_TEXTURE_2D, depth);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depth_values.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  // A perspective camera (fovy 45°, square, near 0.1, far 10), column-major.
  const float f = 2.4142135f;
  const float projection[16] = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, -1.020202f, -1, 0, 0, -0.2020202f, 0};
  StateCost cost;
  cost.calls_per_batch = kCalls;
  cost.batches = kBatches;
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const auto cleanup = [&] {
    reset_pass_state(viewport);
    const GLuint textures[2] = {color, depth};
    glDeleteTextures(2, textures);
  };
  try {
    cost.with_restore_us = time_calls(loader, 0, color, depth, projection);
    cost.without_restore_us = time_calls(loader, SSS_CREATE_NO_STATE_RESTORE, color, depth, projection);
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
  return cost;
}

void reset_pass_state(const GLint viewport[4]) {
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  for (GLuint unit = 0; unit < 4; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindSampler(unit, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDisable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xFFFFFFFFu);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xFFFFFFFFu);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace sss_bench
