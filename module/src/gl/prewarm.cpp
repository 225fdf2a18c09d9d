// sss_prepare's GPU side: the programs and targets a frame will need, built and allocated before
// it, so that its run() compiles and allocates nothing (a compile or allocation in the middle of a
// game is a visible hitch). Each path asks its runner's own prepare_* function (runners.hpp), the
// very calls the runner makes before its first draw; only what a runner makes as it draws (the
// stencil mark's program and buffer, the host stencil's copy) is
// spelt out here, next to the runner it follows. The prewarm test (tests/gl/prewarm_test.cpp)
// counts the GL creations of the first frame after it: any drift shows there.
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
  sss_result r = prepare_fragment(ctx, run, message);
  // The masked path's tile marks: where it is asked for, or AUTO may take it.
  const bool masked = run.path == SSS_PATH_FRAGMENT_MASKED || run.path == SSS_PATH_AUTO;
  if (r == SSS_OK && masked && masked_available(run)) r = prepare_tile_culling(ctx, run, message);
  return r == SSS_OK ? host_stencil_resources(ctx, run, message) : r;
}

// run_compute (compute_runner.cpp): its programs and targets, and the host stencil's copy.
sss_result prewarm_compute(PassContext& ctx, const FilterRun& run, std::string* message) {
  const sss_result r = prepare_compute(ctx, run, message);
  return r == SSS_OK ? host_stencil_resources(ctx, run, message) : r;
}

}  // namespace

sss_result SeparableFilter::prewarm(const FilterRun& described, std::string* message) {
  PassContext ctx{*gl_, programs_, targets_, objects_, labels_, nullptr};
  ctx.profile_tables = &profile_tables_;
  FilterRun run = described;
  run.identity = false;  // what identity settings skip is prepared too: a superset costs only time here
  if (run.has_profiles()) {  // the tables' buffer, made and filled now
    const sss_result r = profile_tables_.upload(run, message);
    if (r != SSS_OK) return r;
  }
  if (run.strength.name != 0) {  // the passes run on the colour with the strength as alpha
    const sss_result r = prepare_strength_source(ctx, run, message);
    if (r != SSS_OK) return r;
    run = with_strength_source(run, targets_.names());
  }
  if (run.color.multisampled()) return prepare_msaa(ctx, run, message);
  // The paths choose_path may take for such a frame: the one asked for where it can run, else the
  // plain fragment passes; SSS_PATH_AUTO any of them (and the timing's queries). Whether the target
  // is complete, which the compute path needs, is each frame's to say (SSS_FRAME_TARGET_COMPLETE, or
  // the GL's answer for an undescribed frame): the compute path is prepared where it could run, and
  // the fragment passes an incomplete target takes instead with it.
  run.target_complete = true;
  const bool compute = (run.path == SSS_PATH_COMPUTE || run.path == SSS_PATH_AUTO) &&
                       *compute_unavailable(*gl_, run) == '\0';
  // The masked path is the fragment passes (run_masked) and its tile marks: every path but compute
  // alone takes the passes, and compute falls back to them.
  const bool half = (run.path == SSS_PATH_HALF_RESOLUTION || (run.path == SSS_PATH_AUTO && run.auto_half_resolution)) &&
                    *half_resolution_unavailable(run) == '\0';
  // Whether the colour is complete is each frame's to say too (FilterRun::color_complete): the
  // passes' inputs draw reads it through the image unit where it is, through the sampler where it
  // is not (or the context has no image units: the two runs then ask for the same programs).
  sss_result r = SSS_OK;
  for (const bool color_complete : {true, false}) {
    run.color_complete = color_complete;
    if (r == SSS_OK) r = prewarm_fragment(ctx, run, message);
    if (r == SSS_OK && half) r = prepare_half_resolution(ctx, run, message);  // its runner's own prepare
  }
  if (r == SSS_OK && compute) r = prewarm_compute(ctx, run, message);
  if (r == SSS_OK && run.path == SSS_PATH_AUTO) chooser_.prewarm();
  return r;
}

}  // namespace sss::gl
