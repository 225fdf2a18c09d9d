#include "separable_filter.hpp"

#include <atomic>
#include <cstdio>

#include "debug_label.hpp"
#include "program.hpp"
#include "state_guard.hpp"

namespace sss::gl {

namespace {
constexpr GLuint kSourceUnit = 0, kDepthUnit = 1, kOriginalUnit = 2, kNormalUnit = 3, kAccumulatedUnit = 3;

// A tag in [1025, 1025 + 2^20), exact in float, different for each init() in the process (modulo
// 2^20). It is stored as the sampler's GL_TEXTURE_MAX_LOD, which has no effect here: the sampler
// never reads mipmaps (GL_LINEAR/GL_NEAREST minification, texelFetch at level 0), and a maximum LOD
// above 0 does not change which of the two identical filters applies. Unlike the border colour
// (used before), the LOD range exists on OpenGL ES 3.0 too.
GLfloat next_sampler_tag() {
  static std::atomic<unsigned> counter{0};
  const unsigned n = counter.fetch_add(1, std::memory_order_relaxed) % (1u << 20);
  return 1025.0f + static_cast<GLfloat>(n);
}

void set_sampler(const Functions& f, GLuint sampler, GLenum filter) {
  f.SamplerParameteri(sampler, TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  f.SamplerParameteri(sampler, TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  f.SamplerParameteri(sampler, TEXTURE_WRAP_S, static_cast<GLint>(CLAMP_TO_EDGE));
  f.SamplerParameteri(sampler, TEXTURE_WRAP_T, static_cast<GLint>(CLAMP_TO_EDGE));
  f.SamplerParameteri(sampler, TEXTURE_COMPARE_MODE, static_cast<GLint>(NONE));
}
}  // namespace

sss_result SeparableFilter::init(const Functions* gl, GlslVariant variant, bool labels, std::string* message) {
  gl_ = gl;
  variant_ = variant;
  labels_ = labels;
  const Functions& f = *gl_;

  f.GenVertexArrays(1, &vertex_array_);
  // A framebuffer name becomes an object on first bind; the caller's StateGuard restores bindings.
  GLuint framebuffers[4] = {0, 0, 0, 0};
  f.GenFramebuffers(4, framebuffers);
  intermediate_framebuffer_ = framebuffers[0];
  output_framebuffer_ = framebuffers[1];
  stencil_source_framebuffer_ = framebuffers[2];
  accumulator_framebuffer_ = framebuffers[3];
  for (GLuint fb : framebuffers) f.BindFramebuffer(FRAMEBUFFER, fb);
  f.BindVertexArray(vertex_array_);
  // The stencil source is only ever read from, and has no colour.
  f.BindFramebuffer(READ_FRAMEBUFFER, stencil_source_framebuffer_);
  f.ReadBuffer(NONE);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, stencil_source_framebuffer_);
  const GLenum no_colour = NONE;
  f.DrawBuffers(1, &no_colour);  // glDrawBuffer is not in ES

  // Samplers: bilinear, clamped, no depth comparison (they override whatever parameters the host
  // set on its own textures, which the module never changes). The depth unit has its own: on ES a
  // depth texture is incomplete unless sampled GL_NEAREST (the passes only fetch whole texels).
  GLuint samplers[2] = {0, 0};
  f.GenSamplers(2, samplers);
  sampler_ = samplers[0];
  depth_sampler_ = samplers[1];
  set_sampler(f, sampler_, LINEAR);
  set_sampler(f, depth_sampler_, gl_->api.es ? NEAREST : LINEAR);
  // The maximum LOD carries the tag objects_present checks (see next_sampler_tag).
  sampler_tag_ = next_sampler_tag();
  f.SamplerParameterf(sampler_, TEXTURE_MAX_LOD, sampler_tag_);

  if (measure_) queries_.init(gl_, es_timer_extension_, software_renderer_);
  {
    // SSS_PATH_AUTO times the paths only where GL_TIME_ELAPSED is whole and readable without an
    // extension: desktop GL, not a software rasteriser, with counter bits.
    GLint bits = 0;
    if (!software_renderer_ && !gl_->api.es) f.GetQueryiv(TIME_ELAPSED, QUERY_COUNTER_BITS, &bits);
    chooser_.init(gl_, bits > 0);
  }
  label_object(f, labels_, VERTEX_ARRAY, vertex_array_, "sss fullscreen triangle");
  label_object(f, labels_, FRAMEBUFFER, intermediate_framebuffer_, "sss horizontal pass target");
  label_object(f, labels_, FRAMEBUFFER, output_framebuffer_, "sss vertical pass target");
  label_object(f, labels_, FRAMEBUFFER, stencil_source_framebuffer_, "sss host stencil source");
  label_object(f, labels_, FRAMEBUFFER, accumulator_framebuffer_, "sss sum of the kernel's terms");
  label_object(f, labels_, SAMPLER, sampler_, "sss bilinear clamp");
  label_object(f, labels_, SAMPLER, depth_sampler_, "sss depth clamp");

  std::string log;
  copy_program_ = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "copy.frag"), &log);
  if (copy_program_ == 0) {
    *message = "copy shader: " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  if (!has_explicit_bindings(variant_)) {
    f.UseProgram(copy_program_);
    f.Uniform1i(f.GetUniformLocation(copy_program_, "u_source"), static_cast<GLint>(kSourceUnit));
  }
  label_object(f, labels_, PROGRAM, copy_program_, "sss copy");

  // The variants every host uses (write back, follow-surface, hardware depth: the default kernel's)
  // are built now, so a driver that cannot compile them fails in sss_create rather than in the first
  // frame.
  BlurProgram* unused = nullptr;
  BlurVariant common;
  common.follow_surface = 1;
  sss_result r = blur_program(common, &unused, message);
  common.outside = Outside::discard;
  if (r == SSS_OK) r = blur_program(common, &unused, message);
  return r;
}

void SeparableFilter::destroy() {
  if (gl_ == nullptr) return;
  const Functions& f = *gl_;
  for (BlurProgram& p : blur_programs_) {
    if (p.program != 0) f.DeleteProgram(p.program);
    p = BlurProgram{};
  }
  for (BlurProgram& p : compute_programs_) {
    if (p.program != 0) f.DeleteProgram(p.program);
    p = BlurProgram{};
  }
  for (CbfProgram& p : cbf_programs_) {
    if (p.program != 0) f.DeleteProgram(p.program);
    p = CbfProgram{};
  }
  if (masked_source_ != 0) f.DeleteTextures(1, &masked_source_);
  if (masked_framebuffer_ != 0) f.DeleteFramebuffers(1, &masked_framebuffer_);
  if (copy_program_ != 0) f.DeleteProgram(copy_program_);
  GLuint framebuffers[4] = {intermediate_framebuffer_, output_framebuffer_, stencil_source_framebuffer_,
                            accumulator_framebuffer_};
  f.DeleteFramebuffers(4, framebuffers);
  if (intermediate_ != 0) f.DeleteTextures(1, &intermediate_);
  for (GLuint& t : accumulators_) {
    if (t != 0) f.DeleteTextures(1, &t);
  }
  if (stencil_buffer_ != 0) f.DeleteRenderbuffers(1, &stencil_buffer_);
  GLuint samplers[2] = {sampler_, depth_sampler_};
  f.DeleteSamplers(2, samplers);
  if (vertex_array_ != 0) f.DeleteVertexArrays(1, &vertex_array_);
  destroy_msaa();
  queries_.destroy();
  chooser_.destroy();
  forget();
}

bool SeparableFilter::objects_present() const {
  if (gl_ == nullptr || vertex_array_ == 0) return false;
  const Functions& f = *gl_;
  if (!f.IsVertexArray(vertex_array_) || !f.IsFramebuffer(intermediate_framebuffer_) ||
      !f.IsFramebuffer(output_framebuffer_) || !f.IsFramebuffer(stencil_source_framebuffer_) ||
      !f.IsProgram(copy_program_) || !f.IsSampler(sampler_) || !f.IsSampler(depth_sampler_)) {
    return false;
  }
  GLfloat tag = -1.0f;
  f.GetSamplerParameterfv(sampler_, TEXTURE_MAX_LOD, &tag);
  return tag == sampler_tag_;
}

void SeparableFilter::forget() {
  auto log = std::move(log_);
  const bool measure = measure_, es_timer_extension = es_timer_extension_, software = software_renderer_;
  const Functions* gl = gl_;
  const GlslVariant variant = variant_;
  const bool labels = labels_;
  *this = SeparableFilter{};
  log_ = std::move(log);
  measure_ = measure;
  es_timer_extension_ = es_timer_extension;
  software_renderer_ = software;
  gl_ = gl;
  variant_ = variant;
  labels_ = labels;
}

sss_result SeparableFilter::rebuild(std::string* message) {
  const sss_result r = init(gl_, variant_, labels_, message);
  if (r != SSS_OK) destroy();  // what init built before it failed; the arguments stay for the next try
  return r;
}

SeparableFilter::BlurVariant SeparableFilter::blur_variant(const FilterRun& run, std::size_t term, int axis,
                                                          Outside outside) const {
  const math::PassTerm& t = run.kernel->terms[term];
  BlurVariant v;
  v.outside = outside;
  v.follow_surface = !run.follow_surface ? 0 : (t.depth_variance_mm2 > 0.0f ? 2 : 1);
  v.linear_depth = run.constants.linear_depth;
  v.jitter = run.kernel->jittered();
  v.accumulate = axis == 1 && term > 0;
  return v;
}

bool SeparableFilter::writes_half_float(const FilterRun& run, std::size_t term, int axis) const {
  if (axis == 0) return true;
  const std::size_t terms = run.cross_bilateral ? 1 : run.kernel->terms.size();
  if (term + 1 < terms) return accumulators_are_half();
  const TextureInfo& target = run.output.name != 0 ? run.output : run.color;
  return target.internal_format == static_cast<GLint>(RGBA16F);
}

sss_result SeparableFilter::blur_program(const BlurVariant& v, BlurProgram** out, std::string* message) {
  BlurProgram& p = blur_programs_[static_cast<std::size_t>(blur_variant_index(v))];
  *out = &p;
  if (p.program != 0) return SSS_OK;

  const std::string defines = blur_defines(v);
  std::string log;
  const Functions& f = *gl_;
  p.program = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "separable_blur.frag", defines), &log);
  if (p.program == 0) {
    *message = "separable blur shader (" + defines + "): " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  char label[128];
  std::snprintf(label, sizeof label,
                "sss blur outside=%d follow=%d linear=%d jitter=%d accumulate=%d",
                static_cast<int>(v.outside), v.follow_surface, v.linear_depth ? 1 : 0, v.jitter ? 1 : 0,
                v.accumulate ? 1 : 0);
  label_object(f, labels_, PROGRAM, p.program, label);
  note(std::string("built the blur program (") + glsl_variant_name(variant_) + ", " + label + ")");
  find_blur_uniforms(&p);
  // Sampler units never change: set them once (GLSL 420 has them in the shader already).
  if (!has_explicit_bindings(variant_)) {
    f.UseProgram(p.program);
    f.Uniform1i(p.source, static_cast<GLint>(kSourceUnit));
    f.Uniform1i(p.depth, static_cast<GLint>(kDepthUnit));
    if (p.original >= 0) f.Uniform1i(p.original, static_cast<GLint>(kOriginalUnit));
    if (p.accumulated >= 0) f.Uniform1i(p.accumulated, static_cast<GLint>(kAccumulatedUnit));
  }
  return SSS_OK;
}

