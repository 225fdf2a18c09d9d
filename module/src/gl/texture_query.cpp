#include "texture_query.hpp"

#include <cstdio>

namespace sss::gl {

sss_result query_texture(const Functions& gl, GLuint name, const char* role, bool query_level, TextureInfo* out,
                         std::string* message) {
  char buffer[240];
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
  TextureInfo info;
  info.name = name;
  gl.ActiveTexture(TEXTURE0);
  gl.BindTexture(TEXTURE_2D, name);
  if (gl.GetError() != NO_ERROR) {  // GL_INVALID_OPERATION: the texture has another target
    if (!gl.has_multisample_textures()) {  // OpenGL ES 3.0: no multisampled textures to try
      std::snprintf(buffer, sizeof buffer, "%s = %u is not a GL_TEXTURE_2D (array, cube or 3D?)", role, name);
      *message = buffer;
      return SSS_ERROR_INVALID_TEXTURE;
    }
    gl.BindTexture(TEXTURE_2D_MULTISAMPLE, name);
    if (gl.GetError() != NO_ERROR) {
      std::snprintf(buffer, sizeof buffer,
                    "%s = %u is neither GL_TEXTURE_2D nor GL_TEXTURE_2D_MULTISAMPLE (array, cube or 3D?)", role,
                    name);
      *message = buffer;
      return SSS_ERROR_INVALID_TEXTURE;
    }
    info.target = TEXTURE_2D_MULTISAMPLE;
  }
  if (!query_level) {  // OpenGL ES 3.0: the caller takes format and size from the frame description
    *out = info;
    return SSS_OK;
  }
  gl.GetTexLevelParameteriv(info.target, 0, TEXTURE_INTERNAL_FORMAT, &info.internal_format);
  gl.GetTexLevelParameteriv(info.target, 0, TEXTURE_WIDTH, &info.width);
  gl.GetTexLevelParameteriv(info.target, 0, TEXTURE_HEIGHT, &info.height);
  if (info.multisampled()) {
    GLint fixed = 1;
    gl.GetTexLevelParameteriv(info.target, 0, TEXTURE_SAMPLES, &info.samples);
    gl.GetTexLevelParameteriv(info.target, 0, TEXTURE_FIXED_SAMPLE_LOCATIONS, &fixed);
    info.fixed_locations = fixed != 0 ? 1 : 0;
  }
  if (info.width <= 0 || info.height <= 0 || (info.multisampled() && info.samples <= 0)) {
    if (info.multisampled()) {
      // The usual cause: glTexImage2DMultisample was refused (a sample count above GL_MAX_*_SAMPLES).
      GLint max_samples = 0;
      gl.GetIntegerv(MAX_SAMPLES, &max_samples);
      std::snprintf(buffer, sizeof buffer,
                    "%s = %u (GL_TEXTURE_2D_MULTISAMPLE) has no storage (%dx%d, %d samples); this context "
                    "supports at most %d samples",
                    role, name, info.width, info.height, info.samples, max_samples);
    } else {
      std::snprintf(buffer, sizeof buffer, "%s = %u has no storage at level 0 (%dx%d)", role, name, info.width,
                    info.height);
    }
    *message = buffer;
    return SSS_ERROR_INVALID_TEXTURE;
  }
  *out = info;
  return SSS_OK;
}

std::string describe_target(const TextureInfo& t) {
  if (!t.multisampled()) return "GL_TEXTURE_2D";
  return "GL_TEXTURE_2D_MULTISAMPLE with " + std::to_string(t.samples) + " samples";
}

bool is_color_format(GLint f) { return f == static_cast<GLint>(RGBA16F) || f == static_cast<GLint>(RGBA32F); }

bool is_alpha_free_color_format(GLint f) { return f == static_cast<GLint>(R11F_G11F_B10F); }

bool is_albedo_format(GLint f) {
  return f == static_cast<GLint>(SRGB8_ALPHA8) || f == static_cast<GLint>(RGBA8) || f == static_cast<GLint>(RGBA16F);
}

bool is_strength_format(GLint f) {
  return f == static_cast<GLint>(R8) || f == static_cast<GLint>(R16F) || f == static_cast<GLint>(R32F);
}

bool is_profile_format(GLint f) { return f == static_cast<GLint>(R8UI) || f == static_cast<GLint>(R16UI); }

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
