// sss_create and sss_destroy.
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

#include "../gl/state_guard.hpp"
#include "context.hpp"
#include "gl_session.hpp"
#include "validation.hpp"
#include "versioned_structs.hpp"

namespace {

using sss::api::fail;
namespace gl = sss::gl;

bool parse_version(const char* text, int* major, int* minor, bool* es) {
  const char* es_prefix = "OpenGL ES ";
  *es = std::strncmp(text, es_prefix, std::strlen(es_prefix)) == 0;
  if (*es) text += std::strlen(es_prefix);
  return std::sscanf(text, "%d.%d", major, minor) == 2;
}

bool has_extension(const gl::Functions& f, const char* name) {
  gl::GLint count = 0;
  f.GetIntegerv(gl::NUM_EXTENSIONS, &count);
  for (gl::GLint i = 0; i < count; ++i) {
    const auto* ext = reinterpret_cast<const char*>(f.GetStringi(gl::EXTENSIONS, static_cast<gl::GLuint>(i)));
    if (ext != nullptr && std::strcmp(ext, name) == 0) return true;
  }
  return false;
}

// Checks the version before loading the rest, so that an old context reports UNSUPPORTED rather
// than a missing 3.3 function.
sss_result check_version(sss_context* ctx, sss_get_proc_address_fn get_proc_address, void* user) {
  using GetStringFn = const gl::GLubyte*(SSS_GL_APIENTRY*)(gl::GLenum);
  auto get_string = reinterpret_cast<GetStringFn>(get_proc_address("glGetString", user));
  if (get_string == nullptr) return fail(nullptr, SSS_ERROR_GL_FUNCTION_MISSING, "get_proc_address(\"glGetString\") gave NULL");
  const auto* version = reinterpret_cast<const char*>(get_string(gl::VERSION));
  if (version == nullptr) {
    return fail(nullptr, SSS_ERROR_NO_CONTEXT, "no GL context is current on this thread (glGetString(GL_VERSION) is NULL)");
  }
  bool es = false;
  if (!parse_version(version, &ctx->gl_major, &ctx->gl_minor, &es)) {
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "GL_VERSION \"%s\" cannot be parsed", version);
  }
  ctx->gl_es = es;
  if (es) {
    if (ctx->gl_major < 3) {
      return fail(nullptr, SSS_ERROR_UNSUPPORTED, "GL_VERSION \"%s\": OpenGL ES 3.0 or newer is required", version);
    }
    return SSS_OK;
  }
  if (ctx->gl_major * 10 + ctx->gl_minor < 33) {
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "GL_VERSION \"%s\": OpenGL 3.3 or newer is required", version);
  }
  return SSS_OK;
}

sss_result check_create_desc(const sss_create_desc* desc) {
  if (desc == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "desc is NULL");
  // Every release so far has the same sss_create_desc (0.1's 48 bytes on x86-64).
  const sss_result size = sss::api::check_struct_size(nullptr, "desc->struct_size", "sss_create_desc", desc->struct_size,
                                                      {{"0.1, 0.2, 0.3", static_cast<uint32_t>(sizeof(sss_create_desc))}});
  if (size != SSS_OK) return size;
  if (desc->get_proc_address == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "desc->get_proc_address is NULL");
  if ((desc->flags & ~SSS_CREATE_ALL_FLAGS) != 0) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "desc->flags = 0x%x has unknown bits 0x%x", desc->flags,
                desc->flags & ~SSS_CREATE_ALL_FLAGS);
  }
  return SSS_OK;
}

