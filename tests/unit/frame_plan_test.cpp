// The frame plan on the CPU (module/src/gl/frame_plan.hpp, no GL): for every path, mode, kernel of
// one or several terms, per-pixel profiles, MSAA layout and debug view, the steps a frame runs in
// order and the variants each step names. The GL suites check what the steps draw; this checks the
// decisions, one place, without a context.
#include "gl/frame_plan.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "math/footprint_kernel.hpp"

namespace {

using namespace sss::gl;

// A kernel of `terms` terms at `taps` taps (spacing: taps / 2 a side), the last term's depth
// variance `variance` (0: the follow-surface ramp).
sss::math::PassKernel kernel_of(int terms, int taps = 17, float variance = 0.0f, bool jitter = false) {
  sss::math::PassKernel k;
  k.terms.resize(static_cast<std::size_t>(terms));
  k.terms.back().depth_variance_mm2 = variance;
  k.spacing.assign(static_cast<std::size_t>(taps / 2), 1.0f);
  k.jitter_from = jitter ? 3 : sss::math::kNoJitter;
  return k;
}

TextureInfo texture(GLuint name, GLenum format, int samples = 0) {
  TextureInfo t;
  t.name = name;
  t.internal_format = static_cast<GLint>(format);
  t.width = 640;
  t.height = 360;
  if (samples > 0) {
    t.target = TEXTURE_2D_MULTISAMPLE;
    t.samples = samples;
  }
  return t;
}

// A frame as the api layer fills it: RGBA16F colour written back, hardware depth, the default kernel.
struct Frame {
  sss::math::PassKernel kernel = kernel_of(1);
  StencilInput stencil;
  FilterRun run;
  Frame() {
    run.color = texture(1, RGBA16F);
    run.depth = texture(2, DEPTH_COMPONENT32F);
    run.viewport = run.draw_rect = {0, 0, 640, 360};
    run.kernel = &kernel;
    run.follow_surface = true;
    run.target_complete = true;
    run.color_complete = true;
  }
  Frame(const Frame&) = delete;
  void with_stencil() {
    stencil.texture = texture(3, DEPTH24_STENCIL8, run.color.samples);
    stencil.ref = 1;
    stencil.mask = 0xFF;
    run.stencil = &stencil;
  }
};

// Desktop GL 4.3+ with the GLSL 4.20 dialect: compute shaders and image loads.
Capabilities desktop() {
  Capabilities c;
  c.compute = true;
  c.image_loads = true;
  return c;
}
Capabilities gl33() { return Capabilities{}; }
Capabilities es30() {
  Capabilities c;
  c.es = true;
  return c;
}

std::vector<StepKind> kinds(const FramePlan& p) {
  std::vector<StepKind> k;
  for (int i = 0; i < p.step_count; ++i) k.push_back(p.steps[static_cast<std::size_t>(i)].kind);
  return k;
}

const Step* find(const FramePlan& p, StepKind kind, int term = 0, int axis = 0) {
  for (int i = 0; i < p.step_count; ++i) {
    const Step& s = p.steps[static_cast<std::size_t>(i)];
    if (s.kind == kind && s.term == term && s.axis == axis) return &s;
  }
  return nullptr;
}

using K = StepKind;

// The plan's steps are `expected`, in order (the plan printed where they are not).
void expect_steps(const FramePlan& p, const std::vector<K>& expected) { EXPECT_EQ(kinds(p), expected) << describe(p); }

TEST(FramePlan, TheDefaultFrameIsTheSeparablePassesInOrder) {
  Frame f;
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_EQ(p.kind, PlanKind::separable);
  EXPECT_EQ(p.path, static_cast<unsigned>(SSS_PATH_FRAGMENT));
  expect_steps(p, {K::begin, K::draw_inputs, K::attach_targets, K::blur, K::blur, K::detach});
  const Step& h = *find(p, K::blur, 0, 0);
  const Step& v = *find(p, K::blur, 0, 1);
  EXPECT_EQ(h.into, Into::intermediate);
  EXPECT_TRUE(h.variant.packed_output);
  EXPECT_EQ(h.variant.outside, BlurOutside::write_centre);
  EXPECT_EQ(v.into, Into::target);
  EXPECT_FALSE(v.variant.packed_output);
  EXPECT_EQ(v.variant.outside, BlurOutside::discard);  // written back: the untouched pixels are left alone
  EXPECT_FALSE(v.copy_untouched);
  for (const Step* s : {&h, &v}) {
    EXPECT_EQ(s->variant.half_taps, 8);  // the preset 17 taps as a constant
    EXPECT_TRUE(s->variant.image_taps);
    EXPECT_EQ(s->variant.follow_surface, 1);
    EXPECT_FALSE(s->variant.linear_depth);  // the inputs draw linearised
  }
  EXPECT_TRUE(p.inputs.mark_depth);
  EXPECT_EQ(p.inputs.color_image, 0);  // RGBA16F, complete: through the image unit
  EXPECT_EQ(p.stencil_format, static_cast<GLint>(DEPTH24_STENCIL8));
  EXPECT_EQ(p.intermediate_format, static_cast<GLint>(RGBA16F));
}

TEST(FramePlan, AContextWithoutImageLoadsOrARefusalReadsThroughSamplers) {
  Frame f;
  for (const bool refused : {false, true}) {
    Capabilities caps = refused ? desktop() : gl33();
    caps.image_taps_refused = refused;
    caps.image_inputs_refused = refused;
    const FramePlan p = plan_frame(f.run, caps, SSS_PATH_FRAGMENT);
    EXPECT_FALSE(find(p, K::blur)->variant.image_taps);
    EXPECT_EQ(p.inputs.color_image, -1);
  }
  // A colour the GL did not call complete is read through the sampler too (image loads would read 0).
  f.run.color_complete = false;
  EXPECT_EQ(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT).inputs.color_image, -1);
}

