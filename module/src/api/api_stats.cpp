// sss_get_stats: the context's counters, the GPU measurements read back so far and the storage its
// GL objects hold, written in the layout the caller's struct_size names. No GL call.
#include <cstddef>
#include <cstring>

#include "context.hpp"
#include "legacy_structs.hpp"
#include "versioned_structs.hpp"

namespace gl = sss::gl;
using sss::api::fail;

extern "C" {

SSS_API sss_result sss_get_stats(const sss_context* ctx, sss_stats* stats) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  auto* mutable_ctx = const_cast<sss_context*>(ctx);  // only for the error message
  if (stats == nullptr) return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "stats is NULL");
  // 0.1-0.4 had the same sss_stats (72 bytes on x86-64); 0.5 appended gpu_memory_bytes.
  const sss_result size = sss::api::check_struct_size(mutable_ctx, "stats->struct_size", "sss_stats", stats->struct_size,
                                                      {{"0.1 - 0.4", sss::legacy::kStatsSize04},
                                                       {"0.5", static_cast<uint32_t>(sizeof(sss_stats))}});
  if (size != SSS_OK) return size;
  const uint32_t given = stats->struct_size;
  sss_stats s = {};
  s.struct_size = sizeof s;
  switch (ctx->filter.variant()) {
    case gl::GlslVariant::glsl330: s.glsl_variant = SSS_GLSL_330_CORE; break;
    case gl::GlslVariant::glsl420: s.glsl_variant = SSS_GLSL_420_CORE; break;
    case gl::GlslVariant::essl300: s.glsl_variant = SSS_GLSL_300_ES; break;
  }
  s.frames = ctx->frames;
  s.passes = ctx->passes;
  s.last_frame_passes = ctx->last_frame_passes;
  s.last_frame_path = ctx->last_frame_path;
  const gl::PassMeasurement& m = ctx->filter.queries().latest();
  if (m.frame != 0) {
    s.measured_frame = m.frame;
    if (m.has_pixels) {
      s.measured |= SSS_STATS_PIXELS;
      s.pixels_touched = m.pixels;
    }
    if (m.has_time) {
      s.measured |= SSS_STATS_GPU_TIME;
      s.gpu_time_ms[0] = m.milliseconds[0];
      s.gpu_time_ms[1] = m.milliseconds[1];
    }
  }
  s.gpu_memory_bytes = ctx->filter.gpu_memory_bytes() + ctx->lut_texture_bytes();
  if (given == sizeof(sss_stats)) {
    *stats = s;
  } else {
    // An earlier release's struct: its fields only (they are today's first ones), its size kept.
    s.struct_size = given;
    std::memcpy(static_cast<void*>(stats), &s, offsetof(sss::legacy::Stats04, last_frame_path) + sizeof(uint32_t));
  }
  return SSS_OK;
}

}  // extern "C"
