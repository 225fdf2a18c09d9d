// The multisampled path (Jimenez et al. 2012, §4): a resolve pass turns the host's multisampled
// colour and depth into single-sample colour (box average) and linear view distance (average of
// the samples' linear depths); the module's stencil is marked from the resolved strength mask
// unless the host gave its own; the two separable passes run on the resolved images as in the
// single-sample path; writing back, a last pass blends each pixel's change into the host's
// translucent samples (msaa_write.frag), in one draw where the shaders have gl_SampleMask (GLSL
// 4.20) and one draw per sample under glSampleMaski on a GL 3.3-4.1 context. It never reads the
// host's colour: the resolve kept what it needs of each pixel's translucent samples. A texturing
// mode (FramePlan::resolve_albedo) divides each sample by its own A_post in the resolve and
// multiplies each sample's change by it in the write-back (msaa_resolve.frag, msaa_write.frag).
#include "debug_label.hpp"
#include "pass_uniforms.hpp"
#include "plan_steps.hpp"
#include "state_guard.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
// The host's multisampled albedo on its unit (the state guard saves that unit's multisample
// binding in a frame with an albedo).
void bind_multisampled_albedo(const Functions& f, const FilterRun& run) {
  f.ActiveTexture(TEXTURE0 + unit::albedo);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.albedo.name);
}
}  // namespace

sss_result resolve_msaa(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const PlanPrograms& programs,
                        std::string* message) {
  const Functions& f = ctx.gl;
  const ResolveProgram& p = *programs.resolve;
  begin_passes(ctx, run.viewport);
  if (!run.identity) ctx.targets.attach_resolve_inputs();
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().resolve_framebuffer);
  // Writing back, the translucent samples' mean and lowest values too (attachments 2 and 3); unless
  // nothing is blurred, the fragment passes' inputs (attachments 4-6: pass_inputs.frag's targets,
  // so that the passes need no inputs draw of their own: the linear depth computed once).
  // A texturing mode into a separate output: the undivided mean (attachment 2) and the samples' mean
  // A_post (attachment 7) for the last pass.
  const bool write_back = plan.resolve_write_back;
  const bool albedo_out = plan.resolve_albedo != 0 && !write_back;
  const GLenum buffers[8] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT1, write_back || albedo_out ? COLOR_ATTACHMENT2 : NONE,
                             write_back ? COLOR_ATTACHMENT3 : NONE, COLOR_ATTACHMENT4, COLOR_ATTACHMENT5,
                             COLOR_ATTACHMENT6, COLOR_ATTACHMENT7};
  f.DrawBuffers(run.identity ? (write_back ? 4 : 2) : (albedo_out ? 8 : 7), buffers);
  const sss_result r = check_framebuffer(ctx, "MSAA resolve", message);
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss msaa resolve");
  f.UseProgram(p.program);
  const ResolveUniforms u = fill_resolve_uniforms(run);
  upload_uniforms(f, kResolveUniforms, p.fields, u.values.data());
  f.ActiveTexture(TEXTURE0 + unit::msaa_color);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.color.name);
  f.ActiveTexture(TEXTURE0 + unit::msaa_depth);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, run.depth.name);
  if (plan.resolve_albedo != 0) bind_multisampled_albedo(f, run);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  // Into an output, the pass that writes it multiplies by the samples' mean A_post: left on the
  // albedo's unit for it, as the single-sample inputs draw leaves the host's albedo there.
  if (albedo_out) bind_texture(ctx, unit::albedo, ctx.targets.names().resolved_albedo, ctx.objects.nearest_sampler);
  return SSS_OK;
}

namespace {
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
  // The host's colour, which this pass draws into, stays bound to no unit (the resolve left it on unit 0).
  f.ActiveTexture(TEXTURE0 + unit::msaa_color);
  f.BindTexture(TEXTURE_2D_MULTISAMPLE, 0);
  bind_texture(ctx, unit::msaa_lowest, t.translucent_lowest, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_blurred, t.blurred, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_resolved, t.resolved_color, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::msaa_translucent, t.translucent_mean, ctx.objects.nearest_sampler);
  if (p.albedo != 0) bind_multisampled_albedo(f, run);
  if (p.one_draw) {
    const SampleWriteUniforms u = fill_sample_write_uniforms(run, 0);
    upload_uniforms(f, kSampleWriteUniforms, p.fields, u.values.data());
    f.DrawArrays(TRIANGLES, 0, 3);
    ++ctx.draws;
  } else {
    f.Enable(SAMPLE_MASK);
    for (int i = 0; i < run.color.samples; ++i) {
      f.SampleMaski(0, 1u << static_cast<unsigned>(i));
      const SampleWriteUniforms u = fill_sample_write_uniforms(run, i);
      upload_uniforms(f, kSampleWriteUniforms, p.fields, u.values.data());
      f.DrawArrays(TRIANGLES, 0, 3);
      ++ctx.draws;
    }
    f.Disable(SAMPLE_MASK);
  }
  f.Disable(BLEND);
}

}  // namespace

sss_result write_samples(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, std::string* message) {
  const Functions& f = ctx.gl;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().sample_write_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, run.color.name, 0);
  const sss_result r = check_framebuffer(ctx, "MSAA write-back", message);
  if (r == SSS_OK) draw_sample_writes(ctx, run, *p.sample_write);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, 0, 0);
  return r;
}
sss_result mark_stencil_from_alpha(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, std::string* message) {
  const Functions& f = ctx.gl;
  const sss_result r = attach_stencil(ctx, horizontal_framebuffer(ctx, run), ctx.targets.names().stencil_buffer, message,
                                      "stencil mark");
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss stencil from alpha");
  f.StencilMaskSeparate(FRONT_AND_BACK, 0xFF);
  const GLint zero = 0;
  f.ClearBufferiv(STENCIL, 0, &zero);  // glClearBuffer leaves the host's clear values alone
  f.ColorMask(0, 0, 0, 0);
  f.Enable(STENCIL_TEST);
  f.StencilFuncSeparate(FRONT_AND_BACK, ALWAYS, 1, 0xFF);
  f.StencilOpSeparate(FRONT_AND_BACK, KEEP, KEEP, REPLACE);
  f.UseProgram(p.stencil_mark);
  bind_texture(ctx, unit::msaa_color, ctx.targets.names().resolved_color, ctx.objects.sampler);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  f.ColorMask(1, 1, 1, 1);
  f.StencilMaskSeparate(FRONT_AND_BACK, 0);
  f.Disable(STENCIL_TEST);
  return SSS_OK;
}

}  // namespace sss::gl
