// The multisampled path (Jimenez et al. 2012, §4): a resolve pass turns the host's multisampled
// colour and depth into single-sample colour (box average) and linear view distance (average of
// the samples' linear depths); the module's stencil is marked from the resolved strength mask
// unless the host gave its own; the two separable passes run on the resolved images as in the
// single-sample path; writing back, a last pass adds each pixel's change to the host's
// translucent samples, one sample per draw.
#include <cstdio>

#include "debug_label.hpp"
#include "program.hpp"
#include "separable_filter.hpp"
#include "state_guard.hpp"

namespace sss::gl {

namespace {
constexpr GLuint kColorUnit = 0, kDepthUnit = 1, kExtraUnit = 2;

sss_result allocation_failed(const Functions& f, const char* what, int width, int height, std::string* message) {
  const GLenum error = f.GetError();
  if (error == NO_ERROR) return SSS_OK;
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "allocating the %dx%d %s failed: %s", width, height, what,
                error_name(error).c_str());
  *message = buffer;
  return error == OUT_OF_MEMORY ? SSS_ERROR_OUT_OF_MEMORY : SSS_ERROR_GL;
}

// (Re)allocates a single-sample texture with one level.
void allocate_2d(const Functions& f, GLuint texture, GLint format, GLenum pixel_format, int width, int height) {
  f.ActiveTexture(TEXTURE0);
  f.BindTexture(TEXTURE_2D, texture);
  f.BindBuffer(PIXEL_UNPACK_BUFFER, 0);  // NULL data must not read from a host buffer
  f.TexParameteri(TEXTURE_2D, TEXTURE_MAX_LEVEL, 0);
  f.TexImage2D(TEXTURE_2D, 0, format, width, height, 0, pixel_format, FLOAT, nullptr);
}
}  // namespace

sss_result SeparableFilter::msaa_programs(bool linear_depth, bool need_mask, bool need_write,
                                          ResolveProgram** resolve, std::string* message) {
  const Functions& f = *gl_;
  std::string log;
  ResolveProgram& p = msaa_.resolve[linear_depth ? 1 : 0];
  *resolve = &p;
  if (p.program == 0) {
    const std::string defines = msaa_resolve_defines(linear_depth);
    p.program = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "msaa_resolve.frag", defines), &log);
    if (p.program == 0) {
      *message = "MSAA resolve shader (" + defines + "): " + log;
      return SSS_ERROR_SHADER_COMPILE;
    }
    label_object(f, labels_, PROGRAM, p.program, linear_depth ? "sss msaa resolve linear" : "sss msaa resolve");
    p.samples = f.GetUniformLocation(p.program, "u_samples");
    p.depth_mode = f.GetUniformLocation(p.program, "u_depth_mode");
    p.ndc_from_depth = f.GetUniformLocation(p.program, "u_ndc_from_depth");
    p.depth_terms = f.GetUniformLocation(p.program, "u_depth_terms");
    if (!has_explicit_bindings(variant_)) {  // GLSL 420 has the units in the shader
      f.UseProgram(p.program);
      f.Uniform1i(f.GetUniformLocation(p.program, "u_color"), static_cast<GLint>(kColorUnit));
      f.Uniform1i(f.GetUniformLocation(p.program, "u_depth"), static_cast<GLint>(kDepthUnit));
    }
  }
  if (need_mask) {
    const sss_result r = ensure_mask_program(message);
    if (r != SSS_OK) return r;
  }
  if (need_write && msaa_.write_program == 0) {
    msaa_.write_program = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "msaa_write.frag"), &log);
    if (msaa_.write_program == 0) {
      *message = "MSAA write-back shader: " + log;
      return SSS_ERROR_SHADER_COMPILE;
    }
    label_object(f, labels_, PROGRAM, msaa_.write_program, "sss msaa per-sample write");
    const GLuint w = msaa_.write_program;
    msaa_.write_sample = f.GetUniformLocation(w, "u_sample");
    msaa_.write_samples = f.GetUniformLocation(w, "u_samples");
    if (!has_explicit_bindings(variant_)) {
      f.UseProgram(w);
      f.Uniform1i(f.GetUniformLocation(w, "u_copy"), static_cast<GLint>(kColorUnit));
      f.Uniform1i(f.GetUniformLocation(w, "u_blurred"), static_cast<GLint>(kDepthUnit));
      f.Uniform1i(f.GetUniformLocation(w, "u_resolved"), static_cast<GLint>(kExtraUnit));
    }
  }
  return SSS_OK;
}