void SeparableFilter::find_blur_uniforms(BlurProgram* program) const {
  const Functions& f = *gl_;
  BlurProgram& p = *program;
  p.source = f.GetUniformLocation(p.program, "u_source");
  p.depth = f.GetUniformLocation(p.program, "u_depth");
  p.original = f.GetUniformLocation(p.program, "u_original");
  p.accumulated = f.GetUniformLocation(p.program, "u_accumulated");
  p.jitter_from = f.GetUniformLocation(p.program, "u_jitter_from");
  p.inv_two_variance = f.GetUniformLocation(p.program, "u_inv_two_variance");
  p.axis = f.GetUniformLocation(p.program, "u_axis");
  p.pixels_per_mm = f.GetUniformLocation(p.program, "u_pixels_per_mm");
  p.follow_surface = f.GetUniformLocation(p.program, "u_follow_surface");
  p.ndc_from_depth = f.GetUniformLocation(p.program, "u_ndc_from_depth");
  p.depth_terms = f.GetUniformLocation(p.program, "u_depth_terms");
  p.clamp = f.GetUniformLocation(p.program, "u_clamp");
  p.cdf = f.GetUniformLocation(p.program, "u_cdf");
  p.footprint = f.GetUniformLocation(p.program, "u_footprint");
  p.spacing = f.GetUniformLocation(p.program, "u_spacing");
  p.half_taps = f.GetUniformLocation(p.program, "u_half_taps");
  p.rect = f.GetUniformLocation(p.program, "u_rect");
  p.round_to_half = f.GetUniformLocation(p.program, "u_round_to_half");
}

