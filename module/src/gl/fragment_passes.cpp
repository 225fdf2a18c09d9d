// The separable fragment passes (Jimenez et al. 2012, §3) on single-sample images. First one draw
// of the passes' inputs (pass_inputs.frag: colour and view distance in one texel, the strength
// apart), then one horizontal and one vertical pass per kernel term: the vertical passes of all
// terms but the last write the running sum into the module's accumulators, the last adds that sum
// and writes the output. The host's colour is only written by the very last draw, after the inputs
// draw has read it, so it is never read and written at once.
// Culling (the paper's stencil culling): the passes shade only the pixels they may change. With a
// stencil (the host's, or the one the MSAA path marks) that is the stencil test; otherwise the
// inputs draw marks translucent pixels in the module's depth buffer (gl_FragDepth 0, the rest 1)
// and the passes draw their triangle at depth 0.5 with GL_GREATER. Either way the inputs draw also
// fills the horizontal pass's target, so the vertical taps find defined values where the culling
// kept the horizontal pass away, and the last vertical pass leaves those pixels alone (in place) or
// copies them (into a separate output).
#include <array>

#include "blur_pass.hpp"
#include "pass_uniforms.hpp"
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

namespace sss::gl {

void draw_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis) {
  set_blur_uniforms(ctx, p, run, term, axis);
  bind_packed_inputs(ctx, p, source, ctx.targets.names().pass_strength);
  if (run.has_profiles()) bind_profile_inputs(ctx, run, axis);
  draw_cover(ctx, p.tile_grid);
}

sss_result draw_pass_inputs(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const PlanPrograms& programs,
                            std::string* message) {
  const Functions& f = ctx.gl;
  const PassInputsProgram& p = *programs.inputs;
  const bool mark_depth = plan.inputs.mark_depth;
  const Targets& t = ctx.targets.names();
  const sss_result r =
      attach_stencil(ctx, t.pass_inputs_framebuffer, mark_depth ? t.stencil_buffer : 0, message, "pass inputs");
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss pass inputs (colour and view distance)");
  f.Disable(STENCIL_TEST);
  if (mark_depth) {  // every pixel of the rectangle written (the test always passes)
    f.Enable(DEPTH_TEST);
    f.DepthFunc(ALWAYS);
    f.DepthMask(1);
    f.set_depth_range(0.0f, 1.0f);  // the passes' triangle at depth 0.5, between the marks
    // The bands of tiles leave pixels out. The passes draw none of them (their bands are inside
    // these), but the copy into a separate output tests every pixel: there they must count as not
    // translucent.
    if (ctx.tile_bands > 0 && !run.keeps_untouched()) {
      const GLfloat far = 1.0f;
      f.ClearBufferfv(DEPTH, 0, &far);  // glClearBuffer leaves the host's clear values alone
    }
  }
  f.UseProgram(p.program);
  const InputsUniforms u = fill_inputs_uniforms(run);
  upload_uniforms(f, kInputsUniforms, p.fields, u.values.data());
  if (p.color_image >= 0) {
    // As bind_packed_inputs' image taps: the colour was last written as a render target.
    f.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
    f.BindImageTexture(0, run.color.name, 0, 0, 0, READ_ONLY, kComputeImageFormats[p.color_image].internal_format);
  } else {
    bind_texture(ctx, unit::source, run.color.name, ctx.objects.sampler);
  }
  bind_texture(ctx, unit::depth, run.depth.name, ctx.objects.depth_sampler);
  if (plan.inputs.profile_ids == 1) bind_texture(ctx, unit::profile_ids, run.profile_ids.name, ctx.objects.nearest_sampler);
  if (plan.inputs.albedo != 0) bind_albedo(ctx, run, plan.inputs.albedo, p.texturing);
  draw_cover(ctx, p.tile_grid);
  // The host's colour leaves the image unit: the next binding there is the module's (or, without
  // the state restore, none).
  if (p.color_image >= 0) f.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  if (mark_depth) f.DepthMask(0);  // the passes only test it
  return SSS_OK;
}

namespace {
// Only the pixels the culling lets through (`func` EQUAL) or only the others (NOTEQUAL).
void set_culling(const Functions& f, const FilterRun& run, GLenum func) {
  if (run.stencil != nullptr) {
    set_stencil_test(f, run.stencil, func);
    return;
  }
  f.Enable(DEPTH_TEST);  // the depth the inputs draw marked (the write mask is off by then)
  f.DepthFunc(func == EQUAL ? GREATER : LEQUAL);
}
}  // namespace