sss_result SeparableFilter::ensure_msaa_framebuffers() {
  if (msaa_.resolve_framebuffer != 0) return SSS_OK;
  const Functions& f = *gl_;
  GLuint framebuffers[4] = {0, 0, 0, 0};
  f.GenFramebuffers(4, framebuffers);
  msaa_.resolve_framebuffer = framebuffers[0];
  msaa_.read_framebuffer = framebuffers[1];
  msaa_.copy_framebuffer = framebuffers[2];
  msaa_.write_framebuffer = framebuffers[3];
  f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.resolve_framebuffer);
  const GLenum both[2] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT1};
  f.DrawBuffers(2, both);  // colour and view distance in one pass
  for (int i = 1; i < 4; ++i) f.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffers[i]);
  label_object(f, labels_, FRAMEBUFFER, msaa_.resolve_framebuffer, "sss msaa resolve target");
  label_object(f, labels_, FRAMEBUFFER, msaa_.read_framebuffer, "sss msaa host colour source");
  label_object(f, labels_, FRAMEBUFFER, msaa_.copy_framebuffer, "sss msaa sample copy");
  label_object(f, labels_, FRAMEBUFFER, msaa_.write_framebuffer, "sss msaa per-sample write target");
  return SSS_OK;
}

sss_result SeparableFilter::ensure_msaa_targets(GLint color_format, int width, int height, bool need_blurred,
                                                std::string* message) {
  const Functions& f = *gl_;
  const bool same = msaa_.resolved_color != 0 && msaa_.color_format == color_format && msaa_.width == width &&
                    msaa_.height == height;
  if (!same) {
    if (msaa_.resolved_color == 0) {
      GLuint t[3] = {0, 0, 0};
      f.GenTextures(3, t);
      msaa_.resolved_color = t[0];
      msaa_.resolved_distance = t[1];
      msaa_.blurred = t[2];
    }
    msaa_.has_blurred = false;
    allocate_2d(f, msaa_.resolved_color, color_format, RGBA, width, height);
    allocate_2d(f, msaa_.resolved_distance, static_cast<GLint>(R32F), RED, width, height);
    sss_result r = allocation_failed(f, "MSAA resolve targets", width, height, message);
    if (r != SSS_OK) {
      msaa_.color_format = 0;  // reallocated next time
      return r;
    }
    label_object(f, labels_, TEXTURE, msaa_.resolved_color, "sss msaa resolved colour");
    label_object(f, labels_, TEXTURE, msaa_.resolved_distance, "sss msaa resolved view distance");
    msaa_.color_format = color_format;
    msaa_.width = width;
    msaa_.height = height;
    f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.resolve_framebuffer);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, msaa_.resolved_color, 0);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT1, TEXTURE_2D, msaa_.resolved_distance, 0);
  }
  if (need_blurred && !msaa_.has_blurred) {
    allocate_2d(f, msaa_.blurred, color_format, RGBA, width, height);
    sss_result r = allocation_failed(f, "MSAA blurred target", width, height, message);
    if (r != SSS_OK) return r;
    label_object(f, labels_, TEXTURE, msaa_.blurred, "sss msaa blurred (before the per-sample write)");
    msaa_.has_blurred = true;
  }
  return SSS_OK;
}

sss_result SeparableFilter::ensure_sample_copy(const TextureInfo& color, std::string* message) {
  if (msaa_.sample_copy != 0 && msaa_.copy_format == color.internal_format && msaa_.copy_width == color.width &&
      msaa_.copy_height == color.height && msaa_.copy_samples == color.samples &&
      msaa_.copy_fixed == color.fixed_locations) {
    return SSS_OK;
  }
  const Functions& f = *gl_;
  // Multisample storage cannot be respecified in place on every driver: make a new texture.
  if (msaa_.sample_copy != 0) f.DeleteTextures(1, &msaa_.sample_copy);
  f.GenTextures(1, &msaa_.sample_copy);
  f.ActiveTexture(TEXTURE0);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, msaa_.sample_copy);
  f.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, color.samples, static_cast<GLenum>(color.internal_format),
                          color.width, color.height, color.fixed_locations);
  sss_result r = allocation_failed(f, "multisampled colour copy", color.width, color.height, message);
  if (r != SSS_OK) {
    f.DeleteTextures(1, &msaa_.sample_copy);
    msaa_.sample_copy = 0;
    return r;
  }
  label_object(f, labels_, TEXTURE, msaa_.sample_copy, "sss msaa copy of the host's samples");
  msaa_.copy_format = color.internal_format;
  msaa_.copy_width = color.width;
  msaa_.copy_height = color.height;
  msaa_.copy_samples = color.samples;
  msaa_.copy_fixed = color.fixed_locations;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.copy_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, msaa_.sample_copy, 0);
  return SSS_OK;
}