// ES 3.0 cannot render to RGBA16F (the intermediate target) without one of the colour-buffer
// extensions; float filtering decides which host formats can be sampled bilinearly.
sss_result check_es_float_targets(sss_context* ctx, const gl::Api& api) {
  const gl::Functions& f = ctx->gl;
  ctx->es_float_render = has_extension(f, "GL_EXT_color_buffer_float");
  if (!ctx->es_float_render && !has_extension(f, "GL_EXT_color_buffer_half_float")) {
    return fail(nullptr, SSS_ERROR_UNSUPPORTED,
                "OpenGL ES %d.%d without GL_EXT_color_buffer_float (or GL_EXT_color_buffer_half_float): the "
                "RGBA16F intermediate target cannot be rendered to",
                api.major, api.minor);
  }
  ctx->es_float_linear = has_extension(f, "GL_OES_texture_float_linear");
  return SSS_OK;
}

// What sss_create found: the GL, the dialect, what the guard and the stats can do (INFO and DEBUG).
void log_created(sss_context* ctx, const gl::Api& api, gl::GlslVariant variant, const std::string& renderer_name,
                 bool software_renderer) {
  const gl::Functions& f = ctx->gl;
  char info[320];
  std::snprintf(info, sizeof info, "sss %d.%d.%d on OpenGL %s%d.%d, %s: shaders in %s%s", SSS_VERSION_MAJOR,
                SSS_VERSION_MINOR, SSS_VERSION_PATCH, api.es ? "ES " : "", ctx->gl_major, ctx->gl_minor,
                renderer_name.empty() ? "(unknown renderer)" : renderer_name.c_str(), gl::glsl_variant_name(variant),
                f.has_debug ? ", KHR_debug" : "");
  sss::api::log(ctx, SSS_LOG_INFO, info);
  std::snprintf(info, sizeof info,
                "sss_create: texture formats %s; state guard for %s; ES float targets %s, float filtering %s",
                f.has_texture_query ? "asked of the GL" : "taken from sss_frame (no glGetTexLevelParameteriv)",
                api.es ? "OpenGL ES (no polygon mode, depth clamp, logic op, clip distances, sRGB enable)"
                       : "desktop GL",
                api.es ? (ctx->es_float_render ? "yes" : "RGBA16F only") : "n/a",
                api.es ? (ctx->es_float_linear ? "yes" : "no") : "n/a");
  sss::api::log(ctx, SSS_LOG_DEBUG, info);
  if ((ctx->create_flags & SSS_CREATE_STATS) != 0) {
    const gl::PassQueries& q = ctx->filter.queries();
    std::snprintf(info, sizeof info, "sss_create: stats on: pixel counts %s, GPU timer %s",
                  q.pixels_supported() ? "yes" : "no (OpenGL ES has no sample count)",
                  q.timing_supported() ? "yes"
                  : software_renderer  ? "no (a software rasteriser: its GL_TIME_ELAPSED covers one tile)"
                                       : "no (no timer queries with counter bits)");
    sss::api::log(ctx, SSS_LOG_INFO, info);
  }
}

}  // namespace