sss_result SeparableFilter::cbf_program(Outside outside, bool linear_depth, bool normals, CbfProgram** out,
                                        std::string* message) {
  const int index = (static_cast<int>(outside) * 2 + (linear_depth ? 1 : 0)) * 2 + (normals ? 1 : 0);
  CbfProgram& p = cbf_programs_[static_cast<std::size_t>(index)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = cbf_defines(outside, linear_depth, normals);
  std::string log;
  const Functions& f = *gl_;
  p.program = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "cbf_blur.frag", defines), &log);
  if (p.program == 0) {
    *message = "cross-bilateral blur shader (" + defines + "): " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  char label[64];
  std::snprintf(label, sizeof label, "sss cross-bilateral outside=%d linear=%d normals=%d", static_cast<int>(outside),
                linear_depth ? 1 : 0, normals ? 1 : 0);
  label_object(f, labels_, PROGRAM, p.program, label);
  note(std::string("built the cross-bilateral program (") + glsl_variant_name(variant_) + ", " + label + ")");
  p.source = f.GetUniformLocation(p.program, "u_source");
  p.depth = f.GetUniformLocation(p.program, "u_depth");
  p.original = f.GetUniformLocation(p.program, "u_original");
  p.kernel = f.GetUniformLocation(p.program, "u_kernel");
  p.tap_count = f.GetUniformLocation(p.program, "u_tap_count");
  p.axis = f.GetUniformLocation(p.program, "u_axis");
  p.pixels_per_mm = f.GetUniformLocation(p.program, "u_pixels_per_mm");
  p.ndc_from_depth = f.GetUniformLocation(p.program, "u_ndc_from_depth");
  p.depth_terms = f.GetUniformLocation(p.program, "u_depth_terms");
  p.clamp = f.GetUniformLocation(p.program, "u_clamp");
  p.xy_terms = f.GetUniformLocation(p.program, "u_xy_terms");
  p.xy_offset = f.GetUniformLocation(p.program, "u_xy_offset");
  p.viewport = f.GetUniformLocation(p.program, "u_viewport");
  p.world_per_mm = f.GetUniformLocation(p.program, "u_world_per_mm");
  p.orthographic = f.GetUniformLocation(p.program, "u_orthographic");
  p.spike_blend = f.GetUniformLocation(p.program, "u_spike_blend");
  p.inv_two_variance = f.GetUniformLocation(p.program, "u_inv_two_variance");
  p.round_to_half = f.GetUniformLocation(p.program, "u_round_to_half");
  p.normals = f.GetUniformLocation(p.program, "u_normals");
  // Sampler units never change: set them once (GLSL 420 has them in the shader already).
  if (!has_explicit_bindings(variant_)) {
    f.UseProgram(p.program);
    if (p.normals >= 0) f.Uniform1i(p.normals, static_cast<GLint>(kNormalUnit));
    f.Uniform1i(p.source, static_cast<GLint>(kSourceUnit));
    f.Uniform1i(p.depth, static_cast<GLint>(kDepthUnit));
    if (p.original >= 0) f.Uniform1i(p.original, static_cast<GLint>(kOriginalUnit));
  }
  return SSS_OK;
}