// The stencil (the host's copy, or the MSAA path's mark) or the culling depth on every target.
sss_result attach_pass_targets(PassContext& ctx, const FilterRun& run, const FramePlan& plan, std::string* message) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const GLuint stencil = t.stencil_buffer;
  sss_result r = attach_stencil(ctx, t.pass_intermediate_framebuffer, stencil, message);
  if (r != SSS_OK) return r;
  if (plan.terms > 1) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.accumulator_framebuffer);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, t.accumulators[0], 0);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil);
    r = check_framebuffer(ctx, "sum of the kernel's terms", message);
    if (r != SSS_OK) return r;
  }
  return attach_output(ctx, run, stencil, message);
}

namespace {
// Horizontal: the inputs -> the packed intermediate (the inputs draw filled what the culling excludes).
void draw_horizontal(PassContext& ctx, const FilterRun& run, BlurProgram& p, std::size_t term, int terms) {
  DebugGroup group(ctx.gl, ctx.labels, terms > 1 ? "sss horizontal pass (one term)" : "sss horizontal pass");
  ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().pass_intermediate_framebuffer);
  set_culling(ctx.gl, run, EQUAL);
  draw_blur(ctx, p, run, ctx.targets.names().pass_taps, term, 0);
}

// Vertical into the running sum (pixels the culling excludes are never read from it).
void draw_into_sum(PassContext& ctx, const FilterRun& run, BlurProgram& p, std::size_t term) {
  const Targets& t = ctx.targets.names();
  DebugGroup group(ctx.gl, ctx.labels, "sss vertical pass (one term, into the sum)");
  ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, t.accumulator_framebuffer);
  ctx.gl.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, t.accumulators[term % 2], 0);
  set_culling(ctx.gl, run, EQUAL);
  draw_blur(ctx, p, run, t.pass_intermediate, term, 1);
}

// The last vertical pass: intermediate -> output. Writing back, the host colour is attached here,
// so it is bound to no unit, and alpha is masked off (it keeps the host's exact value).
void draw_last_vertical(PassContext& ctx, const FilterRun& run, const Step& step, BlurProgram& p,
                        FrameMeasurement& measure) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss vertical pass");
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  bind_original(ctx, run);
  measure.begin(PassQueries::vertical);
  if (run.writes_back()) f.ColorMask(1, 1, 1, 0);
  set_culling(f, run, EQUAL);
  // Samples that pass here are the pixels the blur wrote: in place (the untouched discard),
  // exactly the blurred ones; into a separate output every pixel the culling lets through.
  measure.begin_pixels();
  draw_blur(ctx, p, run, ctx.targets.names().pass_intermediate, step.term, 1);
  measure.end_pixels();
  if (run.debug_view != 0) {
    // A view: the pixels the culling keeps from the passes are left alone, (0, 0, 0, 1), drawn by
    // the same program (no scissor box to set, no clear of the host's texture outside the viewport).
    set_culling(f, run, NOTEQUAL);
    set_debug_fill(f, p, true);
    draw_cover(ctx, p.tile_grid);
    set_debug_fill(f, p, false);
  } else if (step.copy_untouched) {
    set_culling(f, run, NOTEQUAL);
    draw_copy(ctx, run.untouched_colour());
  }
  measure.end(PassQueries::vertical);
}
}  // namespace

// gpu_time_ms[0] spans everything before the last vertical pass (for one term: the horizontal
// pass), [1] that pass.
void draw_blur_step(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const Step& step,
                    BlurProgram& program, PlanMeasurement& measure) {
  const Targets& t = ctx.targets.names();
  FrameMeasurement& m = measure.get();
  if (step.axis == 0) {
    if (step.term == 0) m.begin(PassQueries::horizontal);
    draw_horizontal(ctx, run, program, step.term, plan.terms);
    return;
  }
  if (plan.terms > 1) {  // the earlier terms' sum, read by this term's vertical pass
    // texelFetch only; GL_NEAREST (the depth sampler on ES) is complete for any format.
    bind_texture(ctx, unit::accumulated, step.term > 0 ? t.accumulators[(step.term - 1) % 2] : 0,
                 ctx.objects.depth_sampler);
  }
  if (step.into == Into::sum) {
    draw_into_sum(ctx, run, program, step.term);
    return;
  }
  m.end(PassQueries::horizontal);
  draw_last_vertical(ctx, run, step, program, m);
  m.end_frame();
}

sss_result copy_colour(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  begin_passes(ctx, run.viewport);
  f.Disable(STENCIL_TEST);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.output.name, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
  const sss_result r = check_framebuffer(ctx, "output copy", message);
  if (r == SSS_OK) {
    DebugGroup group(f, ctx.labels, "sss copy (identity settings)");
    draw_copy(ctx, run.color.name);
  }
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

}  // namespace sss::gl
