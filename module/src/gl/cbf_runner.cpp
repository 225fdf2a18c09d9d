// The cross-bilateral mode (Mikkelsen 2010) as two fragment passes of cbf_blur.frag. The shader
// cannot read the stencil, so with one the horizontal pass reads a copy of the colour whose alpha
// is 0 outside it (cleared to 0, then the stencil-passing pixels copied): those neighbours get no
// weight in either pass.
#include <vector>

#include "blur_pass.hpp"
#include "debug_label.hpp"
#include "runners.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
// The programs and targets: everything that can fail but the framebuffer checks.
sss_result build(PassContext& ctx, const FilterRun& run, CbfProgram** horizontal, CbfProgram** vertical,
                 std::string* message) {
  const bool linear_depth = run.constants.linear_depth;
  const bool normals = run.normals.name != 0;
  sss_result r = ctx.programs.cross_bilateral(Outside::write_centre, linear_depth, normals, horizontal, message);
  if (r == SSS_OK) {
    const Outside outside = run.writes_back() ? Outside::discard : Outside::copy_original;
    r = ctx.programs.cross_bilateral(outside, linear_depth, normals, vertical, message);
  }
  if (r == SSS_OK) {
    r = ctx.targets.ensure_intermediate(run.intermediate_format(), run.color.width, run.color.height, message);
  }
  if (r == SSS_OK && run.stencil != nullptr) {
    r = ctx.targets.ensure_masked_source(run.color.internal_format, run.color.width, run.color.height, message);
  }
  return r;
}

sss_result prepare(PassContext& ctx, const FilterRun& run, CbfProgram** horizontal, CbfProgram** vertical,
                   std::string* message) {
  sss_result r = build(ctx, run, horizontal, vertical, message);
  if (r != SSS_OK) return r;
  begin_passes(ctx, run.draw_rect);
  // The MSAA path marked or copied the stencil already (stencil_ready): copying "its" stencil
  // again would allocate a stencil copy of format 0 and fail.
  if (run.stencil != nullptr && !run.stencil_ready) r = copy_stencil(ctx, run, *run.stencil, message);
  if (r != SSS_OK) return r;
  const Targets& t = ctx.targets.names();
  const GLuint stencil = run.stencil != nullptr ? t.stencil_buffer : 0;
  r = attach_stencil(ctx, ctx.targets.names().intermediate_framebuffer, stencil, message);
  if (r == SSS_OK && run.stencil != nullptr) {
    ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, t.masked_framebuffer);
    ctx.gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil);
    r = check_framebuffer(ctx, "masked colour copy", message);
  }
  return r == SSS_OK ? attach_output(ctx, run, stencil, message) : r;
}

void set_cbf_uniforms(const Functions& f, CbfProgram& p, const FilterRun& run, int axis) {
  const math::PassConstants& k = run.constants;
  const math::CbfKernel& kernel = *run.cbf_kernel;
  f.UseProgram(p.program);
  if (p.kernel_revision != run.cbf_kernel_revision) {
    const math::FootprintTable& table = kernel.table;
    std::vector<float> packed;
    packed.reserve(table.half_cdf.size() * 4);
    for (const auto& entry : table.half_cdf) packed.insert(packed.end(), {entry[0], entry[1], entry[2], 0.0f});
    f.Uniform4fv(p.cdf, static_cast<GLsizei>(packed.size() / 4), packed.data());
    f.Uniform4f(p.footprint, table.reach_mm, table.delta[0], table.delta[1], table.delta[2]);
    f.Uniform1fv(p.spacing, static_cast<GLsizei>(kernel.spacing.size()), kernel.spacing.data());
    f.Uniform1i(p.half_taps, static_cast<GLint>(kernel.spacing.size()));
    f.Uniform4f(p.spike_blend, kernel.spike_blend[0], kernel.spike_blend[1], kernel.spike_blend[2], 0.0f);
    f.Uniform4f(p.inv_two_variance, kernel.inv_two_variance[0], kernel.inv_two_variance[1],
                kernel.inv_two_variance[2], 0.0f);
    p.kernel_revision = run.cbf_kernel_revision;
  }
  f.Uniform1f(p.pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  f.Uniform4f(p.clamp, k.clamp_min[0], k.clamp_min[1], k.clamp_max[0], k.clamp_max[1]);
  f.Uniform2f(p.pixel_span, k.pixel_span[0], k.pixel_span[1]);
  f.Uniform4f(p.ray_slope, k.slope_scale[0], k.slope_scale[1], k.slope_bias[0], k.slope_bias[1]);
  f.Uniform1f(p.mm_per_world, k.mm_per_world);
  f.Uniform1i(p.round_to_half, writes_half_float(f, run, 0, axis) ? 1 : 0);
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

void draw_passes(PassContext& ctx, const FilterRun& run, CbfProgram& horizontal, CbfProgram& vertical) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  FrameMeasurement measure(ctx.queries, run.frame);
  measure.begin(PassQueries::horizontal);  // the masked copy counts with it
  if (run.stencil != nullptr) copy_masked_colour(ctx, run);
  {
    DebugGroup group(f, ctx.labels, "sss cross-bilateral horizontal pass");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.intermediate_framebuffer);
    set_stencil_test(f, run.stencil, EQUAL);
    draw_cbf(ctx, horizontal, run, run.stencil != nullptr ? t.masked_source : run.color.name, 0);
    if (run.stencil != nullptr) {
      set_stencil_test(f, run.stencil, NOTEQUAL);
      draw_copy(ctx, t.masked_source);  // alpha 0: the vertical pass gives these no weight either
    }
    measure.end(PassQueries::horizontal);
  }
  {
    DebugGroup group(f, ctx.labels, "sss cross-bilateral vertical pass");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.output_framebuffer);
    bind_original(ctx, run);
    measure.begin(PassQueries::vertical);
    if (run.writes_back()) f.ColorMask(1, 1, 1, 0);
    set_stencil_test(f, run.stencil, EQUAL);
    measure.begin_pixels();
    draw_cbf(ctx, vertical, run, t.intermediate, 1);
    measure.end_pixels();
    if (run.stencil != nullptr && !run.writes_back()) {
      set_stencil_test(f, run.stencil, NOTEQUAL);
      draw_copy(ctx, run.color.name);
    }
    measure.end(PassQueries::vertical);
  }
  measure.end_frame();
}
}  // namespace

sss_result prepare_cross_bilateral(PassContext& ctx, const FilterRun& run, std::string* message) {
  CbfProgram* horizontal = nullptr;
  CbfProgram* vertical = nullptr;
  return build(ctx, run, &horizontal, &vertical, message);
}

sss_result run_cross_bilateral(PassContext& ctx, const FilterRun& run, std::string* message) {
  CbfProgram* horizontal = nullptr;
  CbfProgram* vertical = nullptr;
  const sss_result r = prepare(ctx, run, &horizontal, &vertical, message);
  if (r == SSS_OK) draw_passes(ctx, run, *horizontal, *vertical);
  detach_output(ctx);
  return r;
}

}  // namespace sss::gl