sss_result SeparableFilter::ensure_mask_program(std::string* message) {
  if (msaa_.mask_program != 0) return SSS_OK;
  const Functions& f = *gl_;
  std::string log;
  msaa_.mask_program = build_program(f, vertex_recipe(variant_), stage_recipe(variant_, "msaa_mask.frag"), &log);
  if (msaa_.mask_program == 0) {
    *message = "stencil mask shader: " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  label_object(f, labels_, PROGRAM, msaa_.mask_program, "sss stencil mask from alpha");
  if (!has_explicit_bindings(variant_)) {
    f.UseProgram(msaa_.mask_program);
    f.Uniform1i(f.GetUniformLocation(msaa_.mask_program, "u_source"), static_cast<GLint>(kColorUnit));
  }
  return SSS_OK;
}

// The paper's stencil culling: the stencil is initialised from the strength mask, so both blur
// passes run only on translucent pixels (the multisampling path, on its resolved colour, and the
// masked fragment path, SSS_PATH_FRAGMENT_MASKED, on the host's). Needs the intermediate
// framebuffer allocated; draws over the current viewport.
sss_result SeparableFilter::mark_stencil_from_alpha(GLuint source, int width, int height, std::string* message) {
  const Functions& f = *gl_;
  sss_result r = ensure_stencil_buffer(static_cast<GLint>(DEPTH24_STENCIL8), width, height, message);
  if (r != SSS_OK) return r;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, intermediate_framebuffer_);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_buffer_);
  r = check_framebuffer("MSAA stencil mask", message);
  if (r != SSS_OK) return r;
  DebugGroup group(f, labels_, "sss stencil from alpha");
  f.StencilMaskSeparate(FRONT_AND_BACK, 0xFF);
  const GLint zero = 0;
  f.ClearBufferiv(STENCIL, 0, &zero);  // glClearBuffer leaves the host's clear values alone
  f.ColorMask(0, 0, 0, 0);
  f.Enable(STENCIL_TEST);
  f.StencilFuncSeparate(FRONT_AND_BACK, ALWAYS, 1, 0xFF);
  f.StencilOpSeparate(FRONT_AND_BACK, KEEP, KEEP, REPLACE);
  f.UseProgram(msaa_.mask_program);
  f.ActiveTexture(TEXTURE0 + kColorUnit);
  f.BindTexture(TEXTURE_2D, source);
  f.BindSampler(kColorUnit, sampler_);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++last_draws_;
  f.ColorMask(1, 1, 1, 1);
  f.StencilMaskSeparate(FRONT_AND_BACK, 0);
  f.Disable(STENCIL_TEST);
  return SSS_OK;
}

sss_result SeparableFilter::run_msaa(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  const int width = run.color.width, height = run.color.height;
  const bool write_back = run.output.name == 0;
  if (run.identity && write_back) return SSS_OK;  // in place: nothing changes
  const bool host_linear = run.resolve_constants.linear_depth;

  ResolveProgram* resolve = nullptr;
  sss_result r = msaa_programs(host_linear, !run.identity && run.stencil == nullptr, !run.identity && write_back,
                               &resolve, message);
  if (r != SSS_OK) return r;
  ensure_msaa_framebuffers();
  r = ensure_msaa_targets(run.color.internal_format, width, height, !run.identity && write_back, message);
  if (r == SSS_OK && write_back && !run.identity) r = ensure_sample_copy(run.color, message);
  if (r != SSS_OK) return r;

  set_pass_state(f);
  f.BindVertexArray(vertex_array_);
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.resolve_framebuffer);
  r = check_framebuffer("MSAA resolve", message);
  if (r != SSS_OK) return r;
  {
    DebugGroup group(f, labels_, "sss msaa resolve");
    const math::PassConstants& k = run.resolve_constants;
    f.UseProgram(resolve->program);
    f.Uniform1i(resolve->samples, run.color.samples);
    f.Uniform1i(resolve->depth_mode, static_cast<GLint>(run.depth_resolve));
    f.Uniform2f(resolve->ndc_from_depth, k.ndc_scale, k.ndc_bias);
    f.Uniform4f(resolve->depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
    f.ActiveTexture(TEXTURE0 + kColorUnit);
    f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.color.name);
    f.ActiveTexture(TEXTURE0 + kDepthUnit);
    f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.depth.name);
    f.DrawArrays(TRIANGLES, 0, 3);
    ++last_draws_;
  }

  FilterRun inner = run;
  inner.color = TextureInfo{};
  inner.color.name = msaa_.resolved_color;
  inner.color.internal_format = run.color.internal_format;
  inner.color.width = width;
  inner.color.height = height;
  inner.depth = inner.color;
  inner.depth.name = msaa_.resolved_distance;
  inner.depth.internal_format = static_cast<GLint>(R32F);
  if (write_back) {
    inner.output = inner.color;
    inner.output.name = msaa_.blurred;
  }
  if (run.identity) return run_single(inner, message);  // copies the resolved colour into the output

  // The stencil: the host's (resolved by the blit) or the module's, marked from alpha.
  r = ensure_intermediate(width, height, message);
  if (r != SSS_OK) return r;
  StencilInput own;
  own.ref = 1;
  own.mask = 1;
  if (run.stencil != nullptr) {
    r = copy_stencil(*run.stencil, width, height, message);
  } else {
    r = mark_stencil_from_alpha(msaa_.resolved_color, width, height, message);
    inner.stencil = &own;
  }
  if (r != SSS_OK) return r;
  inner.stencil_ready = true;
  r = run_single(inner, message);
  if (r != SSS_OK || !write_back) return r;
  return write_samples(run, message);
}