TEST(FramePlan, ARefusedPresetTapCountReadsTheCountAsAUniform) {
  Frame f;
  Capabilities caps = desktop();
  const FramePlan before = plan_frame(f.run, caps, SSS_PATH_FRAGMENT);
  caps.refused_presets.push_back(preset_key(find(before, K::blur, 0, 1)->variant));
  const FramePlan after = plan_frame(f.run, caps, SSS_PATH_FRAGMENT);
  EXPECT_EQ(find(after, K::blur, 0, 0)->variant.half_taps, 8);  // the horizontal pass's was not refused
  EXPECT_EQ(find(after, K::blur, 0, 1)->variant.half_taps, 0);
  EXPECT_NE(before, after);
  // A count that is no preset is a uniform from the start.
  f.kernel = kernel_of(1, 21);
  EXPECT_EQ(find(plan_frame(f.run, caps, SSS_PATH_FRAGMENT), K::blur)->variant.half_taps, 0);
}

TEST(FramePlan, ASeparateOutputCopiesTheUntouchedPixels) {
  Frame f;
  f.run.output = texture(4, RGBA32F);
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  const Step& v = *find(p, K::blur, 0, 1);
  EXPECT_EQ(v.variant.outside, BlurOutside::copy_original);
  EXPECT_TRUE(v.copy_untouched);
}

