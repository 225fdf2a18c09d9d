// Saves the GL state the head scenes touch, sets the defaults they rely on, and restores the saved
// values on destruction. Internal to sss_bench_scenes.
#pragma once

#include "host_gl.hpp"

namespace sss_bench::detail {

class GlStateGuard {
 public:
  static constexpr int kUnits = 7;  // texture units 0..6 are used (4, 5: the pre-integrated LUTs, 6: N_low)

  // Saves, then sets what could change the result: every capability of the list in the .cpp off
  // (blend, scissor, stencil, cull, clip distances, primitive restart, ...), full colour and depth
  // masks, filled polygons, no read clamping, pixel store defaults, no pixel buffers, no samplers
  // on the units used.
  GlStateGuard();
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  GLint draw_framebuffer_ = 0, read_framebuffer_ = 0, viewport_[4] = {0, 0, 0, 0}, program_ = 0,
        vertex_array_ = 0, array_buffer_ = 0, active_texture_ = 0, textures_[kUnits] = {0, 0, 0, 0, 0, 0, 0},
        samplers_[kUnits] = {0, 0, 0, 0, 0, 0, 0}, pack_buffer_ = 0, unpack_buffer_ = 0, pack_[4] = {0, 0, 0, 0},
        unpack_[6] = {0, 0, 0, 0, 0, 0}, depth_func_ = 0, cull_face_mode_ = 0, front_face_ = 0,
        polygon_mode_[2] = {0, 0};
  static constexpr int kCapabilityCount = 21;
  GLboolean enabled_[kCapabilityCount] = {};
  GLint clamp_read_color_ = 0;
  GLboolean depth_mask_ = 0, color_mask_[4] = {0, 0, 0, 0};
  GLfloat polygon_offset_factor_ = 0, polygon_offset_units_ = 0, clear_color_[4] = {0, 0, 0, 0};
  GLfloat clear_depth_ = 0;
};

}  // namespace sss_bench::detail
