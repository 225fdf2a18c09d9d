#include "gl_functions.hpp"

#include <cstdio>

namespace sss::gl {

bool load_functions(sss_get_proc_address_fn get_proc_address, void* user, const Api& api, Functions* out,
                    std::string* missing) {
  Functions f;
  f.api = api;
  // Function pointers are converted from the loader's void* (POSIX and Windows guarantee this works).
#define SSS_GL_LOAD_REQUIRED(ret, name, params)                                \
  f.name = reinterpret_cast<decltype(f.name)>(get_proc_address("gl" #name, user)); \
  if (f.name == nullptr) {                                                     \
    if (missing) *missing = "gl" #name;                                        \
    return false;                                                              \
  }
  SSS_GL_REQUIRED_FUNCTIONS(SSS_GL_LOAD_REQUIRED)
  if (!api.es) {
    SSS_GL_DESKTOP_FUNCTIONS(SSS_GL_LOAD_REQUIRED)
    SSS_GL_TEXTURE_QUERY_FUNCTIONS(SSS_GL_LOAD_REQUIRED)
  } else {
    SSS_GL_ES_FUNCTIONS(SSS_GL_LOAD_REQUIRED)
  }
#undef SSS_GL_LOAD_REQUIRED
#define SSS_GL_LOAD_OPTIONAL(ret, name, params) \
  f.name = reinterpret_cast<decltype(f.name)>(get_proc_address("gl" #name, user));
  if (api.es && api.version() < 32) {
    // Before ES 3.2, KHR_debug's entry points carry the KHR suffix on OpenGL ES.
#define SSS_GL_LOAD_KHR(ret, name, params) \
  f.name = reinterpret_cast<decltype(f.name)>(get_proc_address("gl" #name "KHR", user));
    SSS_GL_DEBUG_FUNCTIONS(SSS_GL_LOAD_KHR)
#undef SSS_GL_LOAD_KHR
  } else {
    SSS_GL_DEBUG_FUNCTIONS(SSS_GL_LOAD_OPTIONAL)
  }
  if (api.es) {
    SSS_GL_TEXTURE_QUERY_FUNCTIONS(SSS_GL_LOAD_OPTIONAL)
    SSS_GL_ES_TIMER_FUNCTIONS(SSS_GL_LOAD_OPTIONAL)
  }
  if (!api.es && api.version() >= 43) {
    SSS_GL_COMPUTE_FUNCTIONS(SSS_GL_LOAD_OPTIONAL)
  }
#define SSS_GL_COMPUTE_PRESENT(ret, name, params) &&f.name != nullptr
  f.has_compute = !api.es && api.version() >= 43 SSS_GL_COMPUTE_FUNCTIONS(SSS_GL_COMPUTE_PRESENT);
#undef SSS_GL_COMPUTE_PRESENT
  // ES 3.0 has no texture level query; ES 3.1 and desktop GL do.
  f.has_texture_query = f.GetTexLevelParameteriv != nullptr && (!api.es || api.version() >= 31);
#undef SSS_GL_LOAD_OPTIONAL
  *out = f;
  return true;
}

std::string error_name(GLenum error) {
  switch (error) {
    case NO_ERROR: return "GL_NO_ERROR";
    case INVALID_ENUM: return "GL_INVALID_ENUM";
    case INVALID_VALUE: return "GL_INVALID_VALUE";
    case INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: break;
  }
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04X", error);
  return buffer;
}

std::string format_name(GLint internal_format) {
  switch (static_cast<GLenum>(internal_format)) {
    case RGBA16F: return "GL_RGBA16F";
    case RGBA32F: return "GL_RGBA32F";
    case R16F: return "GL_R16F";
    case R32F: return "GL_R32F";
    case R8: return "GL_R8";
    case RGBA8: return "GL_RGBA8";
    case SRGB8_ALPHA8: return "GL_SRGB8_ALPHA8";
    case R8UI: return "GL_R8UI";
    case R16UI: return "GL_R16UI";
    case R11F_G11F_B10F: return "GL_R11F_G11F_B10F";
    case DEPTH_COMPONENT16: return "GL_DEPTH_COMPONENT16";
    case DEPTH_COMPONENT24: return "GL_DEPTH_COMPONENT24";
    case DEPTH_COMPONENT32: return "GL_DEPTH_COMPONENT32";
    case DEPTH_COMPONENT32F: return "GL_DEPTH_COMPONENT32F";
    case DEPTH24_STENCIL8: return "GL_DEPTH24_STENCIL8";
    case DEPTH32F_STENCIL8: return "GL_DEPTH32F_STENCIL8";
    default: break;
  }
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04X", static_cast<unsigned>(internal_format));
  return buffer;
}

}  // namespace sss::gl