TEST(FramePlan, SeveralTermsSumIntoTheAccumulatorsAndTheLastWritesTheTarget) {
  Frame f;
  f.kernel = kernel_of(3, 17, 0.5f);
  for (const bool es : {false, true}) {
    const FramePlan p = plan_frame(f.run, es ? es30() : desktop(), SSS_PATH_FRAGMENT);
    EXPECT_EQ(p.terms, 3);
    expect_steps(p, {K::begin, K::draw_inputs, K::attach_targets, K::blur, K::blur, K::blur, K::blur, K::blur, K::blur,
                     K::detach});
    for (int t = 0; t < 3; ++t) {
      const Step& v = *find(p, K::blur, t, 1);
      EXPECT_EQ(v.into, t < 2 ? Into::sum : Into::target);
      EXPECT_EQ(v.variant.accumulate, t > 0);
      EXPECT_EQ(v.variant.outside, t < 2 ? BlurOutside::write_centre : BlurOutside::discard);
      EXPECT_EQ(v.variant.follow_surface, t < 2 ? 1 : 2);  // the last term's depth Gaussian
    }
    EXPECT_EQ(p.accumulators_half, es);  // RGBA16F colour: ES sums in half floats
  }
}

TEST(FramePlan, TheMaskedPathMarksTilesFirst) {
  Frame f;
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT_MASKED);
  EXPECT_EQ(p.path, static_cast<unsigned>(SSS_PATH_FRAGMENT_MASKED));
  EXPECT_TRUE(p.tiles);
  expect_steps(p, {K::begin, K::mark_tiles, K::draw_inputs, K::attach_targets, K::blur, K::blur, K::detach});
  EXPECT_EQ(p.tile_mark_image, 0);
}

TEST(FramePlan, AHostStencilIsCopiedAndCullsInsteadOfTheDepthMarks) {
  Frame f;
  f.with_stencil();
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  expect_steps(p, {K::begin, K::draw_inputs, K::copy_host_stencil, K::attach_targets, K::blur, K::blur, K::detach});
  EXPECT_EQ(find(p, K::copy_host_stencil)->stencil_on, StencilOn::horizontal);
  EXPECT_FALSE(p.inputs.mark_depth);
  EXPECT_EQ(p.stencil_format, static_cast<GLint>(DEPTH24_STENCIL8));
  EXPECT_STRNE(path_unavailable(f.run, desktop(), SSS_PATH_FRAGMENT_MASKED), "");
}

TEST(FramePlan, TheHalfResolutionPath) {
  Frame f;
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_HALF_RESOLUTION);
  EXPECT_EQ(p.kind, PlanKind::half_resolution);
  expect_steps(p, {K::begin, K::mark_tiles, K::draw_inputs, K::attach_targets, K::half_size, K::full_size, K::detach});
  EXPECT_TRUE(p.inputs.mark_depth);
  EXPECT_TRUE(p.half_horizontal.packed_output);
  EXPECT_EQ(p.half_vertical.outside, BlurOutside::write_centre);
  EXPECT_EQ(p.full_vertical.outside, BlurOutside::discard);
  // A rectangle on odd coordinates puts 2x2 blocks across tiles: no bands. A host stencil: its copy
  // on the inputs' framebuffer, and the inputs still mark alpha (the half-size passes need it).
  f.run.draw_rect = {1, 0, 600, 360};
  EXPECT_FALSE(plan_frame(f.run, desktop(), SSS_PATH_HALF_RESOLUTION).tiles);
  f.run.draw_rect = {0, 0, 640, 360};
  f.with_stencil();
  const FramePlan s = plan_frame(f.run, desktop(), SSS_PATH_HALF_RESOLUTION);
  expect_steps(
      s, {K::begin, K::copy_host_stencil, K::draw_inputs, K::attach_targets, K::half_size, K::full_size, K::detach});
  EXPECT_EQ(find(s, K::copy_host_stencil)->stencil_on, StencilOn::pass_inputs);
  EXPECT_TRUE(s.inputs.mark_depth);
}

