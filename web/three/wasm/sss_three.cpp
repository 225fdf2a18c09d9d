// The WebAssembly side of the three.js package (web/three, docs/three.md): the library's C API
// flattened into calls that JavaScript can make with numbers and one scratch buffer. The GL context
// is three's own WebGL2RenderingContext, which the package registers with Emscripten's GL layer and
// makes current before each call (web/three/src/sss-three.js); nothing here creates a context.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdint>
#include <cstring>

#include <sss/sss.h>
#include "profile_fields.hpp"

namespace {

// sss_create_desc.get_proc_address: Emscripten's table of its WebGL2 bindings, which act on
// whichever context the package made current (three's).
void* webgl_get_proc_address(const char* name, void*) { return emscripten_webgl_get_proc_address(name); }

// The library's message about the last failed call here (sss_last_error of its context, or of no
// context for sss_create and the tools' calls); it lives until the library's next failure.
const char* g_message = "";

int remember(sss_result r, const sss_context* sss) {
  if (r != SSS_OK) g_message = sss_last_error(sss);
  return r;
}

}  // namespace

extern "C" {

// sss_create on the current (three's) context. Returns the context, or 0: sss3_last_error() says why.
EMSCRIPTEN_KEEPALIVE sss_context* sss3_create(uint32_t flags) {
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = webgl_get_proc_address;
  desc.flags = flags;
  sss_context* sss = nullptr;
  remember(sss_create(&desc, &sss), nullptr);
  return sss;
}

EMSCRIPTEN_KEEPALIVE void sss3_destroy(sss_context* sss) { sss_destroy(sss); }

EMSCRIPTEN_KEEPALIVE const char* sss3_last_error() { return g_message; }

EMSCRIPTEN_KEEPALIVE const char* sss3_result_string(int r) { return sss_result_string(static_cast<sss_result>(r)); }

// The library's default strength (index 0-2) and falloff (3-5) per channel, and its default taps (6):
// the page's sliders multiply them.
EMSCRIPTEN_KEEPALIVE double sss3_default(int index) {
  sss_settings s;
  sss_default_settings(&s);
  if (index < 3) return s.strength[index];
  if (index < 6) return s.falloff[index - 3];
  return s.taps;
}

// sss_set_profiles from `count` profiles of kProfileFloats floats each at `fields` (values as the
// caller gave them: the library judges them), with the settings every profile shares; the floats
// become settings and kernels in profile_fields.cpp, which sss_three_native_apply shares.
EMSCRIPTEN_KEEPALIVE int sss3_set_profiles(sss_context* sss, const float* fields, int count, int taps,
                                           int follow_surface, int path, float jitter) {
  if (count < 1 || count > SSS_MAX_PROFILES) {
    // sss_set_profiles names the bad count itself; it reads no profile for it.
    return remember(sss_set_profiles(sss, nullptr, static_cast<uint32_t>(count < 0 ? 0 : count)), sss);
  }
  sss_settings profiles[SSS_MAX_PROFILES];
  sss_kernel_desc kernels[SSS_MAX_PROFILES];  // sss_set_profiles copies them
  const sss_result r = sss_three::profiles_from_fields(fields, count, taps, follow_surface, path, jitter, profiles, kernels);
  if (r != SSS_OK) return remember(r, nullptr);
  return remember(sss_set_profiles(sss, profiles, static_cast<uint32_t>(count)), sss);
}

// sss_prepare for frames of this size and these formats, with a profile texture (R8UI) and, where a
// profile's texturing needs one, an albedo texture (albedo_format SRGB8_ALPHA8: the split's; 0: none).
EMSCRIPTEN_KEEPALIVE int sss3_prepare(sss_context* sss, int width, int height, uint32_t color_format,
                                      uint32_t depth_format, uint32_t profile_format, uint32_t albedo_format) {
  sss_prepare_desc desc{};
  desc.struct_size = sizeof desc;
  desc.width = width;
  desc.height = height;
  desc.color_format = color_format;
  desc.depth_format = depth_format;
  desc.profile_format = profile_format;
  desc.albedo_format = albedo_format;
  return remember(sss_prepare(sss, &desc), sss);
}

// sss_apply_frame in place on three's textures (their names in Emscripten's GL tables), described
// (formats and size: WebGL2 cannot be asked for them), with this frame's projection (16 floats,
// three's camera.projectionMatrix.elements, column-major) and sss_frame.flags; the albedo (the
// split's SRGB8_ALPHA8 attachment) where a profile's texturing is not pre-scatter, else 0 and 0.
EMSCRIPTEN_KEEPALIVE int sss3_apply(sss_context* sss, uint32_t color, uint32_t color_format, uint32_t depth,
                                    uint32_t depth_format, uint32_t profile, uint32_t profile_format, int width,
                                    int height, const float* projection, uint32_t noise_index, uint32_t flags,
                                    uint32_t albedo, uint32_t albedo_format) {
  sss_frame frame{};
  frame.struct_size = sizeof frame;
  frame.color_texture = color;
  frame.color_format = color_format;
  frame.depth_texture = depth;
  frame.depth_format = depth_format;
  frame.profile_texture = profile;
  frame.profile_format = profile_format;
  frame.texture_width = width;
  frame.texture_height = height;
  frame.projection = projection;
  frame.noise_index = noise_index;
  frame.flags = flags;  // SSS_FRAME_DEPTH_ZERO_TO_ONE for three's reversed depth (clip control)
  frame.albedo_texture = albedo;
  frame.albedo_format = albedo_format;
  return remember(sss_apply_frame(sss, &frame), sss);
}

// sss_get_stats into out[0..5]: frames, passes, last_frame_passes, last_frame_path, gpu_memory_bytes,
// glsl_variant (as doubles: JavaScript's numbers).
EMSCRIPTEN_KEEPALIVE int sss3_stats(const sss_context* sss, double* out) {
  sss_stats stats{};
  stats.struct_size = sizeof stats;
  const sss_result r = sss_get_stats(sss, &stats);
  if (r != SSS_OK) return r;
  out[0] = static_cast<double>(stats.frames);
  out[1] = static_cast<double>(stats.passes);
  out[2] = stats.last_frame_passes;
  out[3] = stats.last_frame_path;
  out[4] = static_cast<double>(stats.gpu_memory_bytes);
  out[5] = stats.glsl_variant;
  return SSS_OK;
}

}  // extern "C"
