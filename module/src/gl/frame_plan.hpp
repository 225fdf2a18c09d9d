// The frame's decisions as a value. plan_frame, a pure function (no GL call), turns what the api
// layer validated (a FilterRun), what the context can run (Capabilities) and the path chosen for
// the frame into a FramePlan: the path, every program variant, what the module allocates, and the
// ordered steps the frame draws. SeparableFilter::run executes a plan step by step
// (plan_executor.cpp); sss_prepare builds what the plans of every path a frame may take name
// (prewarm.cpp). Nothing else decides which path, step or variant a frame runs.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "../math/kernel_plan.hpp"
#include "filter_run.hpp"
#include "shader_variants.hpp"

namespace sss::gl {

// What the context can run, and what its driver refused to build (each refusal has a variant that
// gives the same image, which the planner takes from then on). Filled at create from the context;
// a refusal is added when a program fails to build (plan_resources.cpp).
struct Capabilities {
  bool es = false;           // OpenGL ES: the sum of terms in RGBA16F (unless the colour is RGBA32F)
  bool compute = false;      // compute shaders and image units (desktop GL 4.3+)
  bool image_loads = false;  // the GLSL 4.20 dialect on such a context: fragment programs may imageLoad
  // The blur programs that read their taps through the image unit (BlurVariant::image_taps).
  bool image_taps_refused = false;
  // The passes' inputs and the tile marks that read the colour through the image unit.
  bool image_inputs_refused = false;
  // Blur variants with a preset tap count as a constant that the driver refused, by
  // preset_key(): the variant reading the count as a uniform stands in for each.
  std::vector<int> refused_presets;

