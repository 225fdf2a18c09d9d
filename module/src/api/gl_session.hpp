// Per-call GL bookkeeping shared by the entry points that touch GL: is a context current, clear the
// host's pending errors (logged, since GL cannot re-raise them), and turn an error raised by the
// module's own work into SSS_ERROR_GL.
#pragma once

#include "context.hpp"

namespace sss::api {

// SSS_ERROR_NO_CONTEXT when glGetString(GL_VERSION) gives NULL (nothing current on this thread).
sss_result require_current_context(sss_context* ctx, const sss::gl::Functions& gl);
void drain_host_errors(const sss_context* ctx, const sss::gl::Functions& gl);
// SSS_OK, or SSS_ERROR_GL naming the first error raised since the last drain, with `what`.
sss_result check_gl_errors(sss_context* ctx, const sss::gl::Functions& gl, const char* what);
// The module's GL objects in the current context (call inside a StateGuard). When they are found
// missing (the context they were built in was lost or destroyed, or another one is current) they
// are forgotten, not deleted, and SSS_ERROR_NO_CONTEXT is returned; the next call rebuilds them in
// whatever context is current then (and fails with init's error if that fails, retrying after).
sss_result require_module_objects(sss_context* ctx);

}  // namespace sss::api
