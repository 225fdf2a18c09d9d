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
#include "debug_label.hpp"
#include "runners.hpp"
#include "texture_units.hpp"

namespace sss::gl {

void draw_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis) {
  set_blur_uniforms(ctx, p, run, term, axis);
  bind_packed_inputs(ctx, p, source, ctx.targets.names().pass_strength);
  if (run.has_profiles()) bind_profile_inputs(ctx, run, axis);
  draw_cover(ctx, p.tile_grid);
}

namespace {
// The colour's image format for the inputs draw (PassInputsVariant::color_image): single-sample
// RGBA16F or RGBA32F; -1 for any other colour.
int color_image_format(const FilterRun& run) {
  const int format = image_format_index(run.color.internal_format);
  return !run.color.multisampled() && format >= 0 && format < kPassInputsColorImageFormats ? format : -1;
}
}  // namespace

int readable_color_image(const FilterRun& run) { return run.color_complete ? color_image_format(run) : -1; }

PassInputsVariant pass_inputs_variant(const FilterRun& run) {
  PassInputsVariant v;
  v.linear_depth = run.constants.linear_depth;
  v.profile_ids = profile_ids_variant(run);
  v.mark_depth = run.stencil == nullptr;
  v.color_image = readable_color_image(run);
  return v;
}

bool may_read_color_image(const Functions& gl, const FilterRun& run) {
  return gl.has_compute && !run.identity && !run.cross_bilateral && run.strength.name == 0 &&
         color_image_format(run) >= 0;
}

