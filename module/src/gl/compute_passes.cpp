// The compute path (sss.h SSS_PATH_COMPUTE, OpenGL 4.3+): the same passes as the fragment runner,
// one horizontal and one vertical dispatch of separable_blur.comp per kernel term, each caching its
// tiles in shared memory (module/src/gl/shader_constants.hpp kComputeTiles). Horizontal: host
// colour -> the intermediate (RGBA16F, RGBA32F for RGBA32F colour; image unit 0); vertical:
// intermediate -> the sum of the terms so far (the module's accumulators, read back on unit 3 by
// the next term's vertical pass), the last one -> the host's colour or the separate output. The
// image unit is part of the StateGuard's list; samplers and texture units are the fragment path's.
//
// The host's stencil: a dispatch has no stencil test, so before the first horizontal pass a
// fragment draw behind the stencil (the fragment passes' test) copies the colour into the cleared
// intermediate; the horizontal dispatches read each pixel's strength from there (SSS_MARKED), 0 where
// the stencil fails, which leaves such pixels as the fragment passes do: copied by the horizontal
// pass (its alpha 0 then) and, being not translucent to the vertical pass, left alone or copied there.
// Each horizontal pass writes back the strength it read, so the mark holds for the next term's.
#include "blur_pass.hpp"
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "shader_constants.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
GLuint groups(int pixels, int per_group) { return static_cast<GLuint>((pixels + per_group - 1) / per_group); }

// One dispatch of `p` writing `target` (image unit 0, its format `format`) from `source`.
void dispatch_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis,
                   GLuint target, int format, GLenum access) {
  const Functions& f = ctx.gl;
  set_blur_uniforms(ctx, p, run, term, axis);  // with u_rect, the draw rectangle
  const std::array<int, 4>& rect = run.draw_rect;
  bind_blur_inputs(ctx, source, run.depth.name);
  f.BindImageTexture(0, target, 0, 0, 0, access, kComputeImageFormats[format].internal_format);
  // One work group per tile: its segment along the axis (x), its lines across (y).
  const ComputeTile& tile = kComputeTiles[axis];
  const int along = rect[2 + axis], across = rect[3 - axis];
  f.DispatchCompute(groups(along, tile.segment), groups(across, tile.lines), 1);
  ++ctx.draws;
}

// The next dispatch reads (through a sampler or the image unit) what the last one stored, or
// stores where the last one read.
void between_dispatches(const Functions& f) { f.MemoryBarrier(TEXTURE_FETCH_BARRIER_BIT | SHADER_IMAGE_ACCESS_BARRIER_BIT); }

// With a region and a separate output, the pixels of the viewport outside the region keep their
// input: a fragment copy first.
}  // namespace

sss_result copy_outside_region_first(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.output.name, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
  const sss_result r = check_framebuffer(ctx, "output copy", message);
  if (r == SSS_OK) copy_outside_region(ctx, run);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

// The stencil's mark (the host's stencil copied onto the intermediate's framebuffer first): the
// intermediate cleared to 0 and the colour copied into it where the host's stencil test passes,
// over the draw rectangle.
void mark_compute_stencil(PassContext& ctx, const FilterRun& run) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss the host's stencil, for the compute passes");
  f.Disable(STENCIL_TEST);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  f.ClearBufferfv(COLOR, 0, zero);
  set_stencil_test(f, run.stencil, EQUAL);
  draw_copy(ctx, run.color.name);
  f.Disable(STENCIL_TEST);
  // The dispatches that read the mark through the image unit come after these framebuffer writes.
  f.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

// One term's horizontal or vertical dispatch; gpu_time_ms[0] spans everything before the last
// vertical pass, [1] that pass (as the fragment passes).
void dispatch_step(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const Step& step,
                   BlurProgram& program, PlanMeasurement& measurement) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  FrameMeasurement& measure = measurement.get();
  const std::size_t term = step.term;
  if (step.axis == 0) {
    if (term == 0) measure.begin(PassQueries::horizontal);
    {
      DebugGroup group(f, ctx.labels, "sss horizontal pass (compute)");
      dispatch_blur(ctx, program, run, run.color.name, term, 0, t.intermediate, step.image_format,
                    run.stencil != nullptr ? READ_WRITE : WRITE_ONLY);
    }
    between_dispatches(f);
    return;
  }
  if (plan.terms > 1) {  // the earlier terms' sum, read by this term's vertical pass
    bind_texture(ctx, unit::accumulated, term > 0 ? t.accumulators[(term - 1) % 2] : 0, ctx.objects.depth_sampler);
  }
  if (step.into == Into::sum) {
    DebugGroup group(f, ctx.labels, "sss vertical pass (compute, one term, into the sum)");
    dispatch_blur(ctx, program, run, t.intermediate, term, 1, t.accumulators[term % 2], step.image_format, WRITE_ONLY);
    between_dispatches(f);
    return;
  }
  measure.end(PassQueries::horizontal);
  DebugGroup group(f, ctx.labels, "sss vertical pass (compute)");
  measure.begin(PassQueries::vertical);
  bind_original(ctx, run);
  dispatch_blur(ctx, program, run, t.intermediate, term, 1, run.target().name, step.image_format, WRITE_ONLY);
  measure.end(PassQueries::vertical);
  measure.end_frame();
}

void finish_compute(PassContext& ctx) {
  // The host may use its texture in any way next (sampling, attaching, reading back, copying):
  // every kind of access waits for the image stores.
  ctx.gl.MemoryBarrier(ALL_BARRIER_BITS);
  // Never leave a host texture on the unit (the StateGuard puts the host's binding back; without
  // it the unit is left empty).
  ctx.gl.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
}

}  // namespace sss::gl
