// The steps a FramePlan runs (frame_plan.hpp StepKind), each drawn by the file of its concept, and
// what builds and allocates them before the first draw. SeparableFilter::run (plan_executor.cpp)
// prepares a plan (prepare_plan: every program and target it names, so that no build or allocation
// fails once a frame has drawn) and then runs its steps in order; sss_prepare prepares the plans of
// every path a frame may take (prewarm.cpp). Every step reads its decisions from the plan.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "frame_plan.hpp"
#include "pass_setup.hpp"

namespace sss::gl {

// The programs of one plan, looked up (or built) once by prepare_plan. blur[i]: the program of
// step i (a blur or dispatch step), nullptr for other steps.
struct PlanPrograms {
  std::array<BlurProgram*, kMaxPlanSteps> blur{};
  PassInputsProgram* inputs = nullptr;
  TileMarkProgram* tile_marks = nullptr;
  TileMarkProgram* tile_columns = nullptr;
  std::array<TileViewProgram*, 3> tile_view{};  // by TileSpans: the marks, the passes' and the inputs' bands
  BlurProgram* half_horizontal = nullptr;       // packed output, used at both sizes
  BlurProgram* half_vertical = nullptr;         // into half_result
  BlurProgram* full_vertical = nullptr;         // the full-size vertical pass into the target
  HalfInputsProgram* half_inputs = nullptr;
  HalfUpsampleProgram* half_upsample = nullptr;
  std::array<CbfProgram*, 2> cbf{};  // horizontal, vertical
  ResolveProgram* resolve = nullptr;
  GLuint stencil_mark = 0;
  SampleWriteProgram* sample_write = nullptr;
  ColourCopyProgram* colour_copy = nullptr;
};

// Every program and target `plan` names (host: the api layer's run; passes: passes_run's), and
// the per-pixel profiles' and half-resolution path's tables: programs first, so that a variant
// that fails to build leaves no new target behind. A program the driver refused where another
// gives the same image is recorded in the Capabilities the program cache was given
// (SSS_ERROR_SHADER_COMPILE is returned, and the caller plans again).
sss_result prepare_plan(PassContext& ctx, const FilterRun& host, const FilterRun& passes, const FramePlan& plan,
                        PlanPrograms* programs, std::string* message);

// The measurement of a frame's passes (sss_get_stats), begun by the first step that measures.
class PlanMeasurement {
 public:
  PlanMeasurement(PassQueries* queries, std::uint64_t frame) : queries_(queries), frame_(frame) {}
  FrameMeasurement& get() {
    if (!measure_) measure_.emplace(queries_, frame_);
    return *measure_;
  }

 private:
  PassQueries* queries_;
  std::uint64_t frame_;
  std::optional<FrameMeasurement> measure_;
};

// ---- colour_copy.cpp ----
// The colour's rgb with the strength texture's red as alpha, into the module's copy (over the viewport).
sss_result draw_colour_copy(PassContext& ctx, const FilterRun& host, const FramePlan& plan, const PlanPrograms& p,
                            std::string* message);

// ---- msaa_resolve.cpp ----
// The resolve of the multisampled colour and depth, with the passes' inputs (writing back, what
// the write-back needs of the translucent samples).
sss_result resolve_msaa(PassContext& ctx, const FilterRun& host, const FramePlan& plan, const PlanPrograms& p,
                        std::string* message);
// The paper's stencil culling: the module's stencil set to 1 where the resolved alpha is above 0.
sss_result mark_stencil_from_alpha(PassContext& ctx, const FilterRun& host, const PlanPrograms& p,
                                   std::string* message);
// Each pixel's change blended into the host's translucent samples.
sss_result write_samples(PassContext& ctx, const FilterRun& host, const PlanPrograms& p, std::string* message);

// ---- fragment_passes.cpp ----
// pass_inputs.frag over the drawn rectangle (every pixel of it: the taps read outside the culled
// pixels too), marking the culling depth unless a stencil culls.
sss_result draw_pass_inputs(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const PlanPrograms& p,
                            std::string* message);
// The separable passes' targets with the stencil or culling depth on each (and the output).
sss_result attach_pass_targets(PassContext& ctx, const FilterRun& run, const FramePlan& plan, std::string* message);
// One blur step (Step::term, axis, into) with its program.
void draw_blur_step(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const Step& step,
                    BlurProgram& program, PlanMeasurement& measure);
// One pass of `p` reading `source` (pass_inputs.frag's layout) with the strength on its unit: the
// uniforms, the inputs and the draw over the rectangle or its bands (the half-resolution path's
// full-size passes too).
void draw_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis);
// Nothing to blur: the colour copied into the separate output.
sss_result copy_colour(PassContext& ctx, const FilterRun& run, std::string* message);

// ---- tile_marks.cpp ----
// The masked path's tile marks (left on their units), ctx.tile_bands and tile_grid set for the
// band draws; the viewport back on the drawn rectangle.
void mark_tiles(PassContext& ctx, const FilterRun& run, const PlanPrograms& p);

// ---- tile_view.cpp ----
sss_result attach_tile_view(PassContext& ctx, const FilterRun& run, std::string* message);
void draw_tile_view(PassContext& ctx, const FilterRun& run, const PlanPrograms& p);

// ---- half_resolution_passes.cpp ----
sss_result attach_half_targets(PassContext& ctx, const FilterRun& run, std::string* message);
void draw_half_size(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, PlanMeasurement& measure);
void draw_full_size(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, PlanMeasurement& measure);
// Every profile's two pass tables for the upsample, uploaded only when the kernels changed.
sss_result upload_half_tables(PassContext& ctx, const FilterRun& run, std::string* message);

// ---- cross_bilateral_passes.cpp ----
sss_result attach_cbf_targets(PassContext& ctx, const FilterRun& run, std::string* message);
void draw_cbf_pass(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, int axis, PlanMeasurement& measure);

// ---- compute_passes.cpp ----
sss_result copy_outside_region_first(PassContext& ctx, const FilterRun& run, std::string* message);
// The host stencil's mark for the dispatches (its copy came first, on the intermediate's framebuffer).
void mark_compute_stencil(PassContext& ctx, const FilterRun& run);
void dispatch_step(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const Step& step,
                   BlurProgram& program, PlanMeasurement& measure);
void finish_compute(PassContext& ctx);

}  // namespace sss::gl
