// sss_prepare's GPU side: the programs and targets a frame will need, built and allocated before
// it, so that its run() compiles and allocates nothing (a compile or allocation in the middle of a
// game is a visible hitch). Each path asks its runner's own *_resources function (runners.hpp),
// the very calls the runner makes before drawing; only what a runner does between its draws (the
// MSAA path's resolve-then-passes, the compute path's two programs) is spelt out here, next to the
// runner it follows. The prewarm test (tests/gl/prewarm_test.cpp) counts the GL creations of the
// first frame after it: any drift shows there.
#include "blur_pass.hpp"
#include "runners.hpp"
#include "separable_filter.hpp"

namespace sss::gl {

namespace {

// The host's stencil copied into the module's buffer (pass_setup.cpp copy_stencil allocates it).
sss_result host_stencil_resources(PassContext& ctx, const FilterRun& run, std::string* message) {
  if (run.stencil == nullptr || run.stencil_ready) return SSS_OK;
  return ctx.targets.ensure_stencil_buffer(run.stencil->texture.internal_format, run.color.width, run.color.height,
                                           message);
}

// run_fragment: the separable passes of every term, or the cross-bilateral mode's two passes.
sss_result prewarm_fragment(PassContext& ctx, const FilterRun& run, std::string* message) {
  sss_result r = SSS_OK;
  if (run.cross_bilateral) {
    CbfProgram* horizontal = nullptr;
    CbfProgram* vertical = nullptr;
    r = cross_bilateral_resources(ctx, run, &horizontal, &vertical, message);
  } else {
    TermPrograms programs{};
    r = fragment_resources(ctx, run, &programs, message);
  }
  return r == SSS_OK ? host_stencil_resources(ctx, run, message) : r;
}

// run_masked: the stencil marked from alpha, then the fragment passes behind it.
sss_result prewarm_masked(PassContext& ctx, const FilterRun& run, std::string* message) {
  GLuint mark = 0;
  const sss_result r = stencil_mark_resources(ctx, run.color.width, run.color.height, &mark, message);
  if (r != SSS_OK) return r;
  StencilInput own;
  FilterRun inner = run;
  inner.stencil = &own;
  inner.stencil_ready = true;
  return prewarm_fragment(ctx, inner, message);
}

// run_compute (compute_runner.cpp): its two dispatches' programs (the vertical one writes the
// target's image format) and the intermediate.
sss_result prewarm_compute(PassContext& ctx, const FilterRun& run, std::string* message) {
  BlurProgram* unused = nullptr;
  sss_result r = ctx.programs.compute(blur_variant(run, 0, 0, Outside::write_centre), 0, &unused, message);
  if (r == SSS_OK) {
    const Outside outside = run.writes_back() ? Outside::discard : Outside::copy_original;
    const int format = image_format_index(run.target().internal_format);
    r = ctx.programs.compute(blur_variant(run, 0, 1, outside), format, &unused, message);
  }
  return r == SSS_OK ? ctx.targets.ensure_intermediate(run.color.width, run.color.height, message) : r;
}

// run_msaa (msaa_runner.cpp): its prepare() (the resolve, mark and per-sample write programs, the
// resolve targets and the copy of the samples), then the fragment passes on the resolved images
// (colour in the host's format, linear distance in R32F, written back through the module's
// "blurred" target) behind the host's stencil or the one marked from the resolved alpha.
sss_result prewarm_msaa(PassContext& ctx, const FilterRun& run, std::string* message) {
  const bool write_back = run.writes_back();
  ResolveProgram* resolve = nullptr;
  sss_result r = ctx.programs.msaa_resolve(run.resolve_constants.linear_depth, &resolve, message);
  SampleWriteProgram* sample_write = nullptr;
  if (r == SSS_OK && write_back) r = ctx.programs.sample_write(&sample_write, message);
  if (r != SSS_OK) return r;
  ctx.targets.ensure_msaa_framebuffers();
  const int width = run.color.width, height = run.color.height;
  r = ctx.targets.ensure_msaa_targets(run.color.internal_format, width, height, write_back, message);
  if (r == SSS_OK && write_back) r = ctx.targets.ensure_sample_copy(run.color, message);
  if (r != SSS_OK) return r;

  FilterRun inner = run;
  inner.color = TextureInfo{};
  inner.color.internal_format = run.color.internal_format;
  inner.color.width = width;
  inner.color.height = height;
  inner.depth = inner.color;
  inner.depth.internal_format = static_cast<GLint>(R32F);
  if (write_back) {
    inner.output = inner.color;
    inner.output.name = kPrewarmPlaceholder;
  }
  StencilInput own;
  if (run.stencil == nullptr) {
    GLuint mark = 0;
    r = stencil_mark_resources(ctx, width, height, &mark, message);
    inner.stencil = &own;
  } else {
    r = host_stencil_resources(ctx, run, message);
  }
  inner.stencil_ready = true;
  return r == SSS_OK ? prewarm_fragment(ctx, inner, message) : r;
}

}  // namespace

sss_result SeparableFilter::prewarm(const FilterRun& described, std::string* message) {
  PassContext ctx{*gl_, programs_, targets_, objects_, labels_, nullptr};
  FilterRun run = described;
  run.identity = false;  // what identity settings skip is prepared too: a superset costs only time here
  if (run.color.multisampled()) return prewarm_msaa(ctx, run, message);
  // The paths choose_path may take for such a frame: the one asked for where it can run, else the
  // plain fragment passes; SSS_PATH_AUTO any of them (and the timing's queries).
  const bool compute = (run.path == SSS_PATH_COMPUTE || run.path == SSS_PATH_AUTO) &&
                       *compute_unavailable(*gl_, run) == '\0';
  const bool masked = (run.path == SSS_PATH_FRAGMENT_MASKED || run.path == SSS_PATH_AUTO) && masked_available(run);
  const bool fragment = run.path == SSS_PATH_AUTO || (!compute && !masked);
  sss_result r = SSS_OK;
  if (fragment) r = prewarm_fragment(ctx, run, message);
  if (r == SSS_OK && masked) r = prewarm_masked(ctx, run, message);
  if (r == SSS_OK && compute) r = prewarm_compute(ctx, run, message);
  if (r == SSS_OK && run.path == SSS_PATH_AUTO) chooser_.prewarm();
  return r;
}

}  // namespace sss::gl
