// describe(): a frame plan as SSS_LOG_DEBUG prints it when the plan changes, one line per step,
// the variants by the names of their switches (docs/architecture.md shows the default frame's).
#include <cstdio>
#include <string>

#include "frame_plan.hpp"

namespace sss::gl {

namespace {
// Names for the log, in the order of the enums' values (frame_plan.hpp).
constexpr const char* kKindNames[] = {"nothing",         "copy",    "separable", "cross-bilateral",
                                      "half resolution", "compute", "tiles view"};
constexpr const char* kStepNames[] = {"colour copy",
                                      "resolve MSAA",
                                      "begin",
                                      "copy host stencil",
                                      "mark stencil from alpha",
                                      "mark tiles",
                                      "draw inputs",
                                      "attach targets",
                                      "blur",
                                      "half-size passes",
                                      "upsample and full-size passes",
                                      "cross-bilateral pass",
                                      "copy outside region",
                                      "mark compute stencil",
                                      "dispatch",
                                      "copy colour",
                                      "tiles view",
                                      "detach",
                                      "finish compute",
                                      "write samples"};
constexpr const char* kIntoNames[] = {"intermediate", "sum", "target"};
static_assert(sizeof kKindNames / sizeof kKindNames[0] == static_cast<std::size_t>(PlanKind::tile_view) + 1);
static_assert(sizeof kStepNames / sizeof kStepNames[0] == static_cast<std::size_t>(StepKind::write_samples) + 1);

const char* kind_name(PlanKind k) { return kKindNames[static_cast<std::size_t>(k)]; }
const char* step_name(StepKind k) { return kStepNames[static_cast<std::size_t>(k)]; }
const char* into_name(Into i) { return kIntoNames[static_cast<std::size_t>(i)]; }
}  // namespace

namespace {
constexpr const char* kAlbedoNames[] = {"", "(the albedo)", "(its square root)", "(per profile)"};
// A blur variant's switches by name (shader_variants.hpp), the ones set.
std::string switches(const BlurVariant& v, bool compute) {
  static const char* const kOutside[] = {"writes its own value outside", "discards outside",
                                         "copies the host's outside"};
  static const char* const kFollow[] = {"", ", follow-surface ramp", ", depth Gaussian"};
  std::string text = kOutside[static_cast<int>(v.outside)];
  text += kFollow[v.follow_surface];
  if (v.linear_depth) text += ", linear depth";
  if (v.jitter) text += ", jitter";
  if (v.accumulate) text += ", adds the sum";
  if (v.profile_ids != 0) text += v.profile_ids == 1 ? ", R8UI profiles" : ", R16UI profiles";
  if (v.packed_output) text += ", packed";
  if (!compute)
    text += v.half_taps > 0 ? ", " + std::to_string(2 * v.half_taps + 1) + " taps as a constant" : ", taps a uniform";
  if (v.image_taps) text += ", image taps";
  if (v.debug_view != 0) text += ", debug view " + std::to_string(v.debug_view);
  if (v.albedo != 0) text += ", times A_post " + std::string(kAlbedoNames[v.albedo]);
  return text;
}
}  // namespace

std::string describe(const FramePlan& plan) {
  char line[200];
  std::snprintf(line, sizeof line, "frame plan: %s, path %u%s%s%s, %d term(s)\n", kind_name(plan.kind), plan.path,
                plan.msaa ? ", MSAA" : "", plan.colour_copy ? ", colour copy" : "", plan.tiles ? ", tiles" : "",
                plan.terms);
  std::string text = line;
  for (int i = 0; i < plan.step_count; ++i) {
    const Step& s = plan.steps[static_cast<std::size_t>(i)];
    std::snprintf(line, sizeof line, "  %d. %s%s", i + 1, step_name(s.kind), s.run == StepRun::host ? " (host's)" : "");
    text += line;
    if (s.kind == StepKind::blur || s.kind == StepKind::dispatch) {
      std::snprintf(line, sizeof line, ": term %d %s into %s", s.term, s.axis == 0 ? "horizontal" : "vertical",
                    into_name(s.into));
      text += line;
      if (s.kind == StepKind::dispatch) text += std::string(" as ") + kComputeImageFormats[s.image_format].qualifier;
      text += " (" + switches(s.variant, s.kind == StepKind::dispatch) + ")";
      if (s.copy_untouched) text += ", then copies the untouched pixels";
    } else if (s.kind == StepKind::draw_inputs) {
      text += plan.inputs.mark_depth ? " (marks the culling depth" : " (behind the stencil";
      text += plan.inputs.color_image >= 0 ? ", colour through the image unit)" : ", colour through the sampler)";
    } else if (s.kind == StepKind::colour_copy) {
      if (plan.copy.albedo != 0) text += std::string(" over A_post ") + kAlbedoNames[plan.copy.albedo];
      if (plan.copy.strength_texture) text += ", the strength texture as alpha";
    } else if ((s.kind == StepKind::resolve_msaa || s.kind == StepKind::write_samples) && plan.resolve_albedo != 0) {
      text += std::string(s.kind == StepKind::resolve_msaa ? " (each sample over A_post " : " (each change times A_post ") +
              kAlbedoNames[plan.resolve_albedo] + ")";
    } else if (s.kind == StepKind::copy_host_stencil) {
      static const char* const kOn[] = {" onto the horizontal pass's target", " onto the inputs' target",
                                        " onto the intermediate"};
      text += kOn[static_cast<int>(s.stencil_on)];
    }
    text += "\n";
  }
  return text;
}

}  // namespace sss::gl