TEST(FramePlan, TheComputePath) {
  Frame f;
  f.kernel = kernel_of(2);
  f.run.output = texture(4, RGBA32F);
  f.run.region = true;
  f.with_stencil();
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_COMPUTE);
  EXPECT_EQ(p.path, static_cast<unsigned>(SSS_PATH_COMPUTE));
  expect_steps(p, {K::begin, K::copy_outside_region, K::begin, K::copy_host_stencil, K::mark_compute_stencil,
                   K::dispatch, K::dispatch, K::dispatch, K::dispatch, K::finish_compute});
  EXPECT_EQ(find(p, K::copy_host_stencil)->stencil_on, StencilOn::intermediate);
  const Step& h = *find(p, K::dispatch, 0, 0);
  EXPECT_EQ(h.compute_pass, ComputePass::horizontal_marked);
  EXPECT_EQ(h.image_format, 0);                            // the RGBA16F intermediate
  EXPECT_EQ(find(p, K::dispatch, 0, 1)->image_format, 1);  // the RGBA32F sum
  EXPECT_EQ(find(p, K::dispatch, 1, 1)->image_format, 1);  // the RGBA32F output
  EXPECT_EQ(find(p, K::dispatch, 1, 1)->variant.outside, BlurOutside::copy_original);
  EXPECT_FALSE(h.variant.packed_output);
}

TEST(FramePlan, WhyAPathCannotRun) {
  Frame f;
  EXPECT_STREQ(path_unavailable(f.run, desktop(), SSS_PATH_COMPUTE), "");
  EXPECT_STRNE(path_unavailable(f.run, gl33(), SSS_PATH_COMPUTE), "");
  f.run.target_complete = false;
  EXPECT_NE(std::string(path_unavailable(f.run, desktop(), SSS_PATH_COMPUTE)).find("incomplete"), std::string::npos);
  f.run.target_complete = true;
  f.kernel = kernel_of(2);
  EXPECT_STREQ(path_unavailable(f.run, desktop(), SSS_PATH_HALF_RESOLUTION), "a kernel of several terms");
  f.kernel = kernel_of(1);
  f.run.profile_ids = texture(5, R16UI);
  EXPECT_NE(std::string(path_unavailable(f.run, desktop(), SSS_PATH_HALF_RESOLUTION)).find("R16UI"), std::string::npos);
  EXPECT_NE(std::string(path_unavailable(f.run, desktop(), SSS_PATH_COMPUTE)).find("profiles"), std::string::npos);
  f.run.profile_ids = texture(5, R8UI);
  EXPECT_STREQ(path_unavailable(f.run, desktop(), SSS_PATH_HALF_RESOLUTION), "");
  EXPECT_STREQ(path_unavailable(f.run, desktop(), SSS_PATH_FRAGMENT), "");
}

TEST(FramePlan, PerPixelProfilesSelectTheirVariants) {
  Frame f;
  for (const GLenum format : {R8UI, R16UI}) {
    f.run.profile_ids = texture(5, format);
    f.run.profile_count = 2;
    const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
    const int ids = format == R8UI ? 1 : 2;
    EXPECT_EQ(p.inputs.profile_ids, ids);
    EXPECT_EQ(find(p, K::blur, 0, 0)->variant.profile_ids, ids);
    EXPECT_EQ(find(p, K::blur, 0, 1)->variant.profile_ids, ids);
  }
}

TEST(FramePlan, TheCrossBilateralMode) {
  Frame f;
  f.run.cross_bilateral = true;
  f.run.normals = texture(6, RGBA16F);
  f.with_stencil();
  // The compute path asked for: the cross-bilateral mode runs as fragment passes.
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_EQ(p.kind, PlanKind::cross_bilateral);
  EXPECT_STRNE(path_unavailable(f.run, desktop(), SSS_PATH_COMPUTE), "");
  expect_steps(p,
               {K::begin, K::copy_host_stencil, K::attach_targets, K::cross_bilateral, K::cross_bilateral, K::detach});
  EXPECT_TRUE(p.cbf_normals);
  EXPECT_EQ(p.cbf_vertical_outside, BlurOutside::discard);
}

