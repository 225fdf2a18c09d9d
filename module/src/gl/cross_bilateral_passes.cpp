// The cross-bilateral mode (Mikkelsen 2010) as two fragment passes of cbf_blur.frag. The shader
// cannot read the stencil, so with one the horizontal pass reads a copy of the colour whose alpha
// is 0 outside it (cleared to 0, then the stencil-passing pixels copied): those neighbours get no
// weight in either pass.
#include <vector>

#include "blur_pass.hpp"
#include "pass_uniforms.hpp"
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

namespace sss::gl {

// The framebuffers of the two passes, with the stencil (the host's copy, or the MSAA path's mark)
// on the horizontal pass's and the masked colour copy's.
sss_result attach_cbf_targets(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Targets& t = ctx.targets.names();
  const GLuint stencil = run.stencil != nullptr ? t.stencil_buffer : 0;
  sss_result r = attach_stencil(ctx, t.intermediate_framebuffer, stencil, message);
  if (r == SSS_OK && run.stencil != nullptr) {
    ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, t.masked_framebuffer);
    ctx.gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil);
    r = check_framebuffer(ctx, "masked colour copy", message);
  }
  return r == SSS_OK ? attach_output(ctx, run, stencil, message) : r;
}

namespace {
void set_cbf_uniforms(const Functions& f, CbfProgram& p, const FilterRun& run, int axis) {
  const math::CbfKernel& kernel = *run.cbf_kernel;
  f.UseProgram(p.program);
  if (p.kernel_revision != run.cbf_kernel_revision) {
    const math::FootprintTable& table = kernel.table;
    std::vector<float> packed;
    packed.reserve(table.half_cdf.size() * 4);
    for (const auto& entry : table.half_cdf) packed.insert(packed.end(), {entry[0], entry[1], entry[2], 0.0f});
    f.Uniform4fv(p.cdf, static_cast<GLsizei>(packed.size() / 4), packed.data());
    f.Uniform1fv(p.spacing, static_cast<GLsizei>(kernel.spacing.size()), kernel.spacing.data());
    p.kernel_revision = run.cbf_kernel_revision;
  }
  // The pass's struct, with the kernel's reach, tap count, spike blend and widths (pass_uniforms.hpp).
  const CbfUniforms u = fill_cbf_uniforms(run, axis, writes_half_float(f, run, 0, axis));
  upload_uniforms(f, kCbfUniforms, p.fields, u.values.data());
}

void draw_cbf(PassContext& ctx, CbfProgram& p, const FilterRun& run, GLuint source, int axis) {
  set_cbf_uniforms(ctx.gl, p, run, axis);
  bind_texture(ctx, unit::source, source, ctx.objects.sampler);
  // Depth and normals are only texelFetch'ed here, but a texture must still be complete for its
  // sampler: on ES a depth texture (and an RGBA32F one without OES_texture_float_linear) is not
  // with GL_LINEAR, so both use the depth sampler (GL_NEAREST on ES).
  bind_texture(ctx, unit::depth, run.depth.name, ctx.objects.depth_sampler);
  if (run.normals.name != 0) bind_texture(ctx, unit::normals, run.normals.name, ctx.objects.depth_sampler);
  ctx.gl.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
}

// The colour with alpha 0 outside the stencil, the horizontal pass's input.
void copy_masked_colour(PassContext& ctx, const FilterRun& run) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss masked colour copy");
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().masked_framebuffer);
  const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  f.Disable(STENCIL_TEST);
  f.ClearBufferfv(COLOR, 0, zero);
  set_stencil_test(f, run.stencil, EQUAL);
  draw_copy(ctx, run.color.name);
}

}  // namespace

// The horizontal pass (with a stencil, from the masked copy of the colour, then the copy of the
// pixels outside it), or the vertical one; the masked copy counts with the horizontal pass.
void draw_cbf_pass(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, int axis, PlanMeasurement& measurement) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  FrameMeasurement& measure = measurement.get();
  if (axis == 0) {
    measure.begin(PassQueries::horizontal);
    if (run.stencil != nullptr) copy_masked_colour(ctx, run);
    DebugGroup group(f, ctx.labels, "sss cross-bilateral horizontal pass");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.intermediate_framebuffer);
    set_stencil_test(f, run.stencil, EQUAL);
    draw_cbf(ctx, *p.cbf[0], run, run.stencil != nullptr ? t.masked_source : run.color.name, 0);
    if (run.stencil != nullptr) {
      set_stencil_test(f, run.stencil, NOTEQUAL);
      draw_copy(ctx, t.masked_source);  // alpha 0: the vertical pass gives these no weight either
    }
    measure.end(PassQueries::horizontal);
    return;
  }
  {
    DebugGroup group(f, ctx.labels, "sss cross-bilateral vertical pass");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.output_framebuffer);
    bind_original(ctx, run);
    measure.begin(PassQueries::vertical);
    if (run.writes_back()) f.ColorMask(1, 1, 1, 0);
    set_stencil_test(f, run.stencil, EQUAL);
    measure.begin_pixels();
    draw_cbf(ctx, *p.cbf[1], run, t.intermediate, 1);
    measure.end_pixels();
    if (run.stencil != nullptr && !run.keeps_untouched()) {
      set_stencil_test(f, run.stencil, NOTEQUAL);
      draw_copy(ctx, run.untouched_colour());
    }
    measure.end(PassQueries::vertical);
  }
  measure.end_frame();
}

}  // namespace sss::gl
