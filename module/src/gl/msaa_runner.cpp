// The multisampled path (Jimenez et al. 2012, §4): a resolve pass turns the host's multisampled
// colour and depth into single-sample colour (box average) and linear view distance (average of
// the samples' linear depths); the module's stencil is marked from the resolved strength mask
// unless the host gave its own; the two separable passes run on the resolved images as in the
// single-sample path; writing back, a last pass adds each pixel's change to the host's
// translucent samples, one sample per draw.
#include "debug_label.hpp"
#include "runners.hpp"
#include "state_guard.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
sss_result prepare(PassContext& ctx, const FilterRun& run, ResolveProgram** resolve, std::string* message) {
  const bool write_back = run.writes_back();
  sss_result r = ctx.programs.msaa_resolve(run.resolve_constants.linear_depth, resolve, message);
  if (r == SSS_OK && !run.identity && run.stencil == nullptr) {
    GLuint unused = 0;
    r = ctx.programs.stencil_mark(&unused, message);
  }
  if (r == SSS_OK && !run.identity && write_back) {
    SampleWriteProgram* unused = nullptr;
    r = ctx.programs.sample_write(&unused, message);
  }
  if (r != SSS_OK) return r;
  ctx.targets.ensure_msaa_framebuffers();
  r = ctx.targets.ensure_msaa_targets(run.color.internal_format, run.color.width, run.color.height,
                                      !run.identity && write_back, message);
  if (r == SSS_OK && write_back && !run.identity) r = ctx.targets.ensure_sample_copy(run.color, message);
  if (r != SSS_OK || run.identity) return r;
  // The single-sample passes' stencil copy and targets too: nothing is allocated after the first draw.
  const GLint stencil_format = run.stencil != nullptr ? run.stencil->texture.internal_format
                                                      : static_cast<GLint>(DEPTH24_STENCIL8);
  return ctx.targets.ensure_stencil_buffer(stencil_format, run.color.width, run.color.height, message);
}

sss_result resolve(PassContext& ctx, const FilterRun& run, const ResolveProgram& p, std::string* message) {
  const Functions& f = ctx.gl;
  begin_passes(ctx, run.viewport);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().resolve_framebuffer);
  const sss_result r = check_framebuffer(ctx, "MSAA resolve", message);
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss msaa resolve");
  const math::PassConstants& k = run.resolve_constants;
  f.UseProgram(p.program);
  f.Uniform1i(p.samples, run.color.samples);
  f.Uniform1i(p.depth_mode, static_cast<GLint>(run.depth_resolve));
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  f.ActiveTexture(TEXTURE0 + unit::msaa_color);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.color.name);
  f.ActiveTexture(TEXTURE0 + unit::msaa_depth);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.depth.name);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  return SSS_OK;
}

// The run of the single-sample passes on the resolved images.
FilterRun resolved_run(const FilterRun& run, const Targets& t) {
  FilterRun inner = run;
  inner.color = TextureInfo{};
  inner.color.name = t.resolved_color;
  inner.color.internal_format = run.color.internal_format;
  inner.color.width = run.color.width;
  inner.color.height = run.color.height;
  inner.depth = inner.color;
  inner.depth.name = t.resolved_distance;
  inner.depth.internal_format = static_cast<GLint>(R32F);
  if (run.writes_back()) {
    inner.output = inner.color;
    inner.output.name = t.blurred;
  }
  return inner;
}

// The run of the single-sample passes: on the resolved images, behind the host's stencil (resolved
// by the blit) or `own`, the module's, marked from the resolved alpha; either is in the module's
// stencil buffer before they run.
FilterRun passes_run(const FilterRun& run, const Targets& t, const StencilInput* own) {
  FilterRun inner = resolved_run(run, t);
  if (!run.identity && run.stencil == nullptr) inner.stencil = own;
  inner.stencil_ready = true;
  return inner;
}

// Copies the host's samples: the write pass reads them while the host texture is its target.
sss_result copy_samples(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const int x0 = run.viewport[0], y0 = run.viewport[1];
  const int x1 = x0 + run.viewport[2], y1 = y0 + run.viewport[3];
  f.BindFramebuffer(READ_FRAMEBUFFER, t.msaa_read_framebuffer);
  f.FramebufferTexture2D(READ_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t.sample_copy_framebuffer);
  sss_result r = SSS_OK;
  if (ctx.check_framebuffers && f.CheckFramebufferStatus(READ_FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) {
    *message = "the host's multisampled colour texture cannot be read as a framebuffer attachment";
    r = SSS_ERROR_FRAMEBUFFER;
  } else {
    r = check_framebuffer(ctx, "MSAA sample copy", message);
  }
  if (r == SSS_OK) {
    DebugGroup group(f, ctx.labels, "sss msaa copy of the host's samples");
    f.BlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, COLOR_BUFFER_BIT, NEAREST);
  }
  f.FramebufferTexture2D(READ_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, 0, 0);
  return r;
}

