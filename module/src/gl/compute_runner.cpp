// The compute path (sss.h SSS_PATH_COMPUTE, OpenGL 4.3+): the same two passes as the fragment
// runner, as dispatches of separable_blur.comp that cache each row (then column) segment in shared
// memory. Horizontal: host colour -> the intermediate (RGBA16F, RGBA32F for RGBA32F colour; image unit 0); vertical:
// intermediate -> the host's colour or the separate output (image unit 0). The image unit is part
// of the StateGuard's list; samplers and texture units are the fragment path's.
#include "blur_pass.hpp"
#include "debug_label.hpp"
#include "runners.hpp"
#include "shader_constants.hpp"

namespace sss::gl {

namespace {
GLuint groups(int pixels) { return static_cast<GLuint>((pixels + kComputeSegment - 1) / kComputeSegment); }

void dispatch_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, int axis) {
  const Functions& f = ctx.gl;
  set_blur_uniforms(ctx, p, run, 0, axis);
  const std::array<int, 4>& rect = run.draw_rect;
  f.Uniform4i(p.rect, rect[0], rect[1], rect[2], rect[3]);
  bind_blur_inputs(ctx, source, run.depth.name);
  // One work group per segment of a row (horizontal) or column (vertical) of the rectangle.
  if (axis == 0) {
    f.DispatchCompute(groups(rect[2]), static_cast<GLuint>(rect[3]), 1);
  } else {
    f.DispatchCompute(groups(rect[3]), static_cast<GLuint>(rect[2]), 1);
  }
  ++ctx.draws;
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
}  // namespace

const char* compute_unavailable(const Functions& gl, const FilterRun& run) {
  if (!gl.has_compute) return "the context has no compute shaders (OpenGL 4.3+ desktop)";
  if (run.color.multisampled()) return "the colour is multisampled";
  if (run.cross_bilateral) return "the cross-bilateral mode runs as fragment passes";
  if (run.stencil != nullptr) return "a stencil mask needs the fragment passes' stencil test";
  if (run.has_profiles()) return "per-pixel profiles (profile_texture) run on the fragment passes";
  if (run.kernel == nullptr || run.kernel->terms.size() != 1) return "the kernel has several terms";
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

sss_result run_compute(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  const TextureInfo& target = run.target();
  const int target_format = image_format_index(target.internal_format);
  BlurProgram* horizontal = nullptr;
  BlurProgram* vertical = nullptr;
  const int intermediate_format = image_format_index(run.intermediate_format());
  sss_result r = ctx.programs.compute(blur_variant(run, 0, 0, Outside::write_centre), intermediate_format,
                                      &horizontal, message);
  if (r == SSS_OK) {
    const Outside outside = run.writes_back() ? Outside::discard : Outside::copy_original;
    r = ctx.programs.compute(blur_variant(run, 0, 1, outside), target_format, &vertical, message);
  }
  if (r == SSS_OK) {
    r = ctx.targets.ensure_intermediate(run.intermediate_format(), run.color.width, run.color.height, message);
  }
  if (r == SSS_OK && run.region && !run.writes_back()) r = copy_outside_region_first(ctx, run, message);
  if (r != SSS_OK) return r;

  FrameMeasurement measure(ctx.queries, run.frame);
  {
    DebugGroup group(f, ctx.labels, "sss horizontal pass (compute)");
    measure.begin(PassQueries::horizontal);
    f.BindImageTexture(0, ctx.targets.names().intermediate, 0, 0, 0, WRITE_ONLY,
                       kComputeImageFormats[intermediate_format].internal_format);
    dispatch_blur(ctx, *horizontal, run, run.color.name, 0);
    measure.end(PassQueries::horizontal);
  }
  // The vertical pass reads what the horizontal one stored, through its sampler.
  f.MemoryBarrier(TEXTURE_FETCH_BARRIER_BIT);
  {
    DebugGroup group(f, ctx.labels, "sss vertical pass (compute)");
    measure.begin(PassQueries::vertical);
    bind_original(ctx, run);
    f.BindImageTexture(0, target.name, 0, 0, 0, run.writes_back() ? READ_WRITE : WRITE_ONLY,
                       kComputeImageFormats[target_format].internal_format);
    dispatch_blur(ctx, *vertical, run, ctx.targets.names().intermediate, 1);
    measure.end(PassQueries::vertical);
  }
  measure.end_frame();
  // The host may use its texture in any way next (sampling, attaching, reading back, copying):
  // every kind of access waits for the image stores.
  f.MemoryBarrier(ALL_BARRIER_BITS);
  // Never leave a host texture on the unit (the StateGuard puts the host's binding back; without
  // it the unit is left empty).
  f.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  return SSS_OK;
}

}  // namespace sss::gl
