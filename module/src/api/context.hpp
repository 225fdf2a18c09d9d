// The state behind an sss_context handle.
#pragma once

#include <cstdint>
#include <list>
#include <string>
#include <vector>

#include "../gl/gl_functions.hpp"
#include "../gl/separable_filter.hpp"
#include "../math/filter_constants.hpp"
#include "../math/lut_cache.hpp"
#include "../math/projection.hpp"
#include "../math/cbf_kernel.hpp"
#include "../math/pass_kernel.hpp"
#include "../math/profile_set.hpp"
#include "../math/recent_kernels.hpp"
#include "../math/separable_kernel.hpp"
#include "sss/sss.h"
#include "sss/sss_tools.h"
#include "steady_frame.hpp"

struct sss_context {
  sss::gl::Functions gl;
  sss::gl::SeparableFilter filter;
  sss_log_fn log = nullptr;
  void* log_user = nullptr;
  std::uint32_t create_flags = 0;
  int gl_major = 0, gl_minor = 0;
  bool gl_es = false;
  // OpenGL ES extensions the formats need (see api_apply.cpp): RGBA32F renderable, RGBA32F filterable.
  bool es_float_render = false, es_float_linear = false;
  // Limits, read once by sss_create (they cannot change): no frame asks for them again.
  int max_texture_size = 0;
  int max_color_texture_samples = 0, max_depth_texture_samples = 0;  // 0 where there are no multisample textures
  // The last successful frame, which a steady frame trusts (steady_frame.hpp).
  sss::api::SteadyFrame steady;

  sss::math::FilterSettings settings;
  sss::math::PassKernel kernel;        // what the separable mode's passes run (settings.kernel, jitter)
  std::uint64_t kernel_revision = 1;
  bool has_kernel_desc = false;        // settings.kernel was not NULL
  sss_kernel_desc kernel_desc{};       // *settings.kernel as given, for sss_get_settings; its table pointers
  std::vector<float> table_radius_mm;  // point at these copies
  std::vector<float> table_rgb;
  // Per-pixel profiles 1.. (sss_set_profiles; profile 0 is `settings` and `kernel`), and a revision
  // that changes whenever any profile's kernel or look does (sss_set_settings clears them).
  std::vector<sss::math::Profile> extra_profiles;
  std::uint64_t profiles_revision = 1;
  sss::math::CbfKernel cbf_kernel;            // built from cbf_kernel_inputs (taps 0: not built yet)
  sss::math::CbfKernelInputs cbf_kernel_inputs;
  std::uint64_t cbf_kernel_revision = 1;
  sss::math::RecentKernels recent_kernels;     // the costly kernels built lately (sss_set_settings)

  sss::math::Matrix4 projection{};
  bool has_camera = false;

  std::string last_error;

  // Pre-integrated LUT textures (sss_lut_create_texture), most recently used first, by the text of
  // all their inputs; owned by the context, deleted with it.
  struct LutTexture {
    std::string key;
    std::uint32_t texture = 0;
    std::uint64_t bytes = 0;  // its storage (sss_stats.gpu_memory_bytes)
  };
  std::list<LutTexture> lut_textures;
  std::uint64_t lut_gpu_generations = 0;
  sss::math::LutCache lut_data{4};  // CPU-generated LUTs (SSS_LUT_CPU), by the same keys

  // The LUT textures' storage.
  std::uint64_t lut_texture_bytes() const {
    std::uint64_t sum = 0;
    for (const LutTexture& lut : lut_textures) sum += lut.bytes;
    return sum;
  }

  // sss_get_stats counters.
  std::uint64_t frames = 0, passes = 0;
  std::uint32_t last_frame_passes = 0;
  std::uint32_t last_frame_path = SSS_PATH_FRAGMENT;  // sss_stats.last_frame_path
};

namespace sss::api {

// Records a failure: the message becomes sss_last_error's text (on ctx, or on the thread when ctx is
// NULL) and goes to the log callback. Returns `code` for `return fail(...)`.
sss_result fail(sss_context* ctx, sss_result code, const std::string& message);
sss_result fail(sss_context* ctx, sss_result code, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
void log(const sss_context* ctx, int level, const std::string& message);

}  // namespace sss::api
