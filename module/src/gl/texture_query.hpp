// What the module needs to know about a host texture, asked of the GL without changing anything
// but the binding of unit 0 (which the caller's StateGuard restores).
#pragma once

#include <string>

#include "gl_functions.hpp"

namespace sss::gl {

struct TextureInfo {
  GLuint name = 0;
  GLint internal_format = 0;
  int width = 0, height = 0;
};

// SSS_OK, or SSS_ERROR_INVALID_TEXTURE with a message naming `role` and the name: 0, not a texture
// name (never bound, or deleted), or not a GL_TEXTURE_2D. Needs the GL error flag clear on entry.
// With query_level false (no glGetTexLevelParameteriv: OpenGL ES 3.0) only the name and target are
// checked and format and size are left 0.
sss_result query_texture_2d(const Functions& gl, GLuint name, const char* role, bool query_level,
                            TextureInfo* out, std::string* message);

bool is_color_format(GLint f);          // RGBA16F, RGBA32F
bool is_hardware_depth_format(GLint f); // DEPTH_COMPONENT*, DEPTH*_STENCIL8
bool is_linear_depth_format(GLint f);   // R16F, R32F
bool is_depth_stencil_format(GLint f);  // DEPTH24_STENCIL8, DEPTH32F_STENCIL8

}  // namespace sss::gl
