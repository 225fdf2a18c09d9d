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
#include "runners.hpp"
#include "shader_constants.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
using TermPrograms = std::array<BlurProgram*, 2 * math::kMaxPlanTerms>;  // [2t]: horizontal, [2t + 1]: vertical

// The accumulators' image format (RGBA32F on desktop GL, where the compute path runs).
int accumulator_format(const Functions& gl, const FilterRun& run) {
  return image_format_index(static_cast<GLint>(accumulators_are_half(gl, run) ? RGBA16F : RGBA32F));
}

// Programs first, then the targets: a variant that fails to build must not leave a new target behind.
sss_result build_programs(PassContext& ctx, const FilterRun& run, TermPrograms* programs, std::string* message) {
  const std::size_t terms = run.kernel->terms.size();
  const ComputePass horizontal = run.stencil != nullptr ? ComputePass::horizontal_marked : ComputePass::horizontal;
  const int intermediate_format = image_format_index(run.intermediate_format());
  const Outside last_outside = run.writes_back() ? Outside::discard : Outside::copy_original;
  sss_result r = SSS_OK;
  for (std::size_t t = 0; t < terms && r == SSS_OK; ++t) {
    r = ctx.programs.compute(blur_variant(run, t, 0, Outside::write_centre), intermediate_format, horizontal,
                             &(*programs)[2 * t], message);
    const bool last = t + 1 == terms;
    const int format = last ? image_format_index(run.target().internal_format) : accumulator_format(ctx.gl, run);
    if (r == SSS_OK) {
      r = ctx.programs.compute(blur_variant(run, t, 1, last ? last_outside : Outside::write_centre), format,
                               ComputePass::vertical, &(*programs)[2 * t + 1], message);
    }
  }
  return r;
}

sss_result prepare(PassContext& ctx, const FilterRun& run, TermPrograms* programs, std::string* message) {
  sss_result r = build_programs(ctx, run, programs, message);
  if (r == SSS_OK) {
    r = ctx.targets.ensure_intermediate(run.intermediate_format(), run.color.width, run.color.height, message);
  }
  if (r == SSS_OK && run.kernel->terms.size() > 1) {
    r = ctx.targets.ensure_accumulators(run.color.width, run.color.height, accumulators_are_half(ctx.gl, run),
                                        message);
  }
  return r;
}

GLuint groups(int pixels, int per_group) { return static_cast<GLuint>((pixels + per_group - 1) / per_group); }