// The passes' inputs over the drawn rectangle (where the taps stay), every pixel of it: the taps
// read outside the culled pixels too. Without a stencil it marks the culling depth.
sss_result draw_pass_inputs(PassContext& ctx, const FilterRun& run, const PassInputsVariant& v,
                            std::string* message) {
  const Functions& f = ctx.gl;
  PassInputsProgram* p = nullptr;
  sss_result r = ctx.programs.pass_inputs(v, &p, message);
  if (r != SSS_OK) return r;
  const Targets& t = ctx.targets.names();
  r = attach_stencil(ctx, t.pass_inputs_framebuffer, v.mark_depth ? t.stencil_buffer : 0, message, "pass inputs");
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss pass inputs (colour and view distance)");
  f.Disable(STENCIL_TEST);
  if (v.mark_depth) {  // every pixel of the rectangle written (the test always passes)
    f.Enable(DEPTH_TEST);
    f.DepthFunc(ALWAYS);
    f.DepthMask(1);
    f.set_depth_range(0.0f, 1.0f);  // the passes' triangle at depth 0.5, between the marks
    // The bands of tiles leave pixels out. The passes draw none of them (their bands are inside
    // these), but the copy into a separate output tests every pixel: there they must count as not
    // translucent.
    if (ctx.tile_bands > 0 && !run.writes_back()) {
      const GLfloat far = 1.0f;
      f.ClearBufferfv(DEPTH, 0, &far);  // glClearBuffer leaves the host's clear values alone
    }
  }
  f.UseProgram(p->program);
  const math::PassConstants& k = run.constants;
  f.Uniform2f(p->ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p->depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  if (p->color_image >= 0) {
    // As bind_packed_inputs' image taps: the colour was last written as a render target.
    f.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
    f.BindImageTexture(0, run.color.name, 0, 0, 0, READ_ONLY, kComputeImageFormats[p->color_image].internal_format);
  } else {
    bind_texture(ctx, unit::source, run.color.name, ctx.objects.sampler);
  }
  bind_texture(ctx, unit::depth, run.depth.name, ctx.objects.depth_sampler);
  if (v.profile_ids == 1) bind_texture(ctx, unit::profile_ids, run.profile_ids.name, ctx.objects.nearest_sampler);
  draw_cover(ctx, p->tile_grid);
  // The host's colour leaves the image unit: the next binding there is the module's (or, without
  // the state restore, none).
  if (p->color_image >= 0) f.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  if (v.mark_depth) f.DepthMask(0);  // the passes only test it
  return SSS_OK;
}

namespace {
using TermPrograms = std::array<BlurProgram*, 2 * math::kMaxPlanTerms>;  // [2t]: horizontal, [2t + 1]: vertical

// Programs first: a variant that fails to build must not leave a new target behind.
// The terms the passes run: a debug view shows the first term's passes only.
std::size_t terms_run(const FilterRun& run) { return run.debug_view != 0 ? 1 : run.kernel->terms.size(); }

sss_result build_programs(PassContext& ctx, const FilterRun& run, TermPrograms* programs, std::string* message) {
  const std::size_t terms = terms_run(run);
  const Outside last_outside = run.writes_back() ? Outside::discard : Outside::copy_original;
  sss_result r = SSS_OK;
  for (std::size_t t = 0; t < terms && r == SSS_OK; ++t) {
    r = ctx.programs.blur(fragment_blur_variant(run, t, 0, Outside::write_centre), &(*programs)[2 * t], message);
    const Outside outside = t + 1 == terms ? last_outside : Outside::write_centre;
    if (r == SSS_OK) {
      r = ctx.programs.blur(fragment_blur_variant(run, t, 1, outside), &(*programs)[2 * t + 1], message);
    }
  }
  return r;
}

// Only the pixels the culling lets through (`func` EQUAL) or only the others (NOTEQUAL).
void set_culling(const Functions& f, const FilterRun& run, GLenum func) {
  if (run.stencil != nullptr) {
    set_stencil_test(f, run.stencil, func);
    return;
  }
  f.Enable(DEPTH_TEST);  // the depth the inputs draw marked (the write mask is off by then)
  f.DepthFunc(func == EQUAL ? GREATER : LEQUAL);
}

// The stencil (copied from the host's unless the caller marked it) or the culling depth, and the
// targets of the passes, with that buffer on every one of them.
sss_result attach_targets(PassContext& ctx, const FilterRun& run, std::size_t terms, std::string* message) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  if (run.stencil != nullptr && !run.stencil_ready) {
    const sss_result r = copy_stencil(ctx, run, *run.stencil, message);
    if (r != SSS_OK) return r;
  }
  const GLuint stencil = t.stencil_buffer;
  sss_result r = attach_stencil(ctx, t.pass_intermediate_framebuffer, stencil, message);
  if (r != SSS_OK) return r;
  if (terms > 1) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.accumulator_framebuffer);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, t.accumulators[0], 0);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil);
    r = check_framebuffer(ctx, "sum of the kernel's terms", message);
    if (r != SSS_OK) return r;
  }
  return attach_output(ctx, run, stencil, message);
}

