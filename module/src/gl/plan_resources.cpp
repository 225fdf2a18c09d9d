// prepare_plan: every program and target a FramePlan names, built and allocated before its first
// draw (sss.h: once a frame has drawn, only a GL error the draws raised can fail it), and for
// sss_prepare ahead of the frame (prewarm.cpp). Programs come first, so that a variant that fails
// to build leaves no new target behind.
#include "plan_steps.hpp"

namespace sss::gl {

namespace {

// The order programs are built in, so that what a frame shares with most frames (its blur passes,
// its inputs) is asked for before a path's extras: a build that fails leaves nothing new behind
// where the frame's own variants all exist already.
enum class Phase { first, passes, inputs, tiles };

Phase phase_of(StepKind kind) {
  switch (kind) {
    case StepKind::blur:
    case StepKind::dispatch:
    case StepKind::half_size:
    case StepKind::full_size:
    case StepKind::cross_bilateral: return Phase::passes;
    case StepKind::draw_inputs: return Phase::inputs;
    case StepKind::mark_tiles: return Phase::tiles;
    default: return Phase::first;  // the strength copy, the MSAA resolve and write-back, the tiles view
  }
}

sss_result build_step(PassContext& ctx, const FramePlan& plan, int i, PlanPrograms* p, std::string* message) {
  ProgramCache& cache = ctx.programs;
  const Step& step = plan.steps[static_cast<std::size_t>(i)];
  BlurProgram** blur = &p->blur[static_cast<std::size_t>(i)];
  sss_result r = SSS_OK;
  switch (step.kind) {
    case StepKind::colour_copy: return cache.colour_copy(plan.copy, &p->colour_copy, message);
    case StepKind::resolve_msaa:
      return cache.msaa_resolve(plan.resolve_linear_depth, plan.resolve_write_back, plan.resolve_albedo, &p->resolve,
                                message);
    case StepKind::mark_stencil: return cache.stencil_mark(&p->stencil_mark, message);
    case StepKind::write_samples: return cache.sample_write(plan.resolve_albedo, &p->sample_write, message);
    case StepKind::tile_view:
      for (const TileSpans spans : {TileSpans::none, TileSpans::inputs, TileSpans::passes}) {
        if (r == SSS_OK) r = cache.tile_view(spans, &p->tile_view[static_cast<std::size_t>(spans)], message);
      }
      return r;
    case StepKind::blur: return cache.blur(step.variant, blur, message);
    case StepKind::dispatch: return cache.compute(step.variant, step.image_format, step.compute_pass, blur, message);
    case StepKind::half_size:
      r = cache.blur(plan.half_horizontal, &p->half_horizontal, message);
      return r == SSS_OK ? cache.blur(plan.half_vertical, &p->half_vertical, message) : r;
    case StepKind::full_size: return cache.blur(plan.full_vertical, &p->full_vertical, message);
    case StepKind::cross_bilateral: {
      const BlurOutside outside = step.axis == 0 ? BlurOutside::write_centre : plan.cbf_vertical_outside;
      return cache.cross_bilateral(outside, plan.cbf_linear_depth, plan.cbf_normals, step.axis == 0 ? 0 : plan.cbf_albedo,
                                   &p->cbf[step.axis], message);
    }
    case StepKind::draw_inputs:
      r = cache.pass_inputs(plan.inputs, &p->inputs, message);
      if (r == SSS_OK && plan.kind == PlanKind::half_resolution)
        r = cache.half_inputs(plan.half, &p->half_inputs, message);
      if (r == SSS_OK && plan.kind == PlanKind::half_resolution) {
        r = cache.half_upsample(plan.half, &p->half_upsample, message);
      }
      return r;
    case StepKind::mark_tiles:
      r = cache.tile_mark(false, plan.tile_mark_image, &p->tile_marks, message);
      return r == SSS_OK ? cache.tile_mark(true, -1, &p->tile_columns, message) : r;
    default: return SSS_OK;
  }
}

sss_result build_programs(PassContext& ctx, const FramePlan& plan, Phase phase, PlanPrograms* p, std::string* message) {
  sss_result r = SSS_OK;
  for (int i = 0; i < plan.step_count && r == SSS_OK; ++i) {
    if (phase_of(plan.steps[static_cast<std::size_t>(i)].kind) == phase) r = build_step(ctx, plan, i, p, message);
  }
  return r;
}

bool has_step(const FramePlan& plan, StepKind kind) {
  for (int i = 0; i < plan.step_count; ++i) {
    if (plan.steps[static_cast<std::size_t>(i)].kind == kind) return true;
  }
  return false;
}

// The targets of the passes at the frame's size, with the stencil buffer where it is the module's
// mark or culling depth (or the half-resolution path's).
sss_result allocate_pass_targets(PassContext& ctx, const FilterRun& host, const FilterRun& passes,
                                 const FramePlan& plan, std::string* message) {
  TargetPool& targets = ctx.targets;
  const int w = host.color.width, h = host.color.height;
  const auto stencil = [&] {
    return plan.stencil_format != 0 ? targets.ensure_stencil_buffer(plan.stencil_format, w, h, message) : SSS_OK;
  };
  sss_result r = SSS_OK;
  if (plan.colour_copy) r = targets.ensure_colour_copy(plan.intermediate_format, w, h, message);
  if (r == SSS_OK && plan.msaa) {
    targets.ensure_msaa_framebuffers();
    r = targets.ensure_msaa_targets(host.color.internal_format, w, h, plan.resolve_write_back, plan.resolve_albedo != 0,
                                    message);
    if (r == SSS_OK) r = stencil();
  }
  switch (plan.kind) {
    case PlanKind::separable:
      if (r == SSS_OK) r = targets.ensure_pass_targets(w, h, message);
      if (r == SSS_OK && !plan.msaa && host.stencil == nullptr) r = stencil();  // the culling depth
      if (r == SSS_OK && plan.terms > 1) r = targets.ensure_accumulators(w, h, plan.accumulators_half, message);
      break;
    case PlanKind::half_resolution:
      if (r == SSS_OK) r = targets.ensure_pass_targets(w, h, message);
      if (r == SSS_OK) r = stencil();
      if (r == SSS_OK) r = targets.ensure_half_targets(w, h, plan.intermediate_format, message);
      break;
    case PlanKind::cross_bilateral:
      if (r == SSS_OK) r = targets.ensure_intermediate(plan.intermediate_format, w, h, message);
      if (r == SSS_OK && passes.stencil != nullptr) {
        r = targets.ensure_masked_source(passes.color.internal_format, w, h, message);
      }
      break;
    case PlanKind::compute:
      if (r == SSS_OK) r = targets.ensure_intermediate(plan.intermediate_format, w, h, message);
      if (r == SSS_OK && plan.terms > 1) r = targets.ensure_accumulators(w, h, plan.accumulators_half, message);
      break;
    default: break;
  }
  return r;
}

}  // namespace

sss_result prepare_plan(PassContext& ctx, const FilterRun& host, const FilterRun& passes, const FramePlan& plan,
                        PlanPrograms* programs, std::string* message) {
  *programs = PlanPrograms{};
  // The per-pixel profiles' tables (rewritten only when sss_set_profiles changed them).
  sss_result r = host.has_profiles() && !host.identity ? ctx.profile_tables->upload(host, message) : SSS_OK;
  // What most frames share first (the passes' programs, their inputs, their targets), then what a
  // path adds (the tile marks, the half-resolution tables), and last the copy of a host's stencil:
  // a failure then leaves behind only what the next frame needs anyway.
  for (const Phase phase : {Phase::first, Phase::passes, Phase::inputs}) {
    if (r == SSS_OK) r = build_programs(ctx, plan, phase, programs, message);
  }
  if (r == SSS_OK) r = allocate_pass_targets(ctx, host, passes, plan, message);
  const bool tiles = has_step(plan, StepKind::mark_tiles);
  const int w = host.color.width, h = host.color.height;
  if (r == SSS_OK && tiles) r = build_programs(ctx, plan, Phase::tiles, programs, message);
  if (r == SSS_OK && tiles) r = ctx.targets.ensure_tile_targets(w, h, message);
  if (r == SSS_OK && plan.kind == PlanKind::half_resolution) r = upload_half_tables(ctx, passes, message);
  const bool host_stencil_copy = !plan.msaa && plan.kind != PlanKind::half_resolution && host.stencil != nullptr;
  if (r == SSS_OK && host_stencil_copy) r = ctx.targets.ensure_stencil_buffer(plan.stencil_format, w, h, message);
  return r;
}

}  // namespace sss::gl
