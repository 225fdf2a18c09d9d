#include "state_guard.hpp"

namespace sss::gl {

StateGuard::StateGuard(const Functions& gl, bool enabled, const Scope& scope)
    : gl_(gl), enabled_(enabled), scope_(scope) {
  if (!enabled_) return;
  // What the context lacks is never changed either.
  scope_.image_unit = scope_.image_unit && gl_.has_compute;
  scope_.multisample = scope_.multisample && gl_.has_multisample_textures();  // an invalid enum on ES 3.0
  gl_.GetIntegerv(CURRENT_PROGRAM, &program_);
  gl_.GetIntegerv(VERTEX_ARRAY_BINDING, &vertex_array_);
  gl_.GetIntegerv(DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  gl_.GetIntegerv(READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  gl_.GetIntegerv(RENDERBUFFER_BINDING, &renderbuffer_);
  gl_.GetIntegerv(PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
  gl_.GetIntegerv(ACTIVE_TEXTURE, &active_texture_);
  for (int unit = 0; unit < kUnitCount; ++unit) {
    if (!saves_unit(unit)) continue;
    gl_.ActiveTexture(TEXTURE0 + static_cast<GLenum>(unit));
    gl_.GetIntegerv(TEXTURE_BINDING_2D, &textures_[static_cast<std::size_t>(unit)]);
    if (scope_.multisample) {
      gl_.GetIntegerv(TEXTURE_BINDING_2D_MULTISAMPLE, &multisample_textures_[static_cast<std::size_t>(unit)]);
    }
    gl_.GetIntegerv(SAMPLER_BINDING, &samplers_[static_cast<std::size_t>(unit)]);
  }
  gl_.ActiveTexture(static_cast<GLenum>(active_texture_));
  gl_.GetIntegerv(VIEWPORT, viewport_.data());
  if (msaa_write_back_in_scope()) {
    gl_.GetIntegeri_v(SAMPLE_MASK_VALUE, 0, &sample_mask_value_);
    multisample_ = gl_.IsEnabled(MULTISAMPLE);
    for (std::size_t i = 0; i < kBlendParameters.size(); ++i) gl_.GetIntegerv(kBlendParameters[i], &blend_[i]);
  }
  for (std::size_t i = 0; i < kCapabilities.size(); ++i) capabilities_[i] = gl_.IsEnabled(kCapabilities[i]);
  if (gl_.has_sample_mask()) sample_mask_ = gl_.IsEnabled(SAMPLE_MASK);
  if (gl_.desktop()) {
    for (std::size_t i = 0; i < kDesktopCapabilities.size(); ++i) {
      desktop_capabilities_[i] = gl_.IsEnabled(kDesktopCapabilities[i]);
    }
    for (int i = 0; i < kClipDistances; ++i) {
      clip_distances_[static_cast<std::size_t>(i)] = gl_.IsEnabled(CLIP_DISTANCE0 + static_cast<GLenum>(i));
    }
    gl_.GetIntegerv(POLYGON_MODE, polygon_mode_.data());
  }
  gl_.GetBooleanv(COLOR_WRITEMASK, color_mask_.data());
  if (scope_.image_unit) {
    for (GLuint unit = 0; unit < kImageUnits; ++unit) {
      ImageUnit& u = image_units_[unit];
      gl_.GetIntegeri_v(IMAGE_BINDING_NAME, unit, &u.name);
      gl_.GetIntegeri_v(IMAGE_BINDING_LEVEL, unit, &u.level);
      gl_.GetBooleani_v(IMAGE_BINDING_LAYERED, unit, &u.layered);
      gl_.GetIntegeri_v(IMAGE_BINDING_LAYER, unit, &u.layer);
      gl_.GetIntegeri_v(IMAGE_BINDING_ACCESS, unit, &u.access);
      gl_.GetIntegeri_v(IMAGE_BINDING_FORMAT, unit, &u.format);
    }
  }
  if (scope_.profiles) {
    gl_.GetIntegerv(UNIFORM_BUFFER_BINDING, &uniform_buffer_);
    gl_.GetIntegeri_v(UNIFORM_BUFFER_BINDING, 0, &uniform_buffer0_);
    gl_.GetInteger64i_v(UNIFORM_BUFFER_START, 0, &uniform_buffer0_start_);
    gl_.GetInteger64i_v(UNIFORM_BUFFER_SIZE, 0, &uniform_buffer0_size_);
  }
  if (scope_.pack) {
    gl_.GetIntegerv(PIXEL_PACK_BUFFER_BINDING, &pack_buffer_);
    for (std::size_t i = 0; i < kPackParameters.size(); ++i) gl_.GetIntegerv(kPackParameters[i], &pack_[i]);
  }
  if (scope_.depth) {
    gl_.GetIntegerv(DEPTH_FUNC, &depth_func_);
    gl_.GetBooleanv(DEPTH_WRITEMASK, &depth_mask_);
    gl_.GetFloatv(DEPTH_RANGE, depth_range_.data());
  }
  if (!scope_.stencil) return;
  save_stencil_face(STENCIL_FUNC, STENCIL_REF, STENCIL_VALUE_MASK, STENCIL_FAIL, STENCIL_PASS_DEPTH_FAIL,
                    STENCIL_PASS_DEPTH_PASS, STENCIL_WRITEMASK, &front_);
  save_stencil_face(STENCIL_BACK_FUNC, STENCIL_BACK_REF, STENCIL_BACK_VALUE_MASK, STENCIL_BACK_FAIL,
                    STENCIL_BACK_PASS_DEPTH_FAIL, STENCIL_BACK_PASS_DEPTH_PASS, STENCIL_BACK_WRITEMASK, &back_);
}

void StateGuard::save_stencil_face(GLenum func, GLenum ref, GLenum value_mask, GLenum fail, GLenum depth_fail,
                                   GLenum depth_pass, GLenum write_mask, StencilFace* face) const {
  gl_.GetIntegerv(func, &face->func);
  gl_.GetIntegerv(ref, &face->ref);
  gl_.GetIntegerv(value_mask, &face->value_mask);
  gl_.GetIntegerv(fail, &face->fail);
  gl_.GetIntegerv(depth_fail, &face->depth_fail);
  gl_.GetIntegerv(depth_pass, &face->depth_pass);
  gl_.GetIntegerv(write_mask, &face->write_mask);
}

void StateGuard::restore_stencil_face(GLenum face_enum, const StencilFace& face) const {
  gl_.StencilFuncSeparate(face_enum, static_cast<GLenum>(face.func), face.ref, static_cast<GLuint>(face.value_mask));
  gl_.StencilOpSeparate(face_enum, static_cast<GLenum>(face.fail), static_cast<GLenum>(face.depth_fail),
                        static_cast<GLenum>(face.depth_pass));
  gl_.StencilMaskSeparate(face_enum, static_cast<GLuint>(face.write_mask));
}

#ifdef SSS_STATE_GUARD_TEST_HOOK
std::atomic<uint32_t>& restore_skip_mask_for_tests() {
  static std::atomic<uint32_t> mask{0};
  return mask;
}
#endif

namespace {
// The restore groups to leave out: none, but in the tests' build when the hook asks.
uint32_t restore_skip_mask() {
#ifdef SSS_STATE_GUARD_TEST_HOOK
  return restore_skip_mask_for_tests().load(std::memory_order_relaxed);
#else
  return 0;
#endif
}
}  // namespace

StateGuard::~StateGuard() {
  if (!enabled_) return;
  const uint32_t skip = restore_skip_mask();
  const auto restore = [skip](uint32_t group) { return (skip & group) == 0; };
  if (scope_.stencil && restore(restore_group::stencil)) {
    restore_stencil_face(FRONT, front_);
    restore_stencil_face(BACK, back_);
  }
  if (scope_.depth && restore(restore_group::depth)) {
    gl_.DepthFunc(static_cast<GLenum>(depth_func_));
    gl_.DepthMask(depth_mask_);
    gl_.set_depth_range(depth_range_[0], depth_range_[1]);
  }
  if (restore(restore_group::color_mask)) gl_.ColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
  if (gl_.desktop()) {
    if (restore(restore_group::polygon_mode)) gl_.PolygonMode(FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
    for (int i = 0; i < kClipDistances && restore(restore_group::clip_distances); ++i) {
      const GLenum cap = CLIP_DISTANCE0 + static_cast<GLenum>(i);
      clip_distances_[static_cast<std::size_t>(i)] ? gl_.Enable(cap) : gl_.Disable(cap);
    }
    for (std::size_t i = 0; i < kDesktopCapabilities.size() && restore(restore_group::desktop_enables); ++i) {
      desktop_capabilities_[i] ? gl_.Enable(kDesktopCapabilities[i]) : gl_.Disable(kDesktopCapabilities[i]);
    }
    if (msaa_write_back_in_scope() && restore(restore_group::desktop_enables)) {
      multisample_ ? gl_.Enable(MULTISAMPLE) : gl_.Disable(MULTISAMPLE);
    }
  }
  if (gl_.has_sample_mask() && restore(restore_group::sample_mask_enable)) {
    sample_mask_ ? gl_.Enable(SAMPLE_MASK) : gl_.Disable(SAMPLE_MASK);
  }
  for (std::size_t i = 0; i < kCapabilities.size() && restore(restore_group::enables); ++i) {
    capabilities_[i] ? gl_.Enable(kCapabilities[i]) : gl_.Disable(kCapabilities[i]);
  }
  if (restore(restore_group::viewport)) gl_.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  if (msaa_write_back_in_scope() && restore(restore_group::sample_mask_value)) {
    gl_.SampleMaski(0, static_cast<GLbitfield>(sample_mask_value_));
  }
  if (msaa_write_back_in_scope() && restore(restore_group::blend_function)) {
    const auto e = [this](std::size_t i) { return static_cast<GLenum>(blend_[i]); };
    gl_.BlendFuncSeparate(e(0), e(1), e(2), e(3));
    gl_.BlendEquationSeparate(e(4), e(5));
  }
  for (int unit = 0; unit < kUnitCount && restore(restore_group::texture_units); ++unit) {
    if (!saves_unit(unit)) continue;
    gl_.ActiveTexture(TEXTURE0 + static_cast<GLenum>(unit));
    gl_.BindTexture(TEXTURE_2D, static_cast<GLuint>(textures_[static_cast<std::size_t>(unit)]));
    if (scope_.multisample) {
      gl_.BindTexture(TEXTURE_2D_MULTISAMPLE,
                      static_cast<GLuint>(multisample_textures_[static_cast<std::size_t>(unit)]));
    }
    gl_.BindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(samplers_[static_cast<std::size_t>(unit)]));
  }
  if (restore(restore_group::active_texture)) gl_.ActiveTexture(static_cast<GLenum>(active_texture_));
  if (restore(restore_group::unpack_buffer)) gl_.BindBuffer(PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
  if (restore(restore_group::renderbuffer)) gl_.BindRenderbuffer(RENDERBUFFER, static_cast<GLuint>(renderbuffer_));
  if (restore(restore_group::read_framebuffer)) {
    gl_.BindFramebuffer(READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  }
  if (restore(restore_group::draw_framebuffer)) {
    gl_.BindFramebuffer(DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  }
  if (scope_.image_unit && restore(restore_group::image_unit)) restore_image_units();
  if (scope_.profiles && restore(restore_group::uniform_buffer)) restore_uniform_buffer();
  if (scope_.pack && restore(restore_group::pack_state)) {
    gl_.BindBuffer(PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer_));
    for (std::size_t i = 0; i < kPackParameters.size(); ++i) gl_.PixelStorei(kPackParameters[i], pack_[i]);
  }
  if (restore(restore_group::vertex_array)) gl_.BindVertexArray(static_cast<GLuint>(vertex_array_));
  // A program the host deleted while it was current lives on only while current: once the
  // passes bound another, it is gone and binding its name would raise GL_INVALID_VALUE. Zero is
  // what the host's own next glUseProgram would have found then.
  const GLuint program = static_cast<GLuint>(program_);
  if (restore(restore_group::program)) gl_.UseProgram(program != 0 && gl_.IsProgram(program) ? program : 0);
}

void StateGuard::restore_image_units() const {
  for (GLuint unit = 0; unit < kImageUnits; ++unit) {
    // A texture the host deleted meanwhile left the unit by itself (glDeleteTextures unbinds it),
    // so a name that is no texture any more restores as 0.
    const ImageUnit& u = image_units_[unit];
    const GLuint name = static_cast<GLuint>(u.name);
    gl_.BindImageTexture(unit, name != 0 && gl_.IsTexture(name) ? name : 0, u.level, u.layered, u.layer,
                         static_cast<GLenum>(u.access), static_cast<GLenum>(u.format));
  }
}

void StateGuard::restore_uniform_buffer() const {
  // Binding point 0 as a range, or whole (size 0: glBindBufferBase); a buffer the host deleted
  // meanwhile left the binding by itself, so its name restores as 0. The generic binding last:
  // glBindBufferBase/Range set it too.
  const GLuint name = static_cast<GLuint>(uniform_buffer0_);
  if (name == 0 || !gl_.IsBuffer(name)) {
    gl_.BindBufferBase(UNIFORM_BUFFER, 0, 0);
  } else if (uniform_buffer0_size_ == 0) {
    gl_.BindBufferBase(UNIFORM_BUFFER, 0, name);
  } else {
    gl_.BindBufferRange(UNIFORM_BUFFER, 0, name, static_cast<std::ptrdiff_t>(uniform_buffer0_start_),
                        static_cast<std::ptrdiff_t>(uniform_buffer0_size_));
  }
  const GLuint generic = static_cast<GLuint>(uniform_buffer_);
  gl_.BindBuffer(UNIFORM_BUFFER, generic != 0 && gl_.IsBuffer(generic) ? generic : 0);
}

void set_pass_state(const Functions& gl) {
  gl.Disable(SCISSOR_TEST);
  gl.Disable(DEPTH_TEST);
  gl.Disable(BLEND);
  gl.Disable(CULL_FACE);
  gl.Disable(RASTERIZER_DISCARD);
  gl.Disable(SAMPLE_ALPHA_TO_COVERAGE);
  gl.Disable(SAMPLE_COVERAGE);
  gl.Disable(POLYGON_OFFSET_FILL);
  if (gl.has_sample_mask()) gl.Disable(SAMPLE_MASK);
  // ES has none of these: no sRGB enable (the module's targets are float, never converted), no
  // depth clamp, logic op, clip distances or polygon mode.
  if (gl.desktop()) {
    gl.Disable(FRAMEBUFFER_SRGB);
    gl.Disable(DEPTH_CLAMP);
    gl.Disable(COLOR_LOGIC_OP);
    for (GLenum i = 0; i < 8; ++i) gl.Disable(CLIP_DISTANCE0 + i);
    gl.PolygonMode(FRONT_AND_BACK, FILL);
  }
  gl.ColorMask(1, 1, 1, 1);
}

}  // namespace sss::gl