sss_result SeparableFilter::ensure_masked_source(GLint format, int width, int height, std::string* message) {
  const Functions& f = *gl_;
  if (masked_framebuffer_ == 0) {
    f.GenFramebuffers(1, &masked_framebuffer_);
    f.BindFramebuffer(DRAW_FRAMEBUFFER, masked_framebuffer_);
    label_object(f, labels_, FRAMEBUFFER, masked_framebuffer_, "sss masked colour copy target");
  }
  if (masked_source_ != 0 && masked_format_ == format && masked_width_ == width && masked_height_ == height) {
    return SSS_OK;
  }
  if (masked_source_ == 0) f.GenTextures(1, &masked_source_);
  f.ActiveTexture(TEXTURE0);
  f.BindTexture(TEXTURE_2D, masked_source_);
  f.BindBuffer(PIXEL_UNPACK_BUFFER, 0);
  f.TexParameteri(TEXTURE_2D, TEXTURE_MAX_LEVEL, 0);
  // The host colour's own format: the copy must hold it exactly (its centre share is not blurred),
  // and on OpenGL ES that format is the one the create-time and frame checks found renderable and
  // sampleable (RGBA32F there needs extensions an RGBA16F host may lack).
  f.TexImage2D(TEXTURE_2D, 0, format, width, height, 0, RGBA, FLOAT, nullptr);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "allocating the %dx%d %s masked colour copy failed: %s", width, height,
                  format_name(format).c_str(), error_name(error).c_str());
    *message = buffer;
    f.DeleteTextures(1, &masked_source_);
    masked_source_ = 0;
    masked_width_ = masked_height_ = 0;
    masked_format_ = 0;
    return error == OUT_OF_MEMORY ? SSS_ERROR_OUT_OF_MEMORY : SSS_ERROR_GL;
  }
  label_object(f, labels_, TEXTURE, masked_source_, "sss masked colour copy");
  masked_format_ = format;
  masked_width_ = width;
  masked_height_ = height;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, masked_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, masked_source_, 0);
  return SSS_OK;
}

sss_result SeparableFilter::allocate_target(GLuint* texture, GLenum internal_format, GLenum type, int width,
                                            int height, const char* what, std::string* message) {
  const Functions& f = *gl_;
  if (*texture == 0) f.GenTextures(1, texture);
  f.ActiveTexture(TEXTURE0);
  f.BindTexture(TEXTURE_2D, *texture);
  f.BindBuffer(PIXEL_UNPACK_BUFFER, 0);  // NULL data must not read from a host buffer
  f.TexParameteri(TEXTURE_2D, TEXTURE_MAX_LEVEL, 0);
  f.TexImage2D(TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, RGBA, type, nullptr);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    char buffer[192];
    std::snprintf(buffer, sizeof buffer, "allocating the %dx%d %s failed: %s", width, height, what,
                  error_name(error).c_str());
    *message = buffer;
    f.DeleteTextures(1, texture);
    *texture = 0;
    return error == OUT_OF_MEMORY ? SSS_ERROR_OUT_OF_MEMORY : SSS_ERROR_GL;
  }
  label_object(f, labels_, TEXTURE, *texture, (std::string("sss ") + what).c_str());
  char note_text[160];
  std::snprintf(note_text, sizeof note_text, "allocated the %dx%d %s", width, height, what);
  note(note_text);
  return SSS_OK;
}

sss_result SeparableFilter::ensure_intermediate(int width, int height, std::string* message) {
  if (intermediate_ != 0 && intermediate_width_ == width && intermediate_height_ == height) return SSS_OK;
  intermediate_width_ = intermediate_height_ = 0;
  const sss_result r =
      allocate_target(&intermediate_, RGBA16F, HALF_FLOAT, width, height, "RGBA16F intermediate target", message);
  if (r != SSS_OK) return r;
  intermediate_width_ = width;
  intermediate_height_ = height;
  const Functions& f = *gl_;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, intermediate_, 0);
  return SSS_OK;
}

sss_result SeparableFilter::ensure_accumulators(int width, int height, std::string* message) {
  if (accumulators_[1] != 0 && accumulator_width_ == width && accumulator_height_ == height) return SSS_OK;
  accumulator_width_ = accumulator_height_ = 0;
  const bool es = accumulators_are_half();
  for (GLuint& t : accumulators_) {
    const sss_result r = allocate_target(&t, es ? RGBA16F : RGBA32F, es ? HALF_FLOAT : FLOAT, width, height,
                                         es ? "RGBA16F sum of the kernel's terms" : "RGBA32F sum of the kernel's terms",
                                         message);
    if (r != SSS_OK) return r;
  }
  accumulator_width_ = width;
  accumulator_height_ = height;
  return SSS_OK;
}

sss_result SeparableFilter::ensure_stencil_buffer(GLint format, int width, int height, std::string* message) {
  if (stencil_buffer_ != 0 && stencil_format_ == format && stencil_width_ == width && stencil_height_ == height) {
    return SSS_OK;
  }
  const Functions& f = *gl_;
  if (stencil_buffer_ == 0) f.GenRenderbuffers(1, &stencil_buffer_);
  f.BindRenderbuffer(RENDERBUFFER, stencil_buffer_);
  // The copy is a blit, which needs the host's exact depth-stencil format.
  f.RenderbufferStorage(RENDERBUFFER, static_cast<GLenum>(format), width, height);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "allocating the %dx%d %s stencil copy failed: %s", width, height,
                  format_name(format).c_str(), error_name(error).c_str());
    *message = buffer;
    f.DeleteRenderbuffers(1, &stencil_buffer_);
    stencil_buffer_ = 0;
    stencil_format_ = 0;
    return error == OUT_OF_MEMORY ? SSS_ERROR_OUT_OF_MEMORY : SSS_ERROR_GL;
  }
  label_object(f, labels_, RENDERBUFFER, stencil_buffer_, "sss stencil copy");
  stencil_format_ = format;
  stencil_width_ = width;
  stencil_height_ = height;
  return SSS_OK;
}

