// Runtime library only: the entry points of internal_exports.hpp, and sss_last_error's per-thread
// message, which the copies of errors.cpp in both libraries write through them.
#include "internal_exports.hpp"

#include <string>

#include "../math/fitters.hpp"
#include "context.hpp"

namespace {
std::string& thread_error() {
  thread_local std::string message;
  return message;
}
}  // namespace

extern "C" {

SSS_API void sss_internal_register_fitters(const void* fitters) {
  if (fitters != nullptr) sss::math::set_fitters(static_cast<const sss::math::Fitters*>(fitters));
}

SSS_API void sss_internal_set_thread_error(const char* message) { thread_error() = message; }

SSS_API const char* sss_last_error(const sss_context* ctx) {
  return ctx != nullptr ? ctx->last_error.c_str() : thread_error().c_str();
}

SSS_API uint32_t sss_get_version(void) { return SSS_VERSION; }

SSS_API const char* sss_result_string(sss_result r) {
  switch (r) {
    case SSS_OK: return "SSS_OK";
    case SSS_ERROR_INVALID_ARGUMENT: return "SSS_ERROR_INVALID_ARGUMENT";
    case SSS_ERROR_UNSUPPORTED: return "SSS_ERROR_UNSUPPORTED";
    case SSS_ERROR_GL_FUNCTION_MISSING: return "SSS_ERROR_GL_FUNCTION_MISSING";
    case SSS_ERROR_SHADER_COMPILE: return "SSS_ERROR_SHADER_COMPILE";
    case SSS_ERROR_FRAMEBUFFER: return "SSS_ERROR_FRAMEBUFFER";
    case SSS_ERROR_INVALID_TEXTURE: return "SSS_ERROR_INVALID_TEXTURE";
    case SSS_ERROR_OUT_OF_MEMORY: return "SSS_ERROR_OUT_OF_MEMORY";
    case SSS_ERROR_GL: return "SSS_ERROR_GL";
    case SSS_ERROR_NO_CONTEXT: return "SSS_ERROR_NO_CONTEXT";
    case SSS_ERROR_INVALID_OPERATION: return "SSS_ERROR_INVALID_OPERATION";
  }
  return "SSS_ERROR_UNKNOWN";
}

}  // extern "C"