TEST(FramePlan, NothingToBlur) {
  Frame f;
  f.run.identity = true;
  const FramePlan in_place = plan_frame(f.run, desktop(), SSS_PATH_COMPUTE);
  EXPECT_EQ(in_place.kind, PlanKind::nothing);
  EXPECT_EQ(in_place.step_count, 0);
  f.run.output = texture(4, RGBA16F);
  const FramePlan copy = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_EQ(kinds(copy), (std::vector<K>{K::copy_colour}));
  // With a strength texture, the copy is of the colour with the strength.
  f.run.strength = texture(7, R8);
  EXPECT_EQ(kinds(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT)),
            (std::vector<K>{K::colour_copy, K::copy_colour}));
}

TEST(FramePlan, AStrengthTextureRunsThePassesOnTheModulesCopy) {
  Frame f;
  f.run.color = texture(1, R11F_G11F_B10F);
  f.run.strength = texture(7, R8);
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_TRUE(p.colour_copy);
  EXPECT_EQ(p.steps[0].kind, K::colour_copy);
  EXPECT_EQ(p.steps[0].run, StepRun::host);
  // Written back, the host's colour is the passes' separate output: its rgb alone is written, and
  // the untouched pixels copied (the copy holds them exactly).
  const Step& v = *find(p, K::blur, 0, 1);
  EXPECT_EQ(v.variant.outside, BlurOutside::copy_original);
  EXPECT_TRUE(v.copy_untouched);
  EXPECT_EQ(p.inputs.color_image, 0);  // the module's RGBA16F copy is complete
  PassTextures module;
  module.colour_copy = 40;
  const FilterRun passes = passes_run(f.run, module, nullptr, p.colour_copy);
  EXPECT_EQ(passes.color.name, 40u);
  EXPECT_EQ(passes.color.internal_format, static_cast<GLint>(RGBA16F));
  EXPECT_EQ(passes.output.name, 1u);
  EXPECT_EQ(passes.strength.name, 0u);
}

// A texturing mode (sss.h sss_texturing): the fragment and half-resolution passes divide by the
// albedo in their inputs draw, the compute and cross-bilateral passes read the colour copy, which
// divides; the pass that writes the target multiplies back; pre-scatter plans as without an albedo.
TEST(FramePlan, ATexturingModeDividesWhereThePassesReadTheColour) {
  Frame f;
  f.run.albedo = texture(9, RGBA8);
  const FramePlan pre = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  f.run.albedo = TextureInfo{};
  EXPECT_TRUE(pre == plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT));  // pre-scatter: the albedo unread
  f.run.albedo = texture(9, RGBA8);
  f.run.texturing[0] = SSS_TEXTURING_POST_SCATTER;
  for (const unsigned path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED, SSS_PATH_HALF_RESOLUTION}) {
    SCOPED_TRACE(path);
    const FramePlan p = plan_frame(f.run, desktop(), path);
    EXPECT_FALSE(p.colour_copy);
    EXPECT_EQ(p.inputs.albedo, 1);
    if (path == SSS_PATH_HALF_RESOLUTION) {
      EXPECT_EQ(p.half.albedo, 1);
      EXPECT_EQ(p.full_vertical.albedo, 1);
    } else {
      EXPECT_EQ(find(p, K::blur, 0, 1)->variant.albedo, 1);
      EXPECT_EQ(find(p, K::blur, 0, 0)->variant.albedo, 0);
    }
  }
  const FramePlan compute = plan_frame(f.run, desktop(), SSS_PATH_COMPUTE);
  EXPECT_TRUE(compute.colour_copy);
  EXPECT_EQ(compute.copy.albedo, 1);
  EXPECT_EQ(compute.steps[0].kind, K::colour_copy);
  f.run.texturing[0] = SSS_TEXTURING_PRE_AND_POST_SCATTER;
  f.run.cross_bilateral = true;
  const FramePlan cbf = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_TRUE(cbf.colour_copy);
  EXPECT_EQ(cbf.copy.albedo, 2);
  EXPECT_EQ(cbf.cbf_albedo, 2);
  // Written back, the passes leave the pixels they do not blur where they are (never the copy).
  PassTextures module;
  module.colour_copy = 40;
  const FilterRun passes = passes_run(f.run, module, nullptr, true);
  EXPECT_TRUE(passes.keeps_untouched());
  EXPECT_EQ(cbf.cbf_vertical_outside, BlurOutside::discard);
  // Nothing to blur: no copy, no division.
  f.run.identity = true;
  f.run.output = texture(4, RGBA16F);
  EXPECT_FALSE(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT).colour_copy);
}