sss_result SeparableFilter::check_framebuffer(const char* which, std::string* message) {
  const GLenum status = gl_->CheckFramebufferStatus(DRAW_FRAMEBUFFER);
  if (status == FRAMEBUFFER_COMPLETE) return SSS_OK;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "the %s framebuffer is incomplete (status 0x%04X)", which, status);
  *message = buffer;
  return SSS_ERROR_FRAMEBUFFER;
}

sss_result SeparableFilter::copy_stencil(const StencilInput& stencil, int width, int height, std::string* message) {
  const Functions& f = *gl_;
  sss_result r = ensure_stencil_buffer(stencil.texture.internal_format, width, height, message);
  if (r != SSS_OK) return r;
  f.BindFramebuffer(READ_FRAMEBUFFER, stencil_source_framebuffer_);
  // A multisampled depth-stencil is resolved by the blit: GL picks one sample's stencil per pixel.
  f.FramebufferTexture2D(READ_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, stencil.texture.target, stencil.texture.name, 0);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_buffer_);
  if (gl_->CheckFramebufferStatus(READ_FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) {
    *message = "the host's depth-stencil texture cannot be read as a framebuffer attachment";
    r = SSS_ERROR_FRAMEBUFFER;
  } else {
    r = check_framebuffer("horizontal pass", message);
  }
  if (r == SSS_OK) f.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, STENCIL_BUFFER_BIT, NEAREST);
  // Never keep a host texture attached: its storage would outlive the host's glDeleteTextures.
  f.FramebufferTexture2D(READ_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, TEXTURE_2D, 0, 0);
  return r;
}

void SeparableFilter::set_stencil_test(const StencilInput* stencil, GLenum func) {
  const Functions& f = *gl_;
  if (stencil == nullptr) {
    f.Disable(STENCIL_TEST);
    return;
  }
  f.Enable(STENCIL_TEST);
  f.StencilFuncSeparate(FRONT_AND_BACK, func, static_cast<GLint>(stencil->ref), stencil->mask);
  f.StencilOpSeparate(FRONT_AND_BACK, KEEP, KEEP, KEEP);
  f.StencilMaskSeparate(FRONT_AND_BACK, 0);
}

