// plan_frame: every decision of a frame, from the validated run, the context's capabilities and the
// path chosen. No GL call: the unit tests run it on the CPU (tests/unit/frame_plan_test.cpp).
#include "frame_plan.hpp"

#include <algorithm>
#include <optional>

#include "shader_constants.hpp"

namespace sss::gl {

bool Capabilities::preset_refused(const BlurVariant& v) const {
  return v.half_taps > 0 &&
         std::find(refused_presets.begin(), refused_presets.end(), preset_key(v)) != refused_presets.end();
}

int preset_key(const BlurVariant& v) { return blur_variant_index(v) * (kMaxHalfTaps + 1) + v.half_taps; }

namespace {

// ---- Variants -------------------------------------------------------------------------------

// The colour's image format for the inputs draw and the tile marks: single-sample RGBA16F or
// RGBA32F; -1 for any other colour.
int color_image_format(const FilterRun& run) {
  if (run.color.multisampled()) return -1;
  for (int i = 0; i < kPassInputsColorImageFormats; ++i) {
    if (kComputeImageFormats[i].internal_format == static_cast<GLenum>(run.color.internal_format)) return i;
  }
  return -1;
}

// That format where the context reads images and the colour is known to be complete
// (FilterRun::color_complete: image loads from an incomplete texture read 0); else -1 (the sampler).
int readable_color_image(const FilterRun& run, const Capabilities& caps) {
  return caps.image_inputs() && run.color_complete ? color_image_format(run) : -1;
}

int image_format_of(GLint internal_format) {
  for (int i = 0; i < kComputeImageFormatCount; ++i) {
    if (kComputeImageFormats[i].internal_format == static_cast<GLenum>(internal_format)) return i;
  }
  return -1;
}

// Term `term`'s pass on `axis` (0 horizontal, 1 vertical) writing `outside` where it blurs nothing:
// the switches the compute and fragment variants share.
BlurVariant common_variant(const FilterRun& run, std::size_t term, int axis, BlurOutside outside) {
  const math::PassTerm& t = run.kernel->terms[term];
  BlurVariant v;
  v.outside = outside;
  v.follow_surface = !run.follow_surface ? 0 : (t.depth_variance_mm2 > 0.0f ? 2 : 1);
  v.linear_depth = run.constants.linear_depth;
  v.jitter = run.kernel->jittered();
  v.accumulate = axis == 1 && term > 0;
  return v;
}

// The fragment variant: it reads pass_inputs.frag's texels (the depth already linear), the
// horizontal pass writes them packed, a preset tap count is a constant of the program (unless the
// driver refused that program), and the taps come through the image unit where the context has one.
BlurVariant fragment_variant(const FilterRun& run, const Capabilities& caps, std::size_t term, int axis,
                             BlurOutside outside) {
  BlurVariant v = common_variant(run, term, axis, outside);
  v.linear_depth = false;
  v.profile_ids = profile_ids_variant(run);
  v.packed_output = axis == 0;
  v.half_taps = compile_time_half_taps(static_cast<int>(run.kernel->spacing.size()));
  v.debug_view = static_cast<int>(run.debug_view);
  v.image_taps = caps.image_taps();
  if (caps.preset_refused(v)) v.half_taps = 0;
  return v;
}

bool accumulators_half(const FilterRun& run, const Capabilities& caps) { return accumulators_are_half(caps.es, run); }

// ---- Steps ----------------------------------------------------------------------------------

struct Steps {
  FramePlan& plan;
  Step& add(StepKind kind, StepRun on = StepRun::passes) {
    Step& s = plan.steps[static_cast<std::size_t>(plan.step_count++)];
    s = Step{};
    s.kind = kind;
    s.run = on;
    return s;
  }
  void begin(Rect rect, StepRun on = StepRun::passes) { add(StepKind::begin, on).rect = rect; }
  void copy_stencil(StencilOn on, StepRun run = StepRun::passes) {
    add(StepKind::copy_host_stencil, run).stencil_on = on;
  }
};

// A pass of term `term` along `axis` into `into`: a blur step or a dispatch.
Step& add_pass(Steps& steps, StepKind kind, int term, int axis, Into into, const BlurVariant& variant) {
  Step& s = steps.add(kind);
  s.term = static_cast<std::uint8_t>(term);
  s.axis = static_cast<std::uint8_t>(axis);
  s.into = into;
  s.variant = variant;
  return s;
}

// The fragment passes' terms: per term a horizontal pass into the intermediate and a vertical one
// into the running sum, the last into the target (writing back it leaves the untouched pixels
// alone, into a separate output it copies them unless `untouched_unread`).
void add_terms(Steps& steps, const FilterRun& run, const Capabilities& caps, bool untouched_unread) {
  FramePlan& plan = steps.plan;
  const BlurOutside last_outside = run.keeps_untouched() ? BlurOutside::discard : BlurOutside::copy_original;
  for (int t = 0; t < plan.terms; ++t) {
    const auto term = static_cast<std::size_t>(t);
    const bool last = t + 1 == plan.terms;
    add_pass(steps, StepKind::blur, t, 0, Into::intermediate,
             fragment_variant(run, caps, term, 0, BlurOutside::write_centre));
    const BlurOutside outside = last ? last_outside : BlurOutside::write_centre;
    BlurVariant vertical = fragment_variant(run, caps, term, 1, outside);
    // The filter multiplies by A_post; the albedo view shows it.
    if (last && (run.debug_view == 0 || run.debug_view == SSS_DEBUG_VIEW_ALBEDO)) vertical.albedo = albedo_variant(run);
    Step& v = add_pass(steps, StepKind::blur, t, 1, last ? Into::target : Into::sum, vertical);
    v.copy_untouched = last && run.debug_view == 0 && !run.keeps_untouched() && !untouched_unread;
  }
}

// The separable fragment passes on single-sample images (the host's, or the module's copy with the
// strength): the inputs draw marks the culling depth unless a stencil culls.
void plan_separable(Steps& steps, const FilterRun& run, const Capabilities& caps, bool tiles) {
  FramePlan& plan = steps.plan;
  plan.kind = PlanKind::separable;
  plan.tiles = tiles;
  plan.terms = run.debug_view != 0 ? 1 : static_cast<int>(run.kernel->terms.size());
  plan.inputs.linear_depth = run.constants.linear_depth;
  plan.inputs.profile_ids = profile_ids_variant(run);
  plan.inputs.mark_depth = run.stencil == nullptr;
  plan.inputs.color_image = readable_color_image(run, caps);
  plan.inputs.albedo = plan.colour_copy ? 0 : albedo_variant(run);  // the copy divided already
  plan.tile_mark_image = readable_color_image(run, caps);
  plan.stencil_format =
      run.stencil != nullptr ? run.stencil->texture.internal_format : static_cast<GLint>(DEPTH24_STENCIL8);
  steps.begin(Rect::draw);
  if (tiles) steps.add(StepKind::mark_tiles);
  steps.add(StepKind::draw_inputs);
  if (run.stencil != nullptr) steps.copy_stencil(StencilOn::horizontal);
  steps.add(StepKind::attach_targets);
  add_terms(steps, run, caps, false);
  steps.add(StepKind::detach);
}

void plan_cross_bilateral(Steps& steps, const FilterRun& run, bool stencil_ready) {
  FramePlan& plan = steps.plan;
  plan.kind = PlanKind::cross_bilateral;
  plan.terms = 1;
  plan.cbf_linear_depth = run.constants.linear_depth;
  plan.cbf_normals = run.normals.name != 0;
  plan.cbf_vertical_outside = run.keeps_untouched() ? BlurOutside::discard : BlurOutside::copy_original;
  plan.cbf_albedo = albedo_variant(run);
  if (!plan.msaa && run.stencil != nullptr) plan.stencil_format = run.stencil->texture.internal_format;
  steps.begin(Rect::draw);
  if (run.stencil != nullptr && !stencil_ready) steps.copy_stencil(StencilOn::horizontal);
  steps.add(StepKind::attach_targets);
  steps.add(StepKind::cross_bilateral).axis = 0;
  steps.add(StepKind::cross_bilateral).axis = 1;
  steps.add(StepKind::detach);
}

// The half-resolution path (half_resolution_passes.cpp): the inputs draw marks the culling depth with a host
// stencil too (the half-size passes need alpha's mark), and without one, where 2x2 blocks do not
// straddle tiles, every draw but the copy keeps to the masked path's bands.
void plan_half_resolution(Steps& steps, const FilterRun& run, const Capabilities& caps) {
  FramePlan& plan = steps.plan;
  plan.kind = PlanKind::half_resolution;
  plan.terms = 1;
  plan.tiles = run.stencil == nullptr && run.draw_rect[0] % 2 == 0 && run.draw_rect[1] % 2 == 0;
  plan.inputs.linear_depth = run.constants.linear_depth;
  plan.inputs.profile_ids = profile_ids_variant(run);
  plan.inputs.mark_depth = true;
  plan.inputs.color_image = readable_color_image(run, caps);
  plan.inputs.albedo = plan.colour_copy ? 0 : albedo_variant(run);
  plan.tile_mark_image = readable_color_image(run, caps);
  plan.half.profile_ids = profile_ids_variant(run);
  const BlurOutside last = run.keeps_untouched() ? BlurOutside::discard : BlurOutside::copy_original;
  plan.half_horizontal = fragment_variant(run, caps, 0, 0, BlurOutside::write_centre);
  plan.half_vertical = fragment_variant(run, caps, 0, 1, BlurOutside::write_centre);
  plan.full_vertical = fragment_variant(run, caps, 0, 1, last);
  plan.full_vertical.albedo = plan.half.albedo = albedo_variant(run);  // one mode (path_unavailable)
  // The culling depth: with a host stencil, the module's copy of it in the host's format.
  plan.stencil_format =
      run.stencil != nullptr ? run.stencil->texture.internal_format : static_cast<GLint>(DEPTH24_STENCIL8);
  steps.begin(Rect::draw);
  if (run.stencil != nullptr) steps.copy_stencil(StencilOn::pass_inputs);
  if (plan.tiles) steps.add(StepKind::mark_tiles);
  steps.add(StepKind::draw_inputs);
  steps.add(StepKind::attach_targets);
  steps.add(StepKind::half_size);
  steps.add(StepKind::full_size);
  steps.add(StepKind::detach);
}

// The compute path: per term a horizontal dispatch into the intermediate (reading each pixel's
// strength from the host stencil's mark where there is one) and a vertical one into the sum, the
// last into the target.
void plan_compute(Steps& steps, const FilterRun& run, const Capabilities& caps) {
  FramePlan& plan = steps.plan;
  plan.kind = PlanKind::compute;
  plan.terms = static_cast<int>(run.kernel->terms.size());
  if (run.stencil != nullptr) plan.stencil_format = run.stencil->texture.internal_format;
  if (run.region && !run.keeps_untouched()) {
    steps.begin(Rect::draw);
    steps.add(StepKind::copy_outside_region);
  }
  if (run.stencil != nullptr) {
    steps.begin(Rect::draw);
    steps.copy_stencil(StencilOn::intermediate);
    steps.add(StepKind::mark_compute_stencil);
  }
  const BlurOutside last_outside = run.keeps_untouched() ? BlurOutside::discard : BlurOutside::copy_original;
  const int intermediate = image_format_of(plan.intermediate_format);
  const int sum = image_format_of(static_cast<GLint>(accumulators_half(run, caps) ? RGBA16F : RGBA32F));
  for (int t = 0; t < plan.terms; ++t) {
    const auto term = static_cast<std::size_t>(t);
    const bool last = t + 1 == plan.terms;
    Step& h = add_pass(steps, StepKind::dispatch, t, 0, Into::intermediate,
                       common_variant(run, term, 0, BlurOutside::write_centre));
    h.image_format = intermediate;
    h.compute_pass = run.stencil != nullptr ? ComputePass::horizontal_marked : ComputePass::horizontal;
    BlurVariant vertical = common_variant(run, term, 1, last ? last_outside : BlurOutside::write_centre);
    if (last) vertical.albedo = albedo_variant(run);  // one mode: no per-pixel profiles here
    Step& v = add_pass(steps, StepKind::dispatch, t, 1, last ? Into::target : Into::sum, vertical);
    v.image_format = last ? image_format_of(run.target().internal_format) : sum;
    v.compute_pass = ComputePass::vertical;
  }
  steps.add(StepKind::finish_compute);
}

void plan_tile_view(Steps& steps, const FilterRun& run, const Capabilities& caps) {
  FramePlan& plan = steps.plan;
  plan.kind = PlanKind::tile_view;
  plan.tiles = true;
  plan.tile_mark_image = readable_color_image(run, caps);
  steps.begin(Rect::draw);
  steps.add(StepKind::mark_tiles);
  steps.add(StepKind::attach_targets);
  steps.add(StepKind::tile_view);
  steps.add(StepKind::detach);
}

// The MSAA path: the resolve (which also writes the passes' inputs), the stencil (the host's
// resolved by the blit, or the module's marked from the resolved alpha), the passes on the resolved
// images (`passes`: they write the blurred image where the host's colour is written back) and,
// writing back, the per-sample write. Behind its own mark the write-back reads the blurred image
// only where the passes drew, so the last pass copies nothing there; behind the host's stencil it
// reads pixels outside it too, where the copy makes the change 0.
void plan_msaa(Steps& steps, const FilterRun& run, const FilterRun& passes, const Capabilities& caps) {
  FramePlan& plan = steps.plan;
  plan.msaa = true;
  plan.resolve_linear_depth = run.resolve_constants.linear_depth;
  plan.resolve_write_back = !run.identity && run.writes_back();
  plan.resolve_albedo = msaa_albedo_variant(run);
  steps.add(StepKind::resolve_msaa, StepRun::host);
  if (run.identity) {  // into the output: the resolved colour copied
    plan.kind = PlanKind::copy;
    steps.add(StepKind::copy_colour);
    return;
  }
  plan.own_stencil = run.stencil == nullptr;
  plan.stencil_format =
      run.stencil != nullptr ? run.stencil->texture.internal_format : static_cast<GLint>(DEPTH24_STENCIL8);
  if (run.stencil != nullptr) {
    steps.copy_stencil(StencilOn::horizontal, StepRun::host);
  } else {
    steps.add(StepKind::mark_stencil, StepRun::host);
  }
  if (run.cross_bilateral) {
    plan_cross_bilateral(steps, passes, true);
  } else {
    plan.kind = PlanKind::separable;
    plan.terms = static_cast<int>(passes.kernel->terms.size());
    steps.begin(Rect::draw);
    steps.add(StepKind::attach_targets);
    add_terms(steps, passes, caps, run.writes_back() && run.stencil == nullptr);
    steps.add(StepKind::detach);
  }
  if (run.writes_back()) steps.add(StepKind::write_samples, StepRun::host);
}

}  // namespace

int profile_ids_variant(const FilterRun& run) {
  if (!run.has_profiles()) return 0;
  return run.profile_ids.internal_format == static_cast<GLint>(R16UI) ? 2 : 1;
}

int albedo_variant(const FilterRun& run) {
  if (run.albedo.name == 0) return 0;
  const int count = run.has_profiles() ? run.profile_count : 1;
  const int mode = run.texturing[0];
  for (int i = 1; i < count; ++i) {
    if (run.texturing[static_cast<std::size_t>(i)] != mode) return 3;
  }
  return mode;
}

bool may_read_color_image(const Capabilities& caps, const FilterRun& run) {
  return caps.compute && !run.identity && !run.cross_bilateral && run.strength.name == 0 &&
         color_image_format(run) >= 0;
}

const char* path_unavailable(const FilterRun& run, const Capabilities& caps, unsigned path) {
  switch (path) {
    case SSS_PATH_COMPUTE:
      if (!caps.compute) return "the context has no compute shaders (OpenGL 4.3+ desktop)";
      if (run.color.multisampled()) return "the colour is multisampled";
      if (run.cross_bilateral) return "the cross-bilateral mode runs as fragment passes";
      if (run.has_profiles()) return "per-pixel profiles (profile_texture) run on the fragment passes";
      if (image_format_of(run.target().internal_format) < 0) {
        return "the target's format has no image format (RGBA16F, RGBA32F or R11F_G11F_B10F)";
      }
      if (!run.target_complete) {
        return "the target texture may be incomplete (a mipmap GL_TEXTURE_MIN_FILTER, the default, with more "
               "levels allowed than it may have), and image stores to an incomplete texture are undefined: give it "
               "a GL_NEAREST or GL_LINEAR min filter, or set SSS_FRAME_TARGET_COMPLETE";
      }
      return "";
    case SSS_PATH_FRAGMENT_MASKED:
      if (run.color.multisampled()) return "the colour is multisampled";
      if (run.cross_bilateral) return "the cross-bilateral mode";
      if (run.stencil != nullptr) return "a host stencil (it culls already)";
      if (run.identity) return "nothing to blur";
      return "";
    case SSS_PATH_HALF_RESOLUTION:
      if (run.identity) return "nothing to blur";
      if (run.color.multisampled()) return "a multisampled colour";
      if (run.cross_bilateral) return "the cross-bilateral mode";
      if (run.kernel->terms.size() > 1) return "a kernel of several terms";
      if (profile_ids_variant(run) == 2) return "R16UI profile indices (R8UI ones run at half size)";
      if (albedo_variant(run) == 3) return "profiles of different texturing modes (the upsample takes one)";
      return "";
    default: return "";
  }
}

bool copies_colour(const FilterRun& run, unsigned path) {
  if (run.strength.name != 0) return true;
  if (albedo_variant(run) == 0 || run.identity || run.color.multisampled()) return false;  // the resolve divides
  return run.cross_bilateral || (path == SSS_PATH_COMPUTE && run.debug_view == 0);
}

FilterRun passes_run(const FilterRun& run, const PassTextures& module, const StencilInput* own, bool colour_copy) {
  FilterRun passes = run;
  if (colour_copy) {
    // The module's copy with the strength as alpha, at the intermediate's precision; written back,
    // the host's colour becomes the separate output (its rgb alone is written: R11F_G11F_B10F has
    // no alpha to keep).
    if (run.writes_back()) passes.output = run.color;
    passes.color.name = module.colour_copy;
    passes.color.internal_format = run.intermediate_format();
    passes.color_complete = true;  // one level (TargetPool)
    passes.strength = TextureInfo{};
    // Divided by the albedo, the copy is not the host's colour: a separate output's untouched
    // pixels come from the host's, and written back the passes leave them where they are.
    if (albedo_variant(run) != 0) passes.original = run.color;
  } else if (run.color.multisampled()) {
    passes.color = TextureInfo{};
    passes.color.name = module.resolved_color;
    passes.color.internal_format = run.color.internal_format;
    passes.color.width = run.color.width;
    passes.color.height = run.color.height;
    passes.depth = passes.color;
    passes.depth.name = module.resolved_distance;
    passes.depth.internal_format = static_cast<GLint>(R32F);
    if (run.writes_back()) {
      passes.output = passes.color;
      passes.output.name = module.blurred;
    }
    if (!run.identity && run.stencil == nullptr) passes.stencil = own;
    // A texturing mode: the resolve divided each sample by its A_post, the passes blur the quotient.
    // Written back, each sample's change is multiplied by its own A_post (msaa_write.frag); into an
    // output the last pass multiplies by the samples' mean A_post (mode 1 on that RGBA32F texture)
    // and copies the pixels it leaves alone from the undivided mean, as pre-scatter copies the resolve.
    if (msaa_albedo_variant(run) != 0) {
      passes.albedo = TextureInfo{};
      if (!run.writes_back()) {
        passes.albedo = passes.color;
        passes.albedo.name = module.resolved_albedo;
        passes.texturing[0] = SSS_TEXTURING_POST_SCATTER;
        passes.original = passes.color;
        passes.original.name = module.resolved_original;
      }
    }
  }
  return passes;
}

FramePlan plan_frame(const FilterRun& run, const Capabilities& caps, unsigned path) {
  FramePlan plan;
  plan_frame(run, caps, path, &plan);
  return plan;
}

void plan_frame(const FilterRun& run, const Capabilities& caps, unsigned path, FramePlan* out) {
  // Everything but the steps back to its default; a step is reset as it is added (a frame plans
  // without constructing the whole array of steps).
  FramePlan& plan = *out;
  plan.kind = PlanKind::nothing;
  plan.msaa = plan.tiles = plan.own_stencil = false;
  plan.terms = 0;
  plan.inputs = PassInputsVariant{};
  plan.tile_mark_image = -1;
  plan.half = HalfVariant{};
  plan.half_horizontal = plan.half_vertical = plan.full_vertical = BlurVariant{};
  plan.cbf_linear_depth = plan.cbf_normals = false;
  plan.cbf_albedo = 0;
  plan.cbf_vertical_outside = BlurOutside::write_centre;
  plan.resolve_linear_depth = plan.resolve_write_back = false;
  plan.resolve_albedo = 0;
  plan.stencil_format = 0;
  plan.step_count = 0;
  Steps steps{plan};
  plan.colour_copy = copies_colour(run, path);
  plan.copy = ColourCopyVariant{};
  if (plan.colour_copy) {
    plan.copy.strength_texture = run.strength.name != 0;
    plan.copy.albedo = run.identity ? 0 : albedo_variant(run);
    plan.copy.profile_ids = plan.copy.albedo == 3 ? profile_ids_variant(run) : 0;
  }
  plan.intermediate_format = run.intermediate_format();
  plan.accumulators_half = accumulators_half(run, caps);
  plan.path = SSS_PATH_FRAGMENT;
  if (run.identity && run.writes_back()) return;  // in place with nothing to blur: nothing changes
  // The passes plan on the textures they will read and write (the names do not matter here; the
  // run is copied only where they are not the host's).
  const StencilInput own;
  PassTextures placeholders;
  placeholders.colour_copy = placeholders.resolved_color = placeholders.resolved_distance = placeholders.blurred =
      placeholders.resolved_albedo = ~0u;
  placeholders.resolved_original = ~0u - 1;  // not sss_prepare's output (kPrewarmPlaceholder): never the same
  std::optional<FilterRun> view;
  if (plan.colour_copy || run.color.multisampled()) view.emplace(passes_run(run, placeholders, &own, plan.colour_copy));
  const FilterRun& passes = view ? *view : run;
  if (plan.colour_copy) steps.add(StepKind::colour_copy, StepRun::host);
  if (run.color.multisampled()) {
    plan_msaa(steps, run, passes, caps);
  } else if (run.identity) {
    plan.kind = PlanKind::copy;
    steps.add(StepKind::copy_colour);
  } else if (run.cross_bilateral) {
    plan_cross_bilateral(steps, passes, false);
  } else if (run.debug_view == SSS_DEBUG_VIEW_TILES) {
    plan_tile_view(steps, passes, caps);
  } else if (run.debug_view == 0 && path == SSS_PATH_COMPUTE) {
    plan.path = SSS_PATH_COMPUTE;
    plan_compute(steps, passes, caps);
  } else if (run.debug_view == 0 && path == SSS_PATH_HALF_RESOLUTION) {
    plan.path = SSS_PATH_HALF_RESOLUTION;
    plan_half_resolution(steps, passes, caps);
  } else {
    const bool masked = run.debug_view == 0 && path == SSS_PATH_FRAGMENT_MASKED;
    if (masked) plan.path = SSS_PATH_FRAGMENT_MASKED;
    plan_separable(steps, passes, caps, masked);
  }
}

namespace {
bool same_variant(const BlurVariant& a, const BlurVariant& b) {
  return blur_variant_index(a) == blur_variant_index(b) && a.half_taps == b.half_taps && a.image_taps == b.image_taps &&
         a.albedo == b.albedo;
}
bool same_inputs(const PassInputsVariant& a, const PassInputsVariant& b) {
  return pass_inputs_variant_index(a) == pass_inputs_variant_index(b);
}
}  // namespace

bool operator==(const Step& a, const Step& b) {
  return a.kind == b.kind && a.run == b.run && a.term == b.term && a.axis == b.axis && a.into == b.into &&
         a.rect == b.rect && a.stencil_on == b.stencil_on && a.copy_untouched == b.copy_untouched &&
         same_variant(a.variant, b.variant) && a.image_format == b.image_format && a.compute_pass == b.compute_pass;
}

bool operator==(const FramePlan& a, const FramePlan& b) {
  if (a.kind != b.kind || a.path != b.path || a.msaa != b.msaa || a.colour_copy != b.colour_copy ||
      colour_copy_variant_index(a.copy) != colour_copy_variant_index(b.copy) || a.cbf_albedo != b.cbf_albedo ||
      a.half.albedo != b.half.albedo ||
      a.terms != b.terms || a.tiles != b.tiles || a.own_stencil != b.own_stencil || !same_inputs(a.inputs, b.inputs) ||
      a.tile_mark_image != b.tile_mark_image || a.half.profile_ids != b.half.profile_ids ||
      !same_variant(a.half_horizontal, b.half_horizontal) || !same_variant(a.half_vertical, b.half_vertical) ||
      !same_variant(a.full_vertical, b.full_vertical) || a.cbf_linear_depth != b.cbf_linear_depth ||
      a.cbf_normals != b.cbf_normals || a.cbf_vertical_outside != b.cbf_vertical_outside ||
      a.resolve_linear_depth != b.resolve_linear_depth || a.resolve_write_back != b.resolve_write_back ||
      a.resolve_albedo != b.resolve_albedo ||
      a.intermediate_format != b.intermediate_format || a.accumulators_half != b.accumulators_half ||
      a.stencil_format != b.stencil_format || a.step_count != b.step_count) {
    return false;
  }
  for (int i = 0; i < a.step_count; ++i) {
    if (!(a.steps[static_cast<std::size_t>(i)] == b.steps[static_cast<std::size_t>(i)])) return false;
  }
  return true;
}

}  // namespace sss::gl