// One draw per sample under a one-bit sample mask: works on any GL 3.2+ context (no per-sample
// shading needed) and each draw reads only its own sample of the copy.
void draw_sample_writes(PassContext& ctx, const FilterRun& run, const SampleWriteProgram& p) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  DebugGroup group(f, ctx.labels, "sss msaa per-sample write");
  set_pass_state(f);
  // With GL_MULTISAMPLE off (a host may switch it off for its own passes) the GL ignores the sample
  // mask, and each draw would write every sample of its pixels, the opaque ones included. It acts
  // on multisampled targets alone, so this is the one draw that needs it (and the state guard
  // saves it with the MSAA path's other state). ES has no such switch: it is always on there.
  f.Enable(MULTISAMPLE);
  f.ColorMask(1, 1, 1, 0);  // alpha keeps the host's exact value in every sample
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  f.UseProgram(p.program);
  f.Uniform1i(p.samples, run.color.samples);
  f.ActiveTexture(TEXTURE0 + unit::msaa_color);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, t.sample_copy);
  bind_texture(ctx, unit::msaa_depth, t.blurred, ctx.objects.sampler);
  bind_texture(ctx, unit::msaa_extra, t.resolved_color, ctx.objects.sampler);
  f.Enable(SAMPLE_MASK);
  for (int i = 0; i < run.color.samples; ++i) {
    f.SampleMaski(0, 1u << static_cast<unsigned>(i));
    f.Uniform1i(p.sample, i);
    f.DrawArrays(TRIANGLES, 0, 3);
    ++ctx.draws;
  }
  f.Disable(SAMPLE_MASK);
}

sss_result write_samples(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  sss_result r = copy_samples(ctx, run, message);
  if (r != SSS_OK) return r;
  SampleWriteProgram* program = nullptr;
  r = ctx.programs.sample_write(&program, message);  // built by prepare(): only looked up here
  if (r != SSS_OK) return r;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().sample_write_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  r = check_framebuffer(ctx, "MSAA per-sample write", message);
  if (r == SSS_OK) draw_sample_writes(ctx, run, *program);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, 0, 0);
  return r;
}
}  // namespace

sss_result prepare_msaa(PassContext& ctx, const FilterRun& run, std::string* message) {
  ResolveProgram* resolve_program = nullptr;
  const sss_result r = prepare(ctx, run, &resolve_program, message);
  if (r != SSS_OK) return r;
  const StencilInput own;  // only whether there is one decides what is built
  return prepare_fragment(ctx, passes_run(run, ctx.targets.names(), &own), message);  // identity: nothing
}

sss_result run_msaa(PassContext& ctx, const FilterRun& run, std::string* message) {
  if (run.identity && run.writes_back()) return SSS_OK;  // in place: nothing changes
  // Everything built and allocated before the resolve, the first draw.
  sss_result r = prepare_msaa(ctx, run, message);
  ResolveProgram* resolve_program = nullptr;  // built by prepare_msaa: only looked up here
  if (r == SSS_OK) r = ctx.programs.msaa_resolve(run.resolve_constants.linear_depth, &resolve_program, message);
  if (r == SSS_OK) r = resolve(ctx, run, *resolve_program, message);
  if (r != SSS_OK) return r;
  StencilInput own;
  own.ref = 1;
  own.mask = 1;
  const FilterRun inner = passes_run(run, ctx.targets.names(), &own);
  if (run.identity) return run_fragment(ctx, inner, message);  // copies the resolved colour into the output

  if (run.stencil != nullptr) {
    r = copy_stencil(ctx, run, *run.stencil, message);
  } else {
    r = mark_stencil_from_alpha(ctx, run, ctx.targets.names().resolved_color, message);
  }
  if (r != SSS_OK) return r;
  r = run_fragment(ctx, inner, message);
  if (r != SSS_OK || !run.writes_back()) return r;
  return write_samples(ctx, run, message);
}

}  // namespace sss::gl