void SeparableFilter::set_blur_uniforms(BlurProgram& p, const FilterRun& run, std::size_t term, int axis) {
  const Functions& f = *gl_;
  const math::PassConstants& k = run.constants;
  const math::PassTerm& t = run.kernel->terms[term];
  const math::PassTaps& taps = axis == 0 ? t.horizontal : t.vertical;
  f.UseProgram(p.program);
  if (p.kernel_revision != run.kernel_revision || p.uploaded_term != term || p.uploaded_axis != axis) {
    // The pass's cumulative table, its reach and centre delta, the sparse layout's spacing, the most
    // taps per side and the first that jitters.
    const math::FootprintTable& table = taps.footprint;
    std::vector<float> packed;
    packed.reserve(table.half_cdf.size() * 4);
    for (const auto& entry : table.half_cdf) packed.insert(packed.end(), {entry[0], entry[1], entry[2], 0.0f});
    f.Uniform4fv(p.cdf, static_cast<GLsizei>(packed.size() / 4), packed.data());
    f.Uniform4f(p.footprint, table.reach_mm, table.delta[0], table.delta[1], table.delta[2]);
    const std::vector<float>& spacing = run.kernel->spacing;
    if (!spacing.empty()) f.Uniform1fv(p.spacing, static_cast<GLsizei>(spacing.size()), spacing.data());
    f.Uniform1i(p.half_taps, static_cast<GLint>(spacing.size()));
    if (p.jitter_from >= 0) f.Uniform1i(p.jitter_from, run.kernel->jitter_from);
    if (p.inv_two_variance >= 0) f.Uniform1f(p.inv_two_variance, 0.5f / t.depth_variance_mm2);
    p.kernel_revision = run.kernel_revision;
    p.uploaded_term = term;
    p.uploaded_axis = axis;
  }
  if (p.compute) {
    f.Uniform2i(p.axis, axis == 0 ? 1 : 0, axis == 0 ? 0 : 1);
  } else {
    f.Uniform2f(p.axis, axis == 0 ? 1.0f : 0.0f, axis == 0 ? 0.0f : 1.0f);
  }
  f.Uniform1f(p.pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  // The Gaussian depth correction measures depth in profile millimetres; the ramp in reaches.
  f.Uniform1f(p.follow_surface, p.inv_two_variance >= 0 ? k.mm_per_world : k.follow_surface_factor);
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  f.Uniform4f(p.clamp, k.clamp_min[0], k.clamp_min[1], k.clamp_max[0], k.clamp_max[1]);
  f.Uniform1i(p.round_to_half, writes_half_float(run, term, axis) ? 1 : 0);
}

void SeparableFilter::bind_blur_inputs(GLuint source, GLuint depth) {
  const Functions& f = *gl_;
  f.ActiveTexture(TEXTURE0 + kSourceUnit);
  f.BindTexture(TEXTURE_2D, source);
  f.BindSampler(kSourceUnit, sampler_);
  f.ActiveTexture(TEXTURE0 + kDepthUnit);
  f.BindTexture(TEXTURE_2D, depth);
  f.BindSampler(kDepthUnit, depth_sampler_);
}

void SeparableFilter::draw_blur(BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis) {
  const Functions& f = *gl_;
  set_blur_uniforms(p, run, term, axis);
  bind_blur_inputs(source, run.depth.name);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++last_draws_;
}

void SeparableFilter::draw_cbf(CbfProgram& p, const FilterRun& run, GLuint source, int axis) {
  const Functions& f = *gl_;
  const math::PassConstants& k = run.constants;
  const math::CbfConstants& c = run.cbf;
  const math::CbfKernel& kernel = *run.cbf_kernel;
  f.UseProgram(p.program);
  if (p.kernel_revision != run.cbf_kernel_revision) {
    std::vector<float> packed;
    packed.reserve(kernel.taps.size() * 4);
    for (const math::KernelTap& tap : kernel.taps) {
      packed.insert(packed.end(), {tap.weight[0], tap.weight[1], tap.weight[2], tap.offset_mm});
    }
    f.Uniform4fv(p.kernel, static_cast<GLsizei>(kernel.taps.size()), packed.data());
    f.Uniform1i(p.tap_count, static_cast<GLint>(kernel.taps.size()));
    f.Uniform4f(p.spike_blend, kernel.spike_blend[0], kernel.spike_blend[1], kernel.spike_blend[2], 0.0f);
    f.Uniform4f(p.inv_two_variance, kernel.inv_two_variance[0], kernel.inv_two_variance[1],
                kernel.inv_two_variance[2], 0.0f);
    p.kernel_revision = run.cbf_kernel_revision;
  }
  f.Uniform2f(p.axis, axis == 0 ? 1.0f : 0.0f, axis == 0 ? 0.0f : 1.0f);
  f.Uniform1f(p.pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  f.Uniform4f(p.clamp, k.clamp_min[0], k.clamp_min[1], k.clamp_max[0], k.clamp_max[1]);
  f.Uniform4f(p.xy_terms, c.xy_terms[0], c.xy_terms[1], c.xy_terms[2], c.xy_terms[3]);
  f.Uniform2f(p.xy_offset, c.xy_offset[0], c.xy_offset[1]);
  f.Uniform4f(p.viewport, c.viewport[0], c.viewport[1], c.viewport[2], c.viewport[3]);
  f.Uniform1f(p.world_per_mm, c.world_per_mm);
  f.Uniform1f(p.orthographic, c.orthographic ? 1.0f : 0.0f);
  f.Uniform1i(p.round_to_half, writes_half_float(run, 0, axis) ? 1 : 0);
  f.ActiveTexture(TEXTURE0 + kSourceUnit);
  f.BindTexture(TEXTURE_2D, source);
  f.BindSampler(kSourceUnit, sampler_);
  f.ActiveTexture(TEXTURE0 + kDepthUnit);
  f.BindTexture(TEXTURE_2D, run.depth.name);
  // Depth and normals are only texelFetch'ed here, but a texture must still be complete for its
  // sampler: on ES a depth texture (and an RGBA32F one without OES_texture_float_linear) is not
  // with GL_LINEAR, so both use the depth sampler (GL_NEAREST on ES).
  f.BindSampler(kDepthUnit, depth_sampler_);
  if (run.normals.name != 0) {
    f.ActiveTexture(TEXTURE0 + kNormalUnit);
    f.BindTexture(TEXTURE_2D, run.normals.name);
    f.BindSampler(kNormalUnit, depth_sampler_);
  }
  f.DrawArrays(TRIANGLES, 0, 3);
  ++last_draws_;
}

void SeparableFilter::draw_copy(GLuint source) {
  const Functions& f = *gl_;
  f.UseProgram(copy_program_);
  f.ActiveTexture(TEXTURE0 + kSourceUnit);
  f.BindTexture(TEXTURE_2D, source);
  f.BindSampler(kSourceUnit, sampler_);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++last_draws_;
}

sss_result SeparableFilter::run(const FilterRun& run, std::string* message) {
  last_draws_ = 0;  // run_msaa's draws and those of the run_single it calls add up
  if (run.color.multisampled()) return run_msaa(run, message);
  // Which way the passes run (sss.h SSS_PATH_*): asked for, chosen by timing, or the plain fragment
  // passes where the one asked for cannot run this frame.
  // Availability is asked only when a path other than the plain one is.
  const auto compute_ok = [&] { return !run.identity && *compute_unavailable(run) == '\0'; };
  PathChooser::Choice choice;
  switch (run.path) {
    case SSS_PATH_COMPUTE: choice.path = compute_ok() ? PathChooser::compute : PathChooser::fragment; break;
    case SSS_PATH_FRAGMENT_MASKED:
      choice.path = masked_available(run) ? PathChooser::masked : PathChooser::fragment;
      break;
    case SSS_PATH_AUTO: {
      const unsigned available = (compute_ok() ? 1u << PathChooser::compute : 0u) |
                                 (masked_available(run) ? 1u << PathChooser::masked : 0u);
      if (available != 0) {
        choice = chooser_.choose(run.path_key, available, run.region);
        if (*chooser_.decision() != '\0' && log_) {
          log_(SSS_LOG_INFO, std::string("SSS_PATH_AUTO chose the ") + chooser_.decision());
        }
      }
      break;
    }
    default: break;
  }
  chooser_.begin(choice);
  sss_result r = SSS_OK;
  switch (choice.path) {
    case PathChooser::compute: r = run_compute(run, message); break;
    case PathChooser::masked: r = run_masked(run, message); break;
    default: r = run_single(run, message); break;
  }
  chooser_.end();
  if (r == SSS_OK) {
    last_path_ = choice.path == PathChooser::compute  ? SSS_PATH_COMPUTE
                 : choice.path == PathChooser::masked ? SSS_PATH_FRAGMENT_MASKED
                                                      : SSS_PATH_FRAGMENT;
  }
  return r;
}

sss_result SeparableFilter::run_masked(const FilterRun& run, std::string* message) {
  // The stencil marked from alpha, then the host-stencil passes with it: only translucent pixels
  // are shaded by the blur; the rest are copied (horizontal) or left alone (vertical).
  const Functions& f = *gl_;
  sss_result r = ensure_mask_program(message);
  if (r == SSS_OK) r = ensure_intermediate(run.color.width, run.color.height, message);
  if (r != SSS_OK) return r;
  set_pass_state(f);
  f.BindVertexArray(vertex_array_);
  f.Viewport(run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
  r = mark_stencil_from_alpha(run.color.name, run.color.width, run.color.height, message);
  if (r != SSS_OK) return r;
  StencilInput own;  // the module's stencil holds 1 where translucent
  own.ref = 1;
  own.mask = 0xFF;
  FilterRun inner = run;
  inner.stencil = &own;
  inner.stencil_ready = true;
  return run_single(inner, message);
}

sss_result SeparableFilter::run_single(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  const int width = run.color.width, height = run.color.height;
  const bool write_back = run.output.name == 0;

  if (run.identity) return run_identity(run, message);
  if (run.cross_bilateral) return run_cbf(run, message);
  // One horizontal and one vertical pass per term. The vertical passes of all terms but the last
  // write the running sum into the module's accumulators; the last adds that sum and writes the
  // output. The host colour is only written by the very last draw, after every horizontal pass has
  // read it, so it is never read and written at once.
  const std::size_t terms = run.kernel->terms.size();
  const Outside last_outside = write_back ? Outside::discard : Outside::copy_original;
  // Programs first: a variant that fails to build must not leave a new target behind.
  std::array<BlurProgram*, 2 * math::kMaxPlanTerms> programs{};
  sss_result r = SSS_OK;
  for (std::size_t t = 0; t < terms && r == SSS_OK; ++t) {
    r = blur_program(blur_variant(run, t, 0, Outside::write_centre), &programs[2 * t], message);
    const Outside outside = t + 1 == terms ? last_outside : Outside::write_centre;
    if (r == SSS_OK) r = blur_program(blur_variant(run, t, 1, outside), &programs[2 * t + 1], message);
  }
  if (r != SSS_OK) return r;
  r = ensure_intermediate(width, height, message);
  if (r == SSS_OK && terms > 1) r = ensure_accumulators(width, height, message);
  if (r != SSS_OK) return r;

  set_pass_state(f);
  f.BindVertexArray(vertex_array_);
  f.Viewport(run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);

  // Attachments: the stencil copy goes on every target, or comes off every one.
  if (run.stencil != nullptr && !run.stencil_ready) {
    r = copy_stencil(*run.stencil, width, height, message);  // creates stencil_buffer_ on first use
    if (r != SSS_OK) return r;
  }
  const GLuint stencil_attachment = run.stencil != nullptr ? stencil_buffer_ : 0;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
  r = check_framebuffer("horizontal pass", message);
  if (r != SSS_OK) return r;
  if (terms > 1) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, accumulator_framebuffer_);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, accumulators_[0], 0);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
    r = check_framebuffer("sum of the kernel's terms", message);
    if (r != SSS_OK) return r;
  }
  const GLuint output = write_back ? run.color.name : run.output.name;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, output, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
  r = check_framebuffer("vertical pass", message);
  if (r == SSS_OK && run.region && !write_back) copy_outside_region(run);

  if (r == SSS_OK) {
    // gpu_time_ms[0] spans everything before the last vertical pass (for one term: the horizontal
    // pass), [1] that pass.
    const bool measured = measure_ && queries_.begin_frame(run.frame);
    if (measured) queries_.begin_pass(PassQueries::horizontal);
    for (std::size_t t = 0; t < terms; ++t) {
      const bool last = t + 1 == terms;
      // Horizontal: host colour -> intermediate. Pixels the stencil excludes are copied so the
      // vertical pass's taps find defined values there.
      {
        DebugGroup group(f, labels_, terms > 1 ? "sss horizontal pass (one term)" : "sss horizontal pass");
        f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
        set_stencil_test(run.stencil, EQUAL);
        draw_blur(*programs[2 * t], run, run.color.name, t, 0);
        if (run.stencil != nullptr) {
          set_stencil_test(run.stencil, NOTEQUAL);
          draw_copy(run.color.name);
        }
      }
      if (terms > 1) {  // the earlier terms' sum, read by this term's vertical pass
        f.ActiveTexture(TEXTURE0 + kAccumulatedUnit);
        f.BindTexture(TEXTURE_2D, t > 0 ? accumulators_[(t - 1) % 2] : 0);
        f.BindSampler(kAccumulatedUnit, depth_sampler_);  // texelFetch only; GL_NEAREST is complete for any format
      }
      if (!last) {
        // Vertical into the running sum (pixels outside the stencil are never read from it).
        DebugGroup group(f, labels_, "sss vertical pass (one term, into the sum)");
        f.BindFramebuffer(DRAW_FRAMEBUFFER, accumulator_framebuffer_);
        f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, accumulators_[t % 2], 0);
        set_stencil_test(run.stencil, EQUAL);
        draw_blur(*programs[2 * t + 1], run, intermediate_, t, 1);
        continue;
      }
      if (measured) queries_.end_pass(PassQueries::horizontal);
      // Vertical: intermediate -> output. Writing back, the host colour is attached here, so it is
      // bound to no unit, and alpha is masked off (it keeps the host's exact value).
      DebugGroup group(f, labels_, "sss vertical pass");
      f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
      f.ActiveTexture(TEXTURE0 + kOriginalUnit);
      f.BindTexture(TEXTURE_2D, write_back ? 0 : run.color.name);
      f.BindSampler(kOriginalUnit, sampler_);
      if (measured) queries_.begin_pass(PassQueries::vertical);
      if (write_back) f.ColorMask(1, 1, 1, 0);
      set_stencil_test(run.stencil, EQUAL);
      // Samples that pass here are the pixels the blur wrote: in place (the untouched discard),
      // exactly the blurred ones; into a separate output every pixel the stencil lets through.
      if (measured) queries_.begin_pixels();
      draw_blur(*programs[2 * t + 1], run, intermediate_, t, 1);
      if (measured) queries_.end_pixels();
      if (run.stencil != nullptr && !write_back) {
        set_stencil_test(run.stencil, NOTEQUAL);
        draw_copy(run.color.name);
      }
      if (measured) queries_.end_pass(PassQueries::vertical);
    }
    if (measured) queries_.end_frame();
  }
  // Detach the host's texture (see copy_stencil).
  f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