// One dispatch of `p` writing `target` (image unit 0, its format `format`) from `source`.
void dispatch_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis,
                   GLuint target, int format, GLenum access) {
  const Functions& f = ctx.gl;
  set_blur_uniforms(ctx, p, run, term, axis);
  const std::array<int, 4>& rect = run.draw_rect;
  f.Uniform4i(p.rect, rect[0], rect[1], rect[2], rect[3]);
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

// The stencil's mark: the intermediate cleared to 0 and the colour copied into it where the
// host's stencil test passes, over the draw rectangle.
sss_result mark_stencil(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss the host's stencil, for the compute passes");
  begin_passes(ctx, run.draw_rect);
  // The stencil goes on the intermediate's framebuffer, where the mark is drawn.
  const sss_result r = copy_stencil(ctx, run, *run.stencil, message, ctx.targets.names().intermediate_framebuffer);
  if (r != SSS_OK) return r;
  f.Disable(STENCIL_TEST);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  f.ClearBufferfv(COLOR, 0, zero);
  set_stencil_test(f, run.stencil, EQUAL);
  draw_copy(ctx, run.color.name);
  f.Disable(STENCIL_TEST);
  // The dispatches that read the mark through the image unit come after these framebuffer writes.
  f.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
  return SSS_OK;
}

// With a region and a separate output, the pixels of the viewport outside the region keep their
// input: a fragment copy first.
sss_result copy_outside_region_first(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  begin_passes(ctx, run.draw_rect);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.output.name, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
  const sss_result r = check_framebuffer(ctx, "output copy", message);
  if (r == SSS_OK) copy_outside_region(ctx, run);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
  return r;
}

// Every term's two dispatches; gpu_time_ms[0] spans everything before the last vertical pass, [1]
// that pass (as the fragment runner).
void dispatch_terms(PassContext& ctx, const FilterRun& run, const TermPrograms& programs) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const std::size_t terms = run.kernel->terms.size();
  const int intermediate_format = image_format_index(run.intermediate_format());
  FrameMeasurement measure(ctx.queries, run.frame);
  measure.begin(PassQueries::horizontal);
  for (std::size_t term = 0; term < terms; ++term) {
    {
      DebugGroup group(f, ctx.labels, "sss horizontal pass (compute)");
      dispatch_blur(ctx, *programs[2 * term], run, run.color.name, term, 0, t.intermediate, intermediate_format,
                    run.stencil != nullptr ? READ_WRITE : WRITE_ONLY);
    }
    between_dispatches(f);
    if (terms > 1) {  // the earlier terms' sum, read by this term's vertical pass
      bind_texture(ctx, unit::accumulated, term > 0 ? t.accumulators[(term - 1) % 2] : 0, ctx.objects.depth_sampler);
    }
    if (term + 1 < terms) {
      DebugGroup group(f, ctx.labels, "sss vertical pass (compute, one term, into the sum)");
      dispatch_blur(ctx, *programs[2 * term + 1], run, t.intermediate, term, 1, t.accumulators[term % 2],
                    accumulator_format(f, run), WRITE_ONLY);
      between_dispatches(f);
      continue;
    }
    measure.end(PassQueries::horizontal);
    DebugGroup group(f, ctx.labels, "sss vertical pass (compute)");
    measure.begin(PassQueries::vertical);
    bind_original(ctx, run);
    dispatch_blur(ctx, *programs[2 * term + 1], run, t.intermediate, term, 1, run.target().name,
                  image_format_index(run.target().internal_format), WRITE_ONLY);
    measure.end(PassQueries::vertical);
  }
  measure.end_frame();
}
}  // namespace

const char* compute_unavailable(const Functions& gl, const FilterRun& run) {
  if (!gl.has_compute) return "the context has no compute shaders (OpenGL 4.3+ desktop)";
  if (run.color.multisampled()) return "the colour is multisampled";
  if (run.cross_bilateral) return "the cross-bilateral mode runs as fragment passes";
  if (run.has_profiles()) return "per-pixel profiles (profile_texture) run on the fragment passes";
  if (image_format_index(run.target().internal_format) < 0) {
    return "the target's format has no image format (RGBA16F, RGBA32F or R11F_G11F_B10F)";
  }
  if (!run.target_complete) {
    return "the target texture may be incomplete (a mipmap GL_TEXTURE_MIN_FILTER, the default, with more levels "
           "allowed than it may have), and image stores to an incomplete texture are undefined: give it a "
           "GL_NEAREST or GL_LINEAR min filter, or set SSS_FRAME_TARGET_COMPLETE";
  }
  return "";
}

sss_result prepare_compute(PassContext& ctx, const FilterRun& run, std::string* message) {
  TermPrograms programs{};
  return prepare(ctx, run, &programs, message);
}

sss_result run_compute(PassContext& ctx, const FilterRun& run, std::string* message) {
  TermPrograms programs{};
  sss_result r = prepare(ctx, run, &programs, message);
  if (r == SSS_OK && run.region && !run.writes_back()) r = copy_outside_region_first(ctx, run, message);
  if (r == SSS_OK && run.stencil != nullptr) r = mark_stencil(ctx, run, message);
  if (r != SSS_OK) return r;
  dispatch_terms(ctx, run, programs);
  // The host may use its texture in any way next (sampling, attaching, reading back, copying):
  // every kind of access waits for the image stores.
  ctx.gl.MemoryBarrier(ALL_BARRIER_BITS);
  // Never leave a host texture on the unit (the StateGuard puts the host's binding back; without
  // it the unit is left empty).
  ctx.gl.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  return SSS_OK;
}

}  // namespace sss::gl
