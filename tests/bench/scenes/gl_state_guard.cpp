#include "gl_state_guard.hpp"

using namespace host_gl;

namespace sss_bench::detail {

namespace {

constexpr GLenum kCapabilities[] = {
    GL_BLEND,           GL_SCISSOR_TEST,       GL_STENCIL_TEST,       GL_CULL_FACE,
    GL_DEPTH_TEST,      GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP,       GL_RASTERIZER_DISCARD,
    GL_FRAMEBUFFER_SRGB, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_COLOR_LOGIC_OP, GL_PRIMITIVE_RESTART,
    GL_POLYGON_SMOOTH,  GL_CLIP_DISTANCE0,     GL_CLIP_DISTANCE1,     GL_CLIP_DISTANCE2,
    GL_CLIP_DISTANCE3,  GL_CLIP_DISTANCE4,     GL_CLIP_DISTANCE5,     GL_CLIP_DISTANCE6,
    GL_CLIP_DISTANCE7};
constexpr GLenum kPack[4] = {GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS};
constexpr GLenum kUnpack[6] = {GL_UNPACK_ALIGNMENT,  GL_UNPACK_ROW_LENGTH,  GL_UNPACK_SKIP_ROWS,
                               GL_UNPACK_SKIP_PIXELS, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES};

void set_enabled(GLenum capability, bool on) {
  if (on)
    glEnable(capability);
  else
    glDisable(capability);
}

}  // namespace

GlStateGuard::GlStateGuard() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &textures_[unit]);
    glGetIntegerv(GL_SAMPLER_BINDING, &samplers_[unit]);
    glBindSampler(static_cast<GLuint>(unit), 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer_);
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
  for (int i = 0; i < 4; ++i) glGetIntegerv(kPack[i], &pack_[i]);
  for (int i = 0; i < 6; ++i) glGetIntegerv(kUnpack[i], &unpack_[i]);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func_);
  glGetIntegerv(GL_CULL_FACE_MODE, &cull_face_mode_);
  glGetIntegerv(GL_FRONT_FACE, &front_face_);
  glGetIntegerv(GL_POLYGON_MODE, polygon_mode_);
  static_assert(sizeof kCapabilities / sizeof kCapabilities[0] == kCapabilityCount, "capability count");
  for (int i = 0; i < kCapabilityCount; ++i) enabled_[i] = glIsEnabled(kCapabilities[i]);
  glGetIntegerv(GL_CLAMP_READ_COLOR, &clamp_read_color_);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
  glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_);
  glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &polygon_offset_factor_);
  glGetFloatv(GL_POLYGON_OFFSET_UNITS, &polygon_offset_units_);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear_color_);
  glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clear_depth_);

  for (GLenum capability : kCapabilities) glDisable(capability);
  glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  for (int i = 0; i < 4; ++i) glPixelStorei(kPack[i], i == 0 ? 1 : 0);
  for (int i = 0; i < 6; ++i) glPixelStorei(kUnpack[i], i == 0 ? 1 : 0);
}

GlStateGuard::~GlStateGuard() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glUseProgram(static_cast<GLuint>(program_));
  glBindVertexArray(static_cast<GLuint>(vertex_array_));
  glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(textures_[unit]));
    glBindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(samplers_[unit]));
  }
  glActiveTexture(static_cast<GLenum>(active_texture_));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer_));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
  for (int i = 0; i < 4; ++i) glPixelStorei(kPack[i], pack_[i]);
  for (int i = 0; i < 6; ++i) glPixelStorei(kUnpack[i], unpack_[i]);
  glDepthFunc(static_cast<GLenum>(depth_func_));
  glCullFace(static_cast<GLenum>(cull_face_mode_));
  glFrontFace(static_cast<GLenum>(front_face_));
  // Core profiles keep one polygon mode for both faces.
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
  for (int i = 0; i < kCapabilityCount; ++i) set_enabled(kCapabilities[i], enabled_[i] == GL_TRUE);
  glClampColor(GL_CLAMP_READ_COLOR, static_cast<GLenum>(clamp_read_color_));
  glDepthMask(depth_mask_);
  glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
  glPolygonOffset(polygon_offset_factor_, polygon_offset_units_);
  glClearColor(clear_color_[0], clear_color_[1], clear_color_[2], clear_color_[3]);
  glClearDepth(static_cast<double>(clear_depth_));
}

}  // namespace sss_bench::detail