extern "C" {

SSS_API sss_result sss_create(const sss_create_desc* desc, sss_context** out) {
  if (out == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out is NULL");
  *out = nullptr;
  sss_result r = check_create_desc(desc);
  if (r != SSS_OK) return r;

  std::unique_ptr<sss_context> ctx(new (std::nothrow) sss_context);
  if (!ctx) return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "allocating the context failed");
  ctx->log = desc->log;
  ctx->log_user = desc->log_user;
  ctx->create_flags = desc->flags;

  r = check_version(ctx.get(), desc->get_proc_address, desc->get_proc_address_user);
  if (r != SSS_OK) return r;
  gl::Api api;
  api.es = ctx->gl_es;
  api.major = ctx->gl_major;
  api.minor = ctx->gl_minor;
  std::string missing;
  if (!gl::load_functions(desc->get_proc_address, desc->get_proc_address_user, api, &ctx->gl, &missing)) {
    return fail(nullptr, SSS_ERROR_GL_FUNCTION_MISSING, "get_proc_address(\"%s\") gave NULL", missing.c_str());
  }
  gl::Functions& f = ctx->gl;
  // KHR_debug is core in GL 4.3 and ES 3.2.
  const bool debug_core = api.es ? api.version() >= 32 : api.version() >= 43;
  f.has_debug = f.PushDebugGroup != nullptr && f.PopDebugGroup != nullptr && f.ObjectLabel != nullptr &&
                (debug_core || has_extension(f, "GL_KHR_debug"));
  const bool labels = (desc->flags & SSS_CREATE_NO_DEBUG_LABELS) == 0;
  if (api.es) {
    r = check_es_float_targets(ctx.get(), api);
    if (r != SSS_OK) return r;
  }
  // Limits cannot change: read once here, never by a frame.
  f.GetIntegerv(gl::MAX_TEXTURE_SIZE, &ctx->max_texture_size);
  if (f.has_multisample_textures()) {  // invalid enums on ES 3.0
    f.GetIntegerv(gl::MAX_COLOR_TEXTURE_SAMPLES, &ctx->max_color_texture_samples);
    f.GetIntegerv(gl::MAX_DEPTH_TEXTURE_SAMPLES, &ctx->max_depth_texture_samples);
  }
  const gl::GlslVariant variant =
      gl::choose_glsl_variant(api, !api.es && has_extension(f, "GL_ARB_explicit_uniform_location"));
  const char* renderer = reinterpret_cast<const char*>(f.GetString(gl::RENDERER));
  const std::string renderer_name = renderer != nullptr ? renderer : "";
  // Mesa's software rasterisers time one tile of a pass with GL_TIME_ELAPSED (DESIGN.md §6).
  const bool software_renderer = renderer_name.find("llvmpipe") != std::string::npos ||
                                 renderer_name.find("softpipe") != std::string::npos ||
                                 renderer_name.find("swrast") != std::string::npos;
  if ((desc->flags & SSS_CREATE_STATS) != 0) {
    ctx->filter.enable_measurements(api.es && has_extension(f, "GL_EXT_disjoint_timer_query"));
  }
  ctx->filter.set_software_renderer(software_renderer);

  sss_context* raw = ctx.get();
  ctx->filter.set_log([raw](int level, const std::string& text) { sss::api::log(raw, level, text); });
  sss::api::drain_host_errors(ctx.get(), f);
  std::string message;
  {
    gl::StateGuard guard(f, (desc->flags & SSS_CREATE_NO_STATE_RESTORE) == 0);
    r = ctx->filter.init(&f, variant, labels, &message);
    if (r == SSS_OK) r = sss::api::check_gl_errors(nullptr, f, "creating the module's GL objects");
  }
  if (r != SSS_OK) {
    ctx->filter.destroy();
    sss::api::drain_host_errors(nullptr, f);
    if (!message.empty()) fail(nullptr, r, message);
    return r;
  }
  ctx->kernel = sss::math::build_pass_kernel(ctx->settings);
  sss::api::default_kernel_desc(&ctx->kernel_desc);
  log_created(ctx.get(), api, variant, renderer_name, software_renderer);
  *out = ctx.release();
  return SSS_OK;
}

SSS_API void sss_destroy(sss_context* ctx) {
  if (ctx == nullptr) return;
  if (ctx->gl.GetString(gl::VERSION) == nullptr) {
    sss::api::log(ctx, SSS_LOG_WARNING, "sss_destroy without a current GL context: the module's GL objects leak");
  } else if (ctx->filter.objects_present()) {
    ctx->filter.destroy();  // deletes only the module's own objects: no binding changes
    for (const auto& lut : ctx->lut_textures) ctx->gl.DeleteTextures(1, &lut.texture);
  } else if (!ctx->filter.needs_rebuild()) {
    // Deleting the names here would delete whatever the current context holds under them.
    sss::api::log(ctx, SSS_LOG_WARNING,
                  "sss_destroy: the module's GL objects are not in the current GL context (lost with the context "
                  "they were created in, or another context is current); nothing was deleted");
  }
  delete ctx;
}

}  // extern "C"
