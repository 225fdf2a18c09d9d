// The multisampled path (Jimenez et al. 2012, §4): a resolve pass turns the host's multisampled
// colour and depth into single-sample colour (box average) and linear view distance (average of
// the samples' linear depths); the module's stencil is marked from the resolved strength mask
// unless the host gave its own; the two separable passes run on the resolved images as in the
// single-sample path; writing back, a last pass blends each pixel's change into the host's
// translucent samples (msaa_write.frag), in one draw where the shaders have gl_SampleMask (GLSL
// 4.20) and one draw per sample under glSampleMaski on a GL 3.3-4.1 context. It never reads the
// host's colour: the resolve kept what it needs of each pixel's translucent samples.
#include "debug_label.hpp"
#include "runners.hpp"
#include "state_guard.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
sss_result prepare(PassContext& ctx, const FilterRun& run, ResolveProgram** resolve, std::string* message) {
  const bool write_back = run.writes_back();
  sss_result r = ctx.programs.msaa_resolve(run.resolve_constants.linear_depth, !run.identity && write_back, resolve,
                                           message);
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
  if (r != SSS_OK || run.identity) return r;
  // The single-sample passes' stencil copy and targets too: nothing is allocated after the first draw.
  const GLint stencil_format = run.stencil != nullptr ? run.stencil->texture.internal_format
                                                      : static_cast<GLint>(DEPTH24_STENCIL8);
  return ctx.targets.ensure_stencil_buffer(stencil_format, run.color.width, run.color.height, message);
}

sss_result resolve(PassContext& ctx, const FilterRun& run, const ResolveProgram& p, std::string* message) {
  const Functions& f = ctx.gl;
  begin_passes(ctx, run.viewport);
  if (!run.identity) ctx.targets.attach_resolve_inputs();
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().resolve_framebuffer);
  // Writing back, the translucent samples' mean and lowest values too (attachments 2 and 3); unless
  // nothing is blurred, the fragment passes' inputs (attachments 4-6: pass_inputs.frag's targets,
  // so that the passes need no inputs draw of their own: the linear depth computed once).
  const bool write_back = run.writes_back() && !run.identity;
  const GLenum buffers[7] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT1, write_back ? COLOR_ATTACHMENT2 : NONE,
                             write_back ? COLOR_ATTACHMENT3 : NONE, COLOR_ATTACHMENT4, COLOR_ATTACHMENT5,
                             COLOR_ATTACHMENT6};
  f.DrawBuffers(run.identity ? (write_back ? 4 : 2) : 7, buffers);
  const sss_result r = check_framebuffer(ctx, "MSAA resolve", message);
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss msaa resolve");
  const math::PassConstants& k = run.resolve_constants;
  f.UseProgram(p.program);
  f.Uniform1i(p.samples, run.color.samples);
  f.Uniform1i(p.depth_mode, static_cast<GLint>(run.depth_resolve));
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  // The resolved colour rounded to nearest where it is RGBA16F, so that it and the inputs' copy of
  // it hold the same value whatever the driver's conversion does.
  f.Uniform1i(p.round_to_half, run.color.internal_format == static_cast<GLint>(RGBA16F) ? 1 : 0);
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
  inner.inputs_ready = !run.identity;  // the resolve wrote them (resolve())
  // Behind its own mask the write-back reads the blurred image only where the mask let the passes
  // draw (msaa_write.frag applies the mask's test to the resolved colour), so the rest needs no copy.
  // Behind the host's stencil it reads pixels outside it too: there the copy makes the change 0.
  inner.output_outside_stencil_unread = run.writes_back() && run.stencil == nullptr;
  return inner;
}

// The write-back's blend (msaa_write.frag): each written sample becomes src0 + sample · src1 in
// colour; alpha is masked and keeps the host's exact value.
void set_write_back_state(const Functions& f) {
  f.Enable(BLEND);
  f.BlendFuncSeparate(ONE, SRC1_COLOR, ZERO, ONE);
  f.BlendEquationSeparate(FUNC_ADD, FUNC_ADD);
  f.ColorMask(1, 1, 1, 0);
}

// One draw where the shader writes gl_SampleMask; else one draw per sample under a one-bit sample
// mask (GL 3.2+, no per-sample shading needed), each discarding where its sample is opaque.
void draw_sample_writes(PassContext& ctx, const FilterRun& run, const SampleWriteProgram& p) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  DebugGroup group(f, ctx.labels, p.one_draw ? "sss msaa write-back" : "sss msaa per-sample write-back");
  set_pass_state(f);
  // With GL_MULTISAMPLE off (a host may switch it off for its own passes) the GL ignores the sample
  // mask (the shader's and glSampleMaski's), and each draw would write every sample of its pixels,
  // the opaque ones included. It acts on multisampled targets alone, so this is the one pass that
  // needs it (and the state guard saves it with the MSAA path's other state). ES has no such
  // switch: it is always on there.
  f.Enable(MULTISAMPLE);
  set_write_back_state(f);
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  f.UseProgram(p.program);
  f.Uniform1i(p.samples, run.color.samples);
  // The host's colour, which this pass draws into, stays bound to no unit (the resolve left it on unit 0).
  f.ActiveTexture(TEXTURE0 + unit::msaa_color);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, 0);
  bind_texture(ctx, unit::msaa_lowest, t.translucent_lowest, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_blurred, t.blurred, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_resolved, t.resolved_color, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_translucent, t.translucent_mean, ctx.objects.nearest_sampler);
  if (p.one_draw) {
    f.DrawArrays(TRIANGLES, 0, 3);
    ++ctx.draws;
  } else {
    f.Enable(SAMPLE_MASK);
    for (int i = 0; i < run.color.samples; ++i) {
      f.SampleMaski(0, 1u << static_cast<unsigned>(i));
      f.Uniform1i(p.sample, i);
      f.DrawArrays(TRIANGLES, 0, 3);
      ++ctx.draws;
    }
    f.Disable(SAMPLE_MASK);
  }
  f.Disable(BLEND);
}

sss_result write_samples(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  SampleWriteProgram* program = nullptr;
  sss_result r = ctx.programs.sample_write(&program, message);  // built by prepare(): only looked up here
  if (r != SSS_OK) return r;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().sample_write_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  r = check_framebuffer(ctx, "MSAA write-back", message);
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
  if (r == SSS_OK) {
    r = ctx.programs.msaa_resolve(run.resolve_constants.linear_depth, run.writes_back() && !run.identity,
                                  &resolve_program, message);
  }
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