  bool image_taps() const { return image_loads && !image_taps_refused; }
  // How many refusals were recorded (the executor plans again when a preparation added one).
  std::size_t refusals() const {
    return (image_taps_refused ? 1u : 0u) + (image_inputs_refused ? 1u : 0u) + refused_presets.size();
  }
  bool image_inputs() const { return image_loads && !image_inputs_refused; }
  bool preset_refused(const BlurVariant& v) const;
};
// The key of a preset-count blur variant (its index and SSS_HALF_TAPS), for refused_presets.
int preset_key(const BlurVariant& v);

// What runs the frame's passes.
enum class PlanKind : std::uint8_t {
  nothing,          // in place with nothing to blur: no draw
  copy,             // nothing to blur: the colour copied into the separate output
  separable,        // the fragment passes (SSS_PATH_FRAGMENT, and _MASKED with tiles)
  cross_bilateral,  // Mikkelsen's two fragment passes
  half_resolution,  // SSS_PATH_HALF_RESOLUTION
  compute,          // SSS_PATH_COMPUTE
  tile_view,        // SSS_DEBUG_VIEW_TILES
};

enum class StepKind : std::uint8_t {
  colour_copy,           // the colour into the module's copy: over A_post (copies_colour), the strength as alpha
  resolve_msaa,          // the multisampled colour and depth resolved (with the passes' inputs)
  begin,                 // the passes' fixed-function state, vertex array and viewport (Step::rect)
  copy_host_stencil,     // the host's stencil into the module's stencil buffer, on Step::framebuffer
  mark_stencil,          // the module's stencil from the resolved alpha (MSAA without a host stencil)
  mark_tiles,            // the masked path's 16x16 tile marks, then draws over bands of tiles
  draw_inputs,           // pass_inputs.frag: colour and view distance packed, the strength, the culling depth
  attach_targets,        // the passes' framebuffers, with the stencil or the culling depth on each
  blur,                  // one fragment pass of one kernel term (Step::term, axis, into, variant)
  half_size,             // the reduction to half size and the two half-size passes
  full_size,             // the upsample, then the full-size passes where kernels are narrow
  cross_bilateral,       // one pass of the cross-bilateral mode (Step::axis)
  copy_outside_region,   // compute with a region and a separate output: the viewport's colour first
  mark_compute_stencil,  // compute with a host stencil: the colour copied where it passes
  dispatch,              // one compute pass of one kernel term
  copy_colour,           // nothing to blur: the colour into the separate output
  tile_view,             // SSS_DEBUG_VIEW_TILES's draws
  detach,                // the host's texture off the module's framebuffers (also after a failure)
  finish_compute,        // every access waits for the image stores; the image unit emptied
  write_samples,         // MSAA written back: each pixel's change into its translucent samples
};

// Which run a step reads: the api layer's (the host's textures) or the passes' (the module's copy
// of a colour with a strength texture, or the MSAA resolve's images: passes_run()).
enum class StepRun : std::uint8_t { host, passes };
// Where a blur pass or dispatch writes: the horizontal pass's target, the running sum of the
// terms, or the frame's target (the host's colour in place, or the separate output).
enum class Into : std::uint8_t { intermediate, sum, target };
// The rectangle a begin step sets as viewport.
enum class Rect : std::uint8_t { viewport, draw };
// The module's framebuffer a stencil copy goes on.
enum class StencilOn : std::uint8_t { horizontal, pass_inputs, intermediate };

struct Step {
  StepKind kind = StepKind::begin;
  StepRun run = StepRun::passes;
  std::uint8_t term = 0;
  std::uint8_t axis = 0;
  Into into = Into::intermediate;
  Rect rect = Rect::draw;
  StencilOn stencil_on = StencilOn::horizontal;
  // blur: into the target, the pixels the culling keeps from the pass are copied (separate output).
  bool copy_untouched = false;
  BlurVariant variant;                                 // blur, dispatch
  int image_format = -1;                               // dispatch: kComputeImageFormats index of what it writes
  ComputePass compute_pass = ComputePass::horizontal;  // dispatch
};

inline constexpr int kMaxPlanSteps = 10 + 2 * static_cast<int>(math::kMaxPlanTerms);

struct FramePlan {
  PlanKind kind = PlanKind::nothing;
  unsigned path = SSS_PATH_FRAGMENT;  // sss.h SSS_PATH_*, as sss_get_stats reports it
  bool msaa = false;                  // the passes run on the MSAA resolve's images
  bool colour_copy = false;           // the passes run on the module's copy of the colour (colour_copy.cpp)
  ColourCopyVariant copy;             // what that copy divides by and takes its alpha from
  int terms = 0;                      // kernel terms the passes run (a debug view: the first alone)
  bool tiles = false;                 // the masked path's tile culling (and the half path's bands)
  bool own_stencil = false;           // MSAA without a host stencil: the passes cull by the module's mark
  // The programs: the passes' inputs (draw_inputs), the tile marks' colour read (-1: sampler), the
  // half-resolution path's reduction and upsample, the cross-bilateral passes, the MSAA resolve
  // and write-back. Blur variants are on their steps.
  PassInputsVariant inputs;
  int tile_mark_image = -1;
  HalfVariant half;
  BlurVariant half_horizontal, half_vertical, full_vertical;  // the half path's three blur programs
  bool cbf_linear_depth = false, cbf_normals = false;
  int cbf_albedo = 0;  // the cross-bilateral vertical pass's SSS_ALBEDO
  BlurOutside cbf_vertical_outside = BlurOutside::write_centre;
  bool resolve_linear_depth = false, resolve_write_back = false;
  // The MSAA resolve's and write-back's SSS_ALBEDO (msaa_albedo_variant): each sample over its own
  // A_post, and its change times it.
  int resolve_albedo = 0;
  // The module's targets: the horizontal pass's format, the sum of terms in half floats, and the
  // format of the stencil or culling-depth buffer (0: none).
  GLint intermediate_format = 0;
  bool accumulators_half = false;
  GLint stencil_format = 0;
  // The steps, in the order they draw.
  std::array<Step, kMaxPlanSteps> steps{};
  int step_count = 0;
};

bool operator==(const FramePlan& a, const FramePlan& b);
inline bool operator!=(const FramePlan& a, const FramePlan& b) { return !(a == b); }

// SSS_PROFILE_IDS of a run: 0 no profile texture, 1 R8UI, 2 R16UI.
int profile_ids_variant(const FilterRun& run);
// SSS_ALBEDO of the pass that writes a run's target (module/shaders/albedo.glsl): 0 without an
// albedo texture or where every profile the frame can use is pre-scatter, 1 or 2 where they share
// post-scatter or pre- and post-scatter, 3 where their modes differ.
int albedo_variant(const FilterRun& run);
// Whether the passes of `run` on `path` read the module's copy of the colour (colour_copy.cpp)
// instead of the host's: for a strength texture, and for a texturing mode on the passes that read
// the colour themselves (compute, cross-bilateral); the fragment and half-resolution passes divide
// by the albedo in their inputs draw instead (pass_inputs.frag), which saves the copy's draw.
bool copies_colour(const FilterRun& run, unsigned path);
// Whether they may, on some path (the run the path is chosen on).
inline bool may_copy_colour(const FilterRun& run) {
  return run.strength.name != 0 || (albedo_variant(run) != 0 && !run.identity && !run.color.multisampled());
}
// SSS_ALBEDO of the MSAA resolve and write-back of `run` (multisampled): the texturing mode (1 or 2;
// per-pixel profiles take no MSAA frame) where something is blurred, else 0. The resolve divides,
// so no colour copy runs on that path.
inline int msaa_albedo_variant(const FilterRun& run) {
  return run.color.multisampled() && !run.identity ? albedo_variant(run) : 0;
}
// The sum of the kernel's terms in half floats: RGBA32F keeps up to six terms at float precision,
// but OpenGL ES may not render to it (GL_EXT_color_buffer_float), while every ES context the module
// accepts renders RGBA16F; an RGBA32F colour on ES was checked to have that extension, so its sum
// is RGBA32F.
inline bool accumulators_are_half(bool es, const FilterRun& run) {
  return es && run.color.internal_format != static_cast<GLint>(RGBA32F);
}
// Whether the passes' inputs draw could read the colour of `run` through an image unit, were it
// complete (FilterRun::color_complete): the context has image units, the frame runs the separable
// passes on a single-sample RGBA16F or RGBA32F colour of the host's. Where this is false, the api
// layer does not ask the GL whether the colour is complete.
bool may_read_color_image(const Capabilities& caps, const FilterRun& run);

// "" when `run` can take `path` (SSS_PATH_COMPUTE, _FRAGMENT_MASKED or _HALF_RESOLUTION), else why
// not (the frame then takes the fragment passes). SSS_PATH_FRAGMENT always can.
const char* path_unavailable(const FilterRun& run, const Capabilities& caps, unsigned path);

// The plan of `run` on `path` (the path the frame was asked for or SSS_PATH_AUTO chose, one that
// path_unavailable() accepts: SSS_PATH_FRAGMENT, _FRAGMENT_MASKED, _HALF_RESOLUTION or _COMPUTE).
// A multisampled colour, a debug view, the cross-bilateral mode and identity settings decide their
// own path (MSAA and the views: the fragment passes).
FramePlan plan_frame(const FilterRun& run, const Capabilities& caps, unsigned path);
// The same into `plan`, which keeps its storage (a frame plans without constructing a plan).
void plan_frame(const FilterRun& run, const Capabilities& caps, unsigned path, FramePlan* plan);

// The module's textures the passes may read instead of the host's (Targets' names of them).
struct PassTextures {
  GLuint colour_copy = 0;                                         // the colour copy (colour_copy.cpp)
  GLuint resolved_color = 0, resolved_distance = 0, blurred = 0;  // the MSAA resolve's and the passes' result
  // A texturing mode into a separate output: the resolve's undivided mean and mean A_post.
  GLuint resolved_original = 0, resolved_albedo = 0;
};
// The run the passes' steps read (StepRun::passes): `run` itself, or its textures replaced by the
// module's colour copy (written back, the host's colour then is the output) or the MSAA
// resolve's images (behind `own`, the module's stencil, where the host gave none). plan_frame plans
// the passes on this run too. `colour_copy`: the plan's (copies_colour).
FilterRun passes_run(const FilterRun& run, const PassTextures& module, const StencilInput* own, bool colour_copy);

// One line per step, for SSS_LOG_DEBUG and the tests.
std::string describe(const FramePlan& plan);

}  // namespace sss::gl