// Horizontal: the inputs -> the packed intermediate (the inputs draw filled what the culling excludes).
void draw_horizontal(PassContext& ctx, const FilterRun& run, BlurProgram& p, std::size_t term, std::size_t terms) {
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
void draw_last_vertical(PassContext& ctx, const FilterRun& run, BlurProgram& p, std::size_t term,
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
  draw_blur(ctx, p, run, ctx.targets.names().pass_intermediate, term, 1);
  measure.end_pixels();
  if (run.debug_view != 0) {
    // A view: the pixels the culling keeps from the passes are left alone, (0, 0, 0, 1), drawn by
    // the same program (no scissor box to set, no clear of the host's texture outside the viewport).
    set_culling(f, run, NOTEQUAL);
    f.Uniform1i(p.debug_fill, 1);
    draw_cover(ctx, p.tile_grid);
    f.Uniform1i(p.debug_fill, 0);
  } else if (!run.writes_back() && !run.output_outside_stencil_unread) {
    set_culling(f, run, NOTEQUAL);
    draw_copy(ctx, run.color.name);
  }
  measure.end(PassQueries::vertical);
}

// gpu_time_ms[0] spans everything before the last vertical pass (for one term: the horizontal
// pass), [1] that pass.
void draw_terms(PassContext& ctx, const FilterRun& run, const TermPrograms& programs, std::size_t terms) {
  const Targets& t = ctx.targets.names();
  FrameMeasurement measure(ctx.queries, run.frame);
  measure.begin(PassQueries::horizontal);
  for (std::size_t term = 0; term < terms; ++term) {
    draw_horizontal(ctx, run, *programs[2 * term], term, terms);
    if (terms > 1) {  // the earlier terms' sum, read by this term's vertical pass
      // texelFetch only; GL_NEAREST (the depth sampler on ES) is complete for any format.
      bind_texture(ctx, unit::accumulated, term > 0 ? t.accumulators[(term - 1) % 2] : 0, ctx.objects.depth_sampler);
    }
    if (term + 1 < terms) {
      draw_into_sum(ctx, run, *programs[2 * term + 1], term);
      continue;
    }
    measure.end(PassQueries::horizontal);
    draw_last_vertical(ctx, run, *programs[2 * term + 1], term, measure);
  }
  measure.end_frame();
}

// The programs and targets of the separable passes: everything that can fail but the framebuffer
// checks, all before the first draw.
sss_result prepare_separable(PassContext& ctx, const FilterRun& run, TermPrograms* programs, std::string* message) {
  sss_result r = build_programs(ctx, run, programs, message);
  PassInputsProgram* unused = nullptr;
  if (r == SSS_OK) r = ctx.programs.pass_inputs(pass_inputs_variant(run), &unused, message);
  if (r == SSS_OK) r = ctx.targets.ensure_pass_targets(run.color.width, run.color.height, message);
  if (r == SSS_OK && run.stencil == nullptr) {  // the culling depth (a stencil run copies or marks its own)
    r = ctx.targets.ensure_stencil_buffer(static_cast<GLint>(DEPTH24_STENCIL8), run.color.width, run.color.height,
                                          message);
  }
  if (r == SSS_OK && terms_run(run) > 1) {
    r = ctx.targets.ensure_accumulators(run.color.width, run.color.height, accumulators_are_half(ctx.gl, run),
                                        message);
  }
  return r;
}

}  // namespace

sss_result prepare_fragment(PassContext& ctx, const FilterRun& run, std::string* message) {
  if (run.identity) return SSS_OK;
  if (run.cross_bilateral) return prepare_cross_bilateral(ctx, run, message);
  TermPrograms programs{};
  return prepare_separable(ctx, run, &programs, message);
}

sss_result run_fragment(PassContext& ctx, const FilterRun& run, std::string* message) {
  return run_separable(ctx, run, false, message);
}

sss_result run_separable(PassContext& ctx, const FilterRun& run, bool tiles, std::string* message) {
  if (run.identity) return run_identity(ctx, run, message);
  if (run.cross_bilateral) return run_cross_bilateral(ctx, run, message);
  if (run.debug_view == SSS_DEBUG_VIEW_TILES) return run_tile_view(ctx, run, message);
  const std::size_t terms = terms_run(run);
  TermPrograms programs{};
  sss_result r = prepare_separable(ctx, run, &programs, message);
  if (r == SSS_OK && tiles) r = prepare_tile_culling(ctx, run, message);
  if (r != SSS_OK) return r;
  begin_passes(ctx, run.draw_rect);
  if (tiles) r = mark_tiles(ctx, run, message);
  if (r == SSS_OK && !run.inputs_ready) r = draw_pass_inputs(ctx, run, pass_inputs_variant(run), message);
  if (r == SSS_OK) r = attach_targets(ctx, run, terms, message);
  if (r == SSS_OK) draw_terms(ctx, run, programs, terms);
  ctx.tile_bands = 0;
  detach_output(ctx);
  return r;
}

sss_result run_identity(PassContext& ctx, const FilterRun& run, std::string* message) {
  if (run.writes_back()) return SSS_OK;  // in place: nothing changes
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
