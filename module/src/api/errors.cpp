#include <cstdarg>
#include <cstdio>

#include "context.hpp"

namespace sss::api {

std::string& thread_error() {
  thread_local std::string message;
  return message;
}

void log(const sss_context* ctx, int level, const std::string& message) {
  if (ctx != nullptr && ctx->log != nullptr) ctx->log(level, message.c_str(), ctx->log_user);
}

sss_result fail(sss_context* ctx, sss_result code, const std::string& message) {
  const std::string text = std::string(sss_result_string(code)) + ": " + message;
  if (ctx != nullptr) {
    ctx->last_error = text;
    log(ctx, SSS_LOG_ERROR, text);
  } else {
    thread_error() = text;
  }
  return code;
}

sss_result fail(sss_context* ctx, sss_result code, const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return fail(ctx, code, std::string(buffer));
}

}  // namespace sss::api

extern "C" {

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

SSS_API const char* sss_last_error(const sss_context* ctx) {
  return ctx != nullptr ? ctx->last_error.c_str() : sss::api::thread_error().c_str();
}

}  // extern "C"
