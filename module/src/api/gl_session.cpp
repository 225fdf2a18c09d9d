#include "gl_session.hpp"

namespace sss::api {

namespace {
// A lost context can report errors forever; stop after this many.
constexpr int kMaxDrainedErrors = 32;
}

sss_result require_current_context(sss_context* ctx, const sss::gl::Functions& gl) {
  if (gl.GetString(sss::gl::VERSION) == nullptr) {
    return fail(ctx, SSS_ERROR_NO_CONTEXT, "no GL context is current on this thread (glGetString(GL_VERSION) is NULL)");
  }
  return SSS_OK;
}

void drain_host_errors(const sss_context* ctx, const sss::gl::Functions& gl) {
  for (int i = 0; i < kMaxDrainedErrors; ++i) {
    const sss::gl::GLenum error = gl.GetError();
    if (error == sss::gl::NO_ERROR) return;
    log(ctx, SSS_LOG_WARNING, "the host left " + sss::gl::error_name(error) + " pending before the sss call; cleared");
  }
}

sss_result check_gl_errors(sss_context* ctx, const sss::gl::Functions& gl, const char* what) {
  const sss::gl::GLenum error = gl.GetError();
  if (error == sss::gl::NO_ERROR) return SSS_OK;
  drain_host_errors(nullptr, gl);  // leave no error behind
  return fail(ctx, SSS_ERROR_GL, "%s raised %s", what, sss::gl::error_name(error).c_str());
}

sss_result require_module_objects(sss_context* ctx) {
  const sss::gl::Functions& gl = ctx->gl;
  if (ctx->filter.needs_rebuild()) {
    ctx->steady.valid = false;  // new objects: the next frame checks them
    std::string message;
    sss_result r = ctx->filter.rebuild(&message);
    if (r == SSS_OK) {
      r = check_gl_errors(ctx, gl, "rebuilding the module's GL objects");
      if (r != SSS_OK) {
        ctx->filter.destroy();
      } else {
        log(ctx, SSS_LOG_INFO,
            std::string("rebuilt the module's GL objects in the current GL context (shaders in ") +
                sss::gl::glsl_variant_name(ctx->filter.variant()) + ")");
      }
      return r;
    }
    drain_host_errors(nullptr, gl);
    return fail(ctx, r, "rebuilding the module's GL objects in the current context: " + message);
  }
  if (ctx->filter.objects_present()) return SSS_OK;
  ctx->filter.forget();
  ctx->steady.valid = false;  // no frame may trust the forgotten names
  ctx->lut_textures.clear();  // gone with their context too (names only: nothing is deleted)
  return fail(ctx, SSS_ERROR_NO_CONTEXT,
              "the module's GL objects are not in the current GL context (the context the module was created in "
              "was lost or destroyed, or another one is current); they were forgotten, not deleted, and the next "
              "call rebuilds them in the context current then");
}

}  // namespace sss::api
