// One frame, read top to bottom: SeparableFilter::run takes the api layer's run, chooses the path,
// plans the frame (frame_plan.hpp), builds and allocates what the plan names, and runs its steps.
#include <optional>
#include <utility>

#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "separable_filter.hpp"

namespace sss::gl {

namespace {

unsigned sss_path_of(int chooser_path) {
  switch (chooser_path) {
    case PathChooser::compute: return SSS_PATH_COMPUTE;
    case PathChooser::masked: return SSS_PATH_FRAGMENT_MASKED;
    case PathChooser::half: return SSS_PATH_HALF_RESOLUTION;
    default: return SSS_PATH_FRAGMENT;
  }
}

GLuint stencil_framebuffer(const PassContext& ctx, const FilterRun& run, StencilOn on) {
  const Targets& t = ctx.targets.names();
  switch (on) {
    case StencilOn::pass_inputs: return t.pass_inputs_framebuffer;
    case StencilOn::intermediate: return t.intermediate_framebuffer;
    default: return horizontal_framebuffer(ctx, run);
  }
}

sss_result attach_targets(PassContext& ctx, const FilterRun& run, const FramePlan& plan, std::string* message) {
  switch (plan.kind) {
    case PlanKind::half_resolution: return attach_half_targets(ctx, run, message);
    case PlanKind::cross_bilateral: return attach_cbf_targets(ctx, run, message);
    case PlanKind::tile_view: return attach_tile_view(ctx, run, message);
    default: return attach_pass_targets(ctx, run, plan, message);
  }
}

}  // namespace

PathChooser::Choice SeparableFilter::choose_path(const FilterRun& run) {
  PathChooser::Choice choice;
  if (run.debug_view != 0) return choice;  // the views are the fragment passes'
  const auto open = [&](unsigned path) { return *path_unavailable(run, caps_, path) == '\0'; };
  switch (run.path) {
    case SSS_PATH_COMPUTE: {
      // (Nothing to blur is no refusal worth a note: the frame draws at most a copy.)
      const char* refusal = run.identity ? "" : path_unavailable(run, caps_, SSS_PATH_COMPUTE);
      if (!run.identity && *refusal == '\0') choice.path = PathChooser::compute;
      note_refusal(&compute_refusal_, "SSS_PATH_COMPUTE", refusal);
      break;
    }
    case SSS_PATH_FRAGMENT_MASKED:
      if (open(SSS_PATH_FRAGMENT_MASKED)) choice.path = PathChooser::masked;
      break;
    case SSS_PATH_HALF_RESOLUTION: {
      const char* refusal = path_unavailable(run, caps_, SSS_PATH_HALF_RESOLUTION);
      if (*refusal == '\0') choice.path = PathChooser::half;
      note_refusal(&half_refusal_, "SSS_PATH_HALF_RESOLUTION", refusal);
      break;
    }
    case SSS_PATH_AUTO: {
      const bool compute = !run.identity && open(SSS_PATH_COMPUTE);
      const bool half = run.auto_half_resolution && open(SSS_PATH_HALF_RESOLUTION);
      const unsigned available = (compute ? 1u << PathChooser::compute : 0u) |
                                 (open(SSS_PATH_FRAGMENT_MASKED) ? 1u << PathChooser::masked : 0u) |
                                 (half ? 1u << PathChooser::half : 0u);
      if (available != 0) {
        choice = chooser_.choose(run.path_key, available, run.region);
        if (*chooser_.decision() != '\0' && log_) {
          log_(SSS_LOG_INFO, std::string("SSS_PATH_AUTO chose the ") + chooser_.decision());
        }
      }
      break;
    }
    default: break;
  }
  return choice;
}

sss_result SeparableFilter::plan_and_prepare(PassContext& ctx, const FilterRun& host, const FilterRun& passes,
                                             unsigned path, FramePlan* plan, PlanPrograms* programs,
                                             std::string* message) {
  // A program the driver refuses where another gives the same image becomes a capability the next
  // plan reads: plan again, until a plan builds or a refusal has no stand-in.
  for (;;) {
    plan_frame(host, caps_, path, plan);
    const std::size_t refusals = caps_.refusals();
    const sss_result r = prepare_plan(ctx, host, passes, *plan, programs, message);
    if (r == SSS_OK || caps_.refusals() == refusals) return r;
  }
}

sss_result SeparableFilter::plan(PassContext& ctx, const FilterRun& host, const FilterRun& passes, unsigned path,
                                 PlanPrograms* programs, std::string* message) {
  // A steady frame (the last successful one's textures, description and settings:
  // api/steady_frame.hpp) on the same path over the same rectangle has that frame's plan; it is only
  // prepared (lookups that find everything built and allocated).
  const bool same_plan = !host.verify && plan_cached_ && path == plan_key_.path &&
                         host.draw_rect == plan_key_.draw_rect && caps_.refusals() == plan_key_.refusals;
  sss_result r = SSS_OK;
  if (same_plan) {
    r = prepare_plan(ctx, host, passes, last_plan_, programs, message);
  } else {
    r = plan_and_prepare(ctx, host, passes, path, &next_plan_, programs, message);
    if (r == SSS_OK && next_plan_ != last_plan_) {
      std::swap(last_plan_, next_plan_);
      if (log_) log_(SSS_LOG_DEBUG, describe(last_plan_));
    }
  }
  plan_cached_ = r == SSS_OK;
  plan_key_ = PlanKey{path, host.draw_rect, caps_.refusals()};
  return r;
}

// One frame, top to bottom.
sss_result SeparableFilter::run(const FilterRun& host, std::string* message) {
  PassContext ctx{*gl_, programs_, targets_, objects_, labels_, measure_ ? &queries_ : nullptr};
  ctx.check_framebuffers = host.verify;
  ctx.profile_tables = &profile_tables_;

  // 1. What the passes read: the host's textures, or (a copy of the run, only then) the module's
  // copy with the strength texture as alpha, or the MSAA resolve's images behind the module's own
  // stencil mark (the module's names taken again once the plan's targets are allocated: a new size
  // reallocates them).
  StencilInput own_mark;
  own_mark.ref = 1;
  own_mark.mask = 1;
  const bool substituted = may_copy_colour(host) || host.color.multisampled();
  const auto module_textures = [this] {
    const Targets& t = targets_.names();
    return PassTextures{t.colour_copy, t.resolved_color, t.resolved_distance, t.blurred, t.translucent_mean,
                        t.resolved_albedo};
  };
  std::optional<FilterRun> view;
  if (substituted) view.emplace(passes_run(host, module_textures(), &own_mark, may_copy_colour(host)));
  const FilterRun& passes = substituted ? *view : host;

  // 2. The path (an MSAA frame resolves, then runs the fragment passes) and the plan, with every
  // program and target it needs built and allocated before the first draw.
  const bool msaa = host.color.multisampled();
  const PathChooser::Choice choice = msaa ? PathChooser::Choice{} : choose_path(passes);
  PlanPrograms p;
  sss_result r = plan(ctx, host, passes, sss_path_of(choice.path), &p, message);
  if (r != SSS_OK) return r;
  const FramePlan& plan = last_plan_;
  if (substituted) *view = passes_run(host, module_textures(), &own_mark, plan.colour_copy);
  // A steady frame's framebuffers are the last run's only if it took the same path (SSS_PATH_AUTO
  // tries each in turn).
  if (!msaa) ctx.check_framebuffers = host.verify || plan.path != last_path_;

  // 3. The steps, in order. After a failure only a detach step runs (no host texture stays attached
  // to the module's framebuffers), and the error is returned.
  if (!msaa) chooser_.begin(choice);
  PlanMeasurement measure(ctx.queries, host.frame);
  for (int i = 0; i < plan.step_count; ++i) {
    const Step& step = plan.steps[static_cast<std::size_t>(i)];
    if (r != SSS_OK && step.kind != StepKind::detach) continue;
    const FilterRun& run = step.run == StepRun::host ? host : passes;
    BlurProgram* program = p.blur[static_cast<std::size_t>(i)];
    switch (step.kind) {
      case StepKind::colour_copy: r = draw_colour_copy(ctx, run, plan, p, message); break;
      case StepKind::resolve_msaa: r = resolve_msaa(ctx, run, plan, p, message); break;
      case StepKind::begin: begin_passes(ctx, step.rect == Rect::viewport ? run.viewport : run.draw_rect); break;
      case StepKind::copy_host_stencil:
        r = copy_stencil(ctx, run, *run.stencil, message, stencil_framebuffer(ctx, run, step.stencil_on));
        break;
      case StepKind::mark_stencil: r = mark_stencil_from_alpha(ctx, run, p, message); break;
      case StepKind::mark_tiles: mark_tiles(ctx, run, p); break;
      case StepKind::draw_inputs: r = draw_pass_inputs(ctx, run, plan, p, message); break;
      case StepKind::attach_targets: r = attach_targets(ctx, run, plan, message); break;
      case StepKind::blur: draw_blur_step(ctx, run, plan, step, *program, measure); break;
      case StepKind::half_size: draw_half_size(ctx, run, p, measure); break;
      case StepKind::full_size: draw_full_size(ctx, run, p, measure); break;
      case StepKind::cross_bilateral: draw_cbf_pass(ctx, run, p, step.axis, measure); break;
      case StepKind::copy_outside_region: r = copy_outside_region_first(ctx, run, message); break;
      case StepKind::mark_compute_stencil: mark_compute_stencil(ctx, run); break;
      case StepKind::dispatch: dispatch_step(ctx, run, plan, step, *program, measure); break;
      case StepKind::copy_colour: r = copy_colour(ctx, run, message); break;
      case StepKind::tile_view: draw_tile_view(ctx, run, p); break;
      case StepKind::detach:
        ctx.tile_bands = 0;
        detach_output(ctx);
        break;
      case StepKind::finish_compute: finish_compute(ctx); break;
      case StepKind::write_samples: r = write_samples(ctx, run, p, message); break;
    }
  }
  if (!msaa) chooser_.end();
  last_draws_ = ctx.draws;
  if (r == SSS_OK) {
    reported_path_ = plan.path;
    if (!msaa) last_path_ = plan.path;
  }
  return r;
}

}  // namespace sss::gl
