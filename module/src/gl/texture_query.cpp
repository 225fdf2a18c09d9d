#include "texture_query.hpp"

#include <cstdio>

namespace sss::gl {

sss_result query_texture_2d(const Functions& gl, GLuint name, const char* role, bool query_level,
                            TextureInfo* out, std::string* message) {
  char buffer[200];
  if (name == 0) {
    std::snprintf(buffer, sizeof buffer, "%s is 0 (no texture)", role);
    *message = buffer;
    return SSS_ERROR_INVALID_TEXTURE;
  }
  // glIsTexture is false for names never bound (binding one would create a texture in the host's
  // namespace) and for deleted ones.
  if (!gl.IsTexture(name)) {
    std::snprintf(buffer, sizeof buffer, "%s = %u is not a texture name", role, name);
    *message = buffer;
    return SSS_ERROR_INVALID_TEXTURE;
  }
  gl.ActiveTexture(TEXTURE0);
  gl.BindTexture(TEXTURE_2D, name);
  if (gl.GetError() != NO_ERROR) {  // GL_INVALID_OPERATION: the texture has another target
    std::snprintf(buffer, sizeof buffer, "%s = %u is not a GL_TEXTURE_2D (multisample, array, cube or 3D?)",
                  role, name);
    *message = buffer;
    return SSS_ERROR_INVALID_TEXTURE;
  }
  TextureInfo info;
  info.name = name;
  if (!query_level) {  // OpenGL ES 3.0: the caller takes format and size from the frame description
    *out = info;
    return SSS_OK;
  }
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &info.internal_format);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_WIDTH, &info.width);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_HEIGHT, &info.height);
  if (info.width <= 0 || info.height <= 0) {
    std::snprintf(buffer, sizeof buffer, "%s = %u has no storage at level 0 (%dx%d)", role, name, info.width,
                  info.height);
    *message = buffer;
    return SSS_ERROR_INVALID_TEXTURE;
  }
  *out = info;
  return SSS_OK;
}

bool is_color_format(GLint f) { return f == static_cast<GLint>(RGBA16F) || f == static_cast<GLint>(RGBA32F); }

bool is_depth_stencil_format(GLint f) {
  return f == static_cast<GLint>(DEPTH24_STENCIL8) || f == static_cast<GLint>(DEPTH32F_STENCIL8);
}

bool is_hardware_depth_format(GLint f) {
  return f == static_cast<GLint>(DEPTH_COMPONENT16) || f == static_cast<GLint>(DEPTH_COMPONENT24) ||
         f == static_cast<GLint>(DEPTH_COMPONENT32) || f == static_cast<GLint>(DEPTH_COMPONENT32F) ||
         is_depth_stencil_format(f);
}

bool is_linear_depth_format(GLint f) { return f == static_cast<GLint>(R16F) || f == static_cast<GLint>(R32F); }

}  // namespace sss::gl
