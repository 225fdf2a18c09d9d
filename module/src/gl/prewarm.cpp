// sss_prepare's GPU side: the programs and targets a frame will need, built and allocated before
// it, so that its run() compiles and allocates nothing (a compile or allocation in the middle of a
// game is a visible hitch). It plans the frame on every path it may take and prepares what those
// plans name, with the very function a frame prepares its own plan with (prepare_plan), so the two
// cannot drift apart. The prewarm test (tests/gl/prewarm_test.cpp) counts the GL creations of the
// first frame after it.
#include "plan_steps.hpp"
#include "separable_filter.hpp"

namespace sss::gl {

sss_result SeparableFilter::prewarm(const FilterRun& described, std::string* message) {
  PassContext ctx{*gl_, programs_, targets_, objects_, labels_, nullptr};
  ctx.profile_tables = &profile_tables_;
  FilterRun host = described;
  host.identity = false;  // what identity settings skip is prepared too: a superset costs only time here
  // Whether the target is complete, which the compute path needs, is each frame's to say
  // (SSS_FRAME_TARGET_COMPLETE, or the GL's answer for an undescribed frame): the compute path is
  // prepared where it could run, and the fragment passes an incomplete target takes instead with it.
  host.target_complete = true;
  const StencilInput own;  // only whether there is one decides what is planned
  const Targets& t = targets_.names();
  const PassTextures module{t.colour_copy,      t.resolved_color,   t.resolved_distance,
                            t.blurred,          t.translucent_mean, t.resolved_albedo};
  // The paths such a frame may take: the one asked for where it can run, else the plain fragment
  // passes (which every path falls back to); SSS_PATH_AUTO any that can run.
  const auto may_take = [&](const FilterRun& passes, unsigned path) {
    if (host.color.multisampled()) return path == SSS_PATH_FRAGMENT;  // the resolve, then the fragment passes
    if (path == SSS_PATH_FRAGMENT) return true;
    const bool asked = host.path == path ||
                       (host.path == SSS_PATH_AUTO && (path != SSS_PATH_HALF_RESOLUTION || host.auto_half_resolution));
    return asked && *path_unavailable(passes, caps_, path) == '\0';
  };
  sss_result r = SSS_OK;
  // Whether the colour is complete is each frame's to say too (FilterRun::color_complete): the
  // passes' inputs draw reads it through the image unit where it is, through the sampler where it
  // is not (or the context has no image units: the two plans then name the same programs).
  for (const bool color_complete : {true, false}) {
    host.color_complete = color_complete;
    for (const unsigned path :
         {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED, SSS_PATH_HALF_RESOLUTION, SSS_PATH_COMPUTE}) {
      const FilterRun passes = passes_run(host, module, &own, copies_colour(host, path));
      if (r != SSS_OK || !may_take(passes, path)) continue;
      FramePlan plan;
      PlanPrograms programs;
      r = plan_and_prepare(ctx, host, passes, path, &plan, &programs, message);
    }
  }
  if (r == SSS_OK && host.path == SSS_PATH_AUTO) chooser_.prewarm();
  return r;
}

}  // namespace sss::gl