sss_result SeparableFilter::write_samples(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  const int x0 = run.viewport[0], y0 = run.viewport[1];
  const int x1 = x0 + run.viewport[2], y1 = y0 + run.viewport[3];
  // Copy the host's samples: the write pass reads them while the host texture is its target.
  f.BindFramebuffer(READ_FRAMEBUFFER, msaa_.read_framebuffer);
  f.FramebufferTexture2D(READ_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.copy_framebuffer);
  sss_result r = SSS_OK;
  if (f.CheckFramebufferStatus(READ_FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) {
    *message = "the host's multisampled colour texture cannot be read as a framebuffer attachment";
    r = SSS_ERROR_FRAMEBUFFER;
  } else {
    r = check_framebuffer("MSAA sample copy", message);
  }
  if (r == SSS_OK) {
    DebugGroup group(f, labels_, "sss msaa copy of the host's samples");
    f.BlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, COLOR_BUFFER_BIT, NEAREST);
  }
  f.FramebufferTexture2D(READ_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, 0, 0);
  if (r != SSS_OK) return r;

  f.BindFramebuffer(DRAW_FRAMEBUFFER, msaa_.write_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  r = check_framebuffer("MSAA per-sample write", message);
  if (r == SSS_OK) {
    DebugGroup group(f, labels_, "sss msaa per-sample write");
    set_pass_state(f);
    f.ColorMask(1, 1, 1, 0);  // alpha keeps the host's exact value in every sample
    f.Viewport(x0, y0, run.viewport[2], run.viewport[3]);
    f.UseProgram(msaa_.write_program);
    f.Uniform1i(msaa_.write_samples, run.color.samples);
    f.ActiveTexture(TEXTURE0 + kColorUnit);
    f.BindTexture(TEXTURE_2D_MULTISAMPLE, msaa_.sample_copy);
    f.ActiveTexture(TEXTURE0 + kDepthUnit);
    f.BindTexture(TEXTURE_2D, msaa_.blurred);
    f.BindSampler(kDepthUnit, sampler_);
    f.ActiveTexture(TEXTURE0 + kExtraUnit);
    f.BindTexture(TEXTURE_2D, msaa_.resolved_color);
    f.BindSampler(kExtraUnit, sampler_);
    // One draw per sample under a one-bit sample mask: works on any GL 3.2+ context (no
    // per-sample shading needed) and each draw reads only its own sample of the copy.
    f.Enable(SAMPLE_MASK);
    for (int i = 0; i < run.color.samples; ++i) {
      f.SampleMaski(0, 1u << static_cast<unsigned>(i));
      f.Uniform1i(msaa_.write_sample, i);
      f.DrawArrays(TRIANGLES, 0, 3);
      ++last_draws_;
    }
    f.Disable(SAMPLE_MASK);
  }
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, 0, 0);
  return r;
}

void SeparableFilter::destroy_msaa() {
  const Functions& f = *gl_;
  for (ResolveProgram& p : msaa_.resolve) {
    if (p.program != 0) f.DeleteProgram(p.program);
  }
  if (msaa_.mask_program != 0) f.DeleteProgram(msaa_.mask_program);
  if (msaa_.write_program != 0) f.DeleteProgram(msaa_.write_program);
  if (msaa_.resolve_framebuffer != 0) {
    const GLuint framebuffers[4] = {msaa_.resolve_framebuffer, msaa_.read_framebuffer, msaa_.copy_framebuffer,
                                    msaa_.write_framebuffer};
    f.DeleteFramebuffers(4, framebuffers);
  }
  if (msaa_.resolved_color != 0) {
    const GLuint textures[3] = {msaa_.resolved_color, msaa_.resolved_distance, msaa_.blurred};
    f.DeleteTextures(3, textures);
  }
  if (msaa_.sample_copy != 0) f.DeleteTextures(1, &msaa_.sample_copy);
  msaa_ = MsaaObjects{};
}

}  // namespace sss::gl
