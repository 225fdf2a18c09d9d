#include <cstdarg>
#include <cstdio>

#include "context.hpp"
#include "internal_exports.hpp"

namespace sss::api {

void log(const sss_context* ctx, int level, const std::string& message) {
  if (ctx != nullptr && ctx->log != nullptr) ctx->log(level, message.c_str(), ctx->log_user);
}

sss_result fail(sss_context* ctx, sss_result code, const std::string& message) {
  const std::string text = std::string(sss_result_string(code)) + ": " + message;
  if (ctx != nullptr) {
    ctx->last_error = text;
    log(ctx, SSS_LOG_ERROR, text);
  } else {
    sss_internal_set_thread_error(text.c_str());  // the runtime library's copy (internal_exports.hpp)
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
