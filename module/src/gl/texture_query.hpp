// What the module needs to know about a host texture, asked of the GL without changing anything
// but the 2D and 2D-multisample bindings of unit 0 (which the caller's StateGuard restores).
#pragma once

#include <string>

#include "gl_functions.hpp"

namespace sss::gl {

struct TextureInfo {
  GLuint name = 0;
  GLenum target = TEXTURE_2D;  // TEXTURE_2D or TEXTURE_2D_MULTISAMPLE
  GLint internal_format = 0;
  int width = 0, height = 0;
  int samples = 0;                   // 0 for TEXTURE_2D; GL_TEXTURE_SAMPLES for a multisample texture
  GLboolean fixed_locations = 1;     // GL_TEXTURE_FIXED_SAMPLE_LOCATIONS (multisample only)

  bool multisampled() const { return target == TEXTURE_2D_MULTISAMPLE; }
};

// SSS_OK, or SSS_ERROR_INVALID_TEXTURE with a message naming `role` and the name: 0, not a texture
// name (never bound, or deleted), neither GL_TEXTURE_2D nor GL_TEXTURE_2D_MULTISAMPLE, or without
// storage. The target is found by binding the name to each target in turn on unit 0: binding a
// texture to a target other than its own raises GL_INVALID_OPERATION and changes nothing, and the
// error is read (cleared) here. GL_TEXTURE_2D_MULTISAMPLE is tried only where it exists (GL 3.2+,
// ES 3.1+; on ES 3.0 it is an invalid enum). Needs the GL error flag clear on entry.
// With query_level false (no glGetTexLevelParameteriv: OpenGL ES 3.0) only the name and target are
// checked and format, size and samples are left 0 (the caller takes them from the frame).
sss_result query_texture(const Functions& gl, GLuint name, const char* role, bool query_level, TextureInfo* out,
                         std::string* message);

// "GL_TEXTURE_2D" / "GL_TEXTURE_2D_MULTISAMPLE with 4 samples", for messages.
std::string describe_target(const TextureInfo& t);

bool is_color_format(GLint f);          // RGBA16F, RGBA32F
bool is_alpha_free_color_format(GLint f);  // R11F_G11F_B10F: a colour whose strength comes from a strength texture
bool is_albedo_format(GLint f);         // SRGB8_ALPHA8, RGBA8, RGBA16F (sss_frame.albedo_texture)
bool is_strength_format(GLint f);       // R8, R16F, R32F (sss_frame.strength_texture)
bool is_profile_format(GLint f);        // R8UI, R16UI (sss_frame.profile_texture)
bool is_hardware_depth_format(GLint f); // DEPTH_COMPONENT*, DEPTH*_STENCIL8
bool is_linear_depth_format(GLint f);   // R16F, R32F
bool is_depth_stencil_format(GLint f);  // DEPTH24_STENCIL8, DEPTH32F_STENCIL8

}  // namespace sss::gl
