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

}  // namespace sss::api