TEST(FramePlan, TheMsaaPathResolvesMarksBlursAndWritesBack) {
  Frame f;
  f.run.color = texture(1, RGBA16F, 4);
  f.run.depth = texture(2, DEPTH_COMPONENT32F, 4);
  f.kernel = kernel_of(2);
  // The path asked for does not matter: the resolve, then the fragment passes.
  const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_COMPUTE);
  EXPECT_TRUE(p.msaa);
  EXPECT_TRUE(p.own_stencil);
  EXPECT_EQ(p.path, static_cast<unsigned>(SSS_PATH_FRAGMENT));
  expect_steps(p, {K::resolve_msaa, K::mark_stencil, K::begin, K::attach_targets, K::blur, K::blur, K::blur, K::blur,
                   K::detach, K::write_samples});
  EXPECT_TRUE(p.resolve_write_back);
  EXPECT_EQ(p.steps[0].run, StepRun::host);
  EXPECT_EQ(p.steps[p.step_count - 1].run, StepRun::host);
  // The passes write the blurred image, never the host's samples; behind the module's own mark the
  // write-back never reads what they leave, so nothing is copied.
  const Step& last = *find(p, K::blur, 1, 1);
  EXPECT_EQ(last.variant.outside, BlurOutside::copy_original);
  EXPECT_FALSE(last.copy_untouched);
  // Behind the host's stencil the write-back reads outside it too: copied there.
  f.with_stencil();
  const FramePlan s = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_EQ(s.steps[1].kind, K::copy_host_stencil);
  EXPECT_TRUE(find(s, K::blur, 1, 1)->copy_untouched);
  // Nothing to blur into a separate output: the resolved colour copied.
  f.run.identity = true;
  f.run.output = texture(4, RGBA16F);
  EXPECT_EQ(kinds(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT)), (std::vector<K>{K::resolve_msaa, K::copy_colour}));
}

// A texturing mode on the MSAA path: the resolve divides each sample by its A_post and the
// write-back multiplies each sample's change by it (resolve_albedo), so there is no colour copy
// and, written back, the passes multiply by nothing; into a separate output the last pass
// multiplies by the resolve's mean A_post (mode 1 on that texture) and copies the pixels it leaves
// alone from the resolve's undivided mean; the same steps as pre-scatter either way.
TEST(FramePlan, AnMsaaTexturingModeDividesInTheResolveAndMultipliesInTheWriteBack) {
  Frame f;
  f.run.color = texture(1, RGBA16F, 4);
  f.run.depth = texture(2, DEPTH_COMPONENT32F, 4);
  const FramePlan pre = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  f.run.albedo = texture(9, RGBA16F, 4);
  f.run.texturing[0] = SSS_TEXTURING_PRE_AND_POST_SCATTER;
  for (const bool cross_bilateral : {false, true}) {
    SCOPED_TRACE(cross_bilateral ? "cross-bilateral" : "separable");
    f.run.cross_bilateral = cross_bilateral;
    f.run.output = TextureInfo{};
    const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
    EXPECT_EQ(p.resolve_albedo, 2);
    EXPECT_FALSE(p.colour_copy);
    EXPECT_FALSE(may_copy_colour(f.run));
    if (!cross_bilateral) {
      EXPECT_EQ(kinds(p), kinds(pre));
      EXPECT_EQ(find(p, K::blur, 0, 1)->variant.albedo, 0);
    } else {
      EXPECT_EQ(p.cbf_albedo, 0);
    }
    PassTextures module;
    module.resolved_color = 30;
    module.resolved_original = 31;
    module.resolved_albedo = 32;
    const FilterRun in_place = passes_run(f.run, module, nullptr, false);
    EXPECT_EQ(in_place.albedo.name, 0u);
    EXPECT_EQ(in_place.original.name, 0u);
    f.run.output = texture(4, RGBA16F);
    const FramePlan o = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
    EXPECT_EQ(o.resolve_albedo, 2);
    if (!cross_bilateral) {
      EXPECT_EQ(find(o, K::blur, 0, 1)->variant.albedo, 1);
    } else {
      EXPECT_EQ(o.cbf_albedo, 1);
    }
    const FilterRun out = passes_run(f.run, module, nullptr, false);
    EXPECT_EQ(out.albedo.name, 32u);
    EXPECT_EQ(out.original.name, 31u);
    EXPECT_EQ(out.untouched_colour(), 31u);
    EXPECT_EQ(out.color.name, 30u);
  }
  // Nothing to blur: the resolved colour copied, nothing divided.
  f.run.identity = true;
  EXPECT_EQ(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT).resolve_albedo, 0);
}