sss_result SeparableFilter::run_cbf(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  const int width = run.color.width, height = run.color.height;
  const bool write_back = run.output.name == 0;
  const bool linear_depth = run.constants.linear_depth;
  last_draws_ = 0;

  CbfProgram* horizontal = nullptr;
  CbfProgram* vertical = nullptr;
  const bool normals = run.normals.name != 0;
  sss_result r = cbf_program(Outside::write_centre, linear_depth, normals, &horizontal, message);
  if (r == SSS_OK) {
    r = cbf_program(write_back ? Outside::discard : Outside::copy_original, linear_depth, normals, &vertical, message);
  }
  if (r == SSS_OK) r = ensure_intermediate(width, height, message);
  if (r == SSS_OK && run.stencil != nullptr) r = ensure_masked_source(run.color.internal_format, width, height, message);
  if (r != SSS_OK) return r;

  set_pass_state(f);
  f.BindVertexArray(vertex_array_);
  f.Viewport(run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
  if (run.stencil != nullptr) {
    r = copy_stencil(*run.stencil, width, height, message);
    if (r != SSS_OK) return r;
  }
  const GLuint stencil_attachment = run.stencil != nullptr ? stencil_buffer_ : 0;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
  r = check_framebuffer("horizontal pass", message);
  if (r != SSS_OK) return r;
  if (run.stencil != nullptr) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, masked_framebuffer_);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
    r = check_framebuffer("masked colour copy", message);
    if (r != SSS_OK) return r;
  }
  const GLuint output = write_back ? run.color.name : run.output.name;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, output, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_attachment);
  r = check_framebuffer("vertical pass", message);
  if (r == SSS_OK && run.region && !write_back) copy_outside_region(run);

  if (r == SSS_OK) {
    const bool measured = measure_ && queries_.begin_frame(run.frame);
    if (measured) queries_.begin_pass(PassQueries::horizontal);  // the masked copy counts with it
    GLuint horizontal_source = run.color.name;
    if (run.stencil != nullptr) {
      // Neighbours outside the stencil must get no weight, but the shader cannot read the stencil:
      // copy the colour with alpha 0 there (cleared to 0, then the stencil-passing pixels copied).
      DebugGroup group(f, labels_, "sss masked colour copy");
      f.BindFramebuffer(DRAW_FRAMEBUFFER, masked_framebuffer_);
      const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      f.Disable(STENCIL_TEST);
      f.ClearBufferfv(COLOR, 0, zero);
      set_stencil_test(run.stencil, EQUAL);
      draw_copy(run.color.name);
      horizontal_source = masked_source_;
    }
    {
      DebugGroup group(f, labels_, "sss cross-bilateral horizontal pass");
      f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
      set_stencil_test(run.stencil, EQUAL);
      draw_cbf(*horizontal, run, horizontal_source, 0);
      if (run.stencil != nullptr) {
        set_stencil_test(run.stencil, NOTEQUAL);
        draw_copy(masked_source_);  // alpha 0: the vertical pass gives these no weight either
      }
      if (measured) queries_.end_pass(PassQueries::horizontal);
    }
    {
      DebugGroup group(f, labels_, "sss cross-bilateral vertical pass");
      f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
      f.ActiveTexture(TEXTURE0 + kOriginalUnit);
      f.BindTexture(TEXTURE_2D, write_back ? 0 : run.color.name);
      f.BindSampler(kOriginalUnit, sampler_);
      if (measured) queries_.begin_pass(PassQueries::vertical);
      if (write_back) f.ColorMask(1, 1, 1, 0);
      set_stencil_test(run.stencil, EQUAL);
      if (measured) queries_.begin_pixels();
      draw_cbf(*vertical, run, intermediate_, 1);
      if (measured) queries_.end_pixels();
      if (run.stencil != nullptr && !write_back) {
        set_stencil_test(run.stencil, NOTEQUAL);
        draw_copy(run.color.name);
      }
      if (measured) queries_.end_pass(PassQueries::vertical);
    }
    if (measured) queries_.end_frame();
  }
  f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

void SeparableFilter::copy_outside_region(const FilterRun& run) {
  const Functions& f = *gl_;
  DebugGroup group(f, labels_, "sss copy of the viewport outside the region");
  f.Disable(STENCIL_TEST);
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  draw_copy(run.color.name);
  f.Viewport(run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
}

sss_result SeparableFilter::run_identity(const FilterRun& run, std::string* message) {
  if (run.output.name == 0) return SSS_OK;  // in place: nothing changes
  const Functions& f = *gl_;
  set_pass_state(f);
  f.Disable(STENCIL_TEST);
  f.BindVertexArray(vertex_array_);
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.output.name, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
  sss_result r = check_framebuffer("output copy", message);
  if (r == SSS_OK) {
    DebugGroup group(f, labels_, "sss copy (identity settings)");
    draw_copy(run.color.name);
  }
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

}  // namespace sss::gl