TEST(FramePlan, DebugViewsRunTheFirstTermsFragmentPasses) {
  Frame f;
  f.kernel = kernel_of(3);
  f.run.output = texture(4, RGBA32F);
  for (std::uint32_t view = 1; view <= SSS_DEBUG_VIEW_LAST; ++view) {
    f.run.debug_view = view;
    const FramePlan p = plan_frame(f.run, desktop(), SSS_PATH_COMPUTE);  // the views are fragment passes'
    EXPECT_EQ(p.path, static_cast<unsigned>(SSS_PATH_FRAGMENT));
    if (view == SSS_DEBUG_VIEW_TILES) {
      EXPECT_EQ(kinds(p), (std::vector<K>{K::begin, K::mark_tiles, K::attach_targets, K::tile_view, K::detach}));
      continue;
    }
    EXPECT_EQ(p.terms, 1);
    const Step& v = *find(p, K::blur, 0, 1);
    EXPECT_EQ(v.variant.debug_view, static_cast<int>(view));
    EXPECT_FALSE(v.copy_untouched);  // the view fills what the culling keeps instead
  }
}

TEST(FramePlan, ThePlanDescribesItselfAndComparesByValue) {
  Frame f;
  const FramePlan a = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  const FramePlan b = plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT);
  EXPECT_EQ(a, b);
  const std::string text = describe(a);
  EXPECT_NE(text.find("separable"), std::string::npos);
  EXPECT_NE(text.find("draw inputs"), std::string::npos);
  EXPECT_NE(text.find("term 0 vertical into target"), std::string::npos) << text;
  EXPECT_NE(a, plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT_MASKED));
}

}  // namespace

namespace {

// docs/architecture.md shows the default frame's plan as SSS_LOG_DEBUG prints it: that block is
// this plan's describe(), kept true here.
TEST(FramePlan, TheArchitecturePageShowsTheDefaultPlan) {
  Frame f;
  const std::string expected = describe(plan_frame(f.run, desktop(), SSS_PATH_FRAGMENT));
  std::FILE* file = std::fopen(SSS_SOURCE_DIR "/docs/architecture.md", "rb");
  ASSERT_NE(file, nullptr);
  std::string page;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) page.append(buffer, n);
  std::fclose(file);
  const std::size_t start = page.find("```\nframe plan:");
  ASSERT_NE(start, std::string::npos) << "docs/architecture.md has no plan block";
  const std::size_t end = page.find("```", start + 4);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(page.substr(start + 4, end - start - 4), expected) << "the block should read:\n" << expected;
}

}  // namespace
