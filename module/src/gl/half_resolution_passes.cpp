// SSS_PATH_HALF_RESOLUTION: the separable passes at half size where the kernel is wide, the
// fragment passes at full size elsewhere (the method and its constants: math/half_resolution.hpp).
// The draws, after pass_inputs.frag's (full size, marking translucent pixels 0 in the culling
// depth, the rest 1):
//   1. half_inputs.frag reduces the inputs to half size (every texel of the half-size rectangle,
//      or of its bands of tiles: below), marking translucent texels in the half-size culling depth
//      (0; the rest 1);
//   2. the horizontal and vertical passes at half size behind that depth (the same programs as at
//      full size, at half the pixels per mm), the vertical one into half_result, cleared first;
//   3. into a separate output: the colour copied where the depth is 1 (not translucent) or the host's
//      stencil fails (with a host stencil, every later draw tests it too);
//   4. half_upsample.frag over translucent pixels (GL_GREATER at depth 0.5), writing depth 0.5
//      where it writes the colour and discarding where the full-size passes must run;
//   5. the full-size horizontal and vertical passes drawn at depth 0.25 (glDepthRange 0..0.5), so
//      that GL_GREATER lets through exactly the translucent pixels step 4 discarded.
// The host's colour is written by steps 3-5 only, after the inputs draw has read it.
// Without a host stencil, and where the rectangle starts on even coordinates (so that each 2x2
// block lies inside one 16x16 tile), every draw but the copy keeps to the masked path's bands of
// tiles (tile_culling.cpp), at full size and, for the reduction and the half-size passes, at half
// size (8 texels a tile). The reasons the bands are enough are the masked path's: a translucent
// pixel's taps stay in its row or column, which the inputs' bands hold whole, at either size; the
// upsample's near field is its row and column too, and of its half-size texels it reads only those
// the half-size passes wrote (half_result, cleared each frame, holds alpha 0 elsewhere), which lie
// in marked tiles. The half-size culling depth needs no clear: the half-size passes test it only
// in their bands, which lie inside the reduction's.
#include <string>
#include <utility>
#include <vector>

#include "../math/half_resolution.hpp"
#include "../math/tile_culling.hpp"
#include "blur_pass.hpp"
#include "pass_uniforms.hpp"
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {

const math::PassKernel& kernel_of(const FilterRun& run, int profile) {
  return run.has_profiles() ? *run.profile_kernels[static_cast<std::size_t>(profile)] : *run.kernel;
}
const math::PassConstants& constants_of(const FilterRun& run, int profile) {
  return run.has_profiles() ? run.profile_constants[static_cast<std::size_t>(profile)] : run.constants;
}

// Every profile's two pass tables, a row each (half_upsample.frag's u_tables).
std::vector<float> table_texels(const FilterRun& run) {
  constexpr int kWidth = math::kFootprintEntries + 1;
  std::vector<float> texels(static_cast<std::size_t>(kWidth) * 4 * 2 * static_cast<std::size_t>(run.profile_count),
                            0.0f);
  for (int p = 0; p < run.profile_count; ++p) {
    const math::PassTerm& term = kernel_of(run, p).terms.front();
    for (int axis = 0; axis < 2; ++axis) {
      const math::FootprintTable& t = (axis == 0 ? term.horizontal : term.vertical).footprint;
      float* row = texels.data() + static_cast<std::size_t>(2 * p + axis) * kWidth * 4;
      for (std::size_t j = 0; j < t.half_cdf.size(); ++j) {
        for (std::size_t c = 0; c < 3; ++c) row[j * 4 + c] = t.half_cdf[j][c];
      }
      row[math::kFootprintEntries * 4] = t.reach_mm;
      for (std::size_t c = 0; c < 3; ++c) row[math::kFootprintEntries * 4 + 1 + c] = t.delta[c];
    }
  }
  return texels;
}

// The tables' revision: the kernels' (profiles and the single kernel count apart).
std::uint64_t tables_revision(const FilterRun& run) {
  return run.has_profiles() ? run.profiles_revision * 2 + 1 : run.kernel_revision * 2;
}

// The run at half size: half the pixels per mm, taps kept in the half-size rectangle.
FilterRun half_size_run(const FilterRun& run, const std::array<int, 4>& half) {
  FilterRun h = run;
  h.constants = math::half_pass_constants(run.constants, half);
  for (int p = 0; p < run.profile_count; ++p) {
    const auto i = static_cast<std::size_t>(p);
    h.profile_constants[i] = math::half_pass_constants(run.profile_constants[i], half);
  }
  return h;
}

void set_viewport(const Functions& f, const std::array<int, 4>& rect) { f.Viewport(rect[0], rect[1], rect[2], rect[3]); }

// The three half-size framebuffers, checked before the first draw (the draws do not check).
sss_result check_half_size_framebuffers(PassContext& ctx, std::string* message) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const std::array<std::pair<GLuint, const char*>, 3> framebuffers = {
      {{t.half_inputs_framebuffer, "half-size inputs"},
       {t.half_intermediate_framebuffer, "half-size horizontal pass"},
       {t.half_result_framebuffer, "half-size vertical pass"}}};
  for (const auto& [framebuffer, which] : framebuffers) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffer);
    const sss_result r = check_framebuffer(ctx, which, message);
    if (r != SSS_OK) return r;
  }
  return SSS_OK;
}

void draw_reduction(PassContext& ctx, const FilterRun& run, const HalfInputsProgram& p) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t.half_inputs_framebuffer);
  DebugGroup group(f, ctx.labels, "sss half-size inputs");
  f.UseProgram(p.program);
  const HalfInputsUniforms u = fill_half_inputs_uniforms(run);
  upload_uniforms(f, kHalfInputsUniforms, p.fields, u.values.data());
  std::array<float, 16> factors{};
  for (int i = 0; i < run.profile_count; ++i) factors[static_cast<std::size_t>(i)] = constants_of(run, i).follow_surface_factor;
  f.Uniform1fv(p.depth_factor, 16, factors.data());
  bind_texture(ctx, unit::source, t.pass_taps, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::pass_strength, t.pass_strength, ctx.objects.nearest_sampler);
  draw_cover(ctx, p.tile_grid);
}

// One pass at half size: `source` and the half-size strength.
void draw_half_pass(PassContext& ctx, const FilterRun& half, BlurProgram& p, int axis) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  f.BindFramebuffer(DRAW_FRAMEBUFFER, axis == 0 ? t.half_intermediate_framebuffer : t.half_result_framebuffer);
  DebugGroup group(f, ctx.labels, axis == 0 ? "sss half-size horizontal pass" : "sss half-size vertical pass");
  // The culled texels of the result are read by the upsample as "not translucent": alpha 0, cleared
  // each frame (what the culling skips would hold an older frame's values).
  if (axis == 1) {
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    f.ClearBufferfv(COLOR, 0, zero);
  }
  // The vertical pass writes half_result, in the intermediate's format (not the target's).
  const int round = axis == 1 ? (half.intermediate_format() == static_cast<GLint>(RGBA16F) ? 1 : 0) : -1;
  set_blur_uniforms(ctx, p, half, 0, axis, round);
  bind_packed_inputs(ctx, p, axis == 0 ? t.half_taps : t.half_intermediate, t.half_strength);
  if (half.has_profiles()) bind_profile_inputs(ctx, half, axis);
  draw_cover(ctx, p.tile_grid);
}

void draw_upsample(PassContext& ctx, const FilterRun& run, const HalfUpsampleProgram& p, const std::array<int, 4>& half) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  DebugGroup group(f, ctx.labels, "sss half-size upsample");
  f.UseProgram(p.program);
  std::array<float, 4 * 16> looks{};
  for (int i = 0; i < run.profile_count; ++i) {
    const math::PassConstants& k = constants_of(run, i);
    const auto at = static_cast<std::size_t>(4 * i);
    looks[at] = k.pixels_per_mm[0];
    looks[at + 1] = k.pixels_per_mm[1];
    looks[at + 2] = k.follow_surface_factor;
  }
  f.Uniform4fv(p.looks, 16, looks.data());
  const UpsampleUniforms u =
      fill_upsample_uniforms(run, half, run.target().internal_format == static_cast<GLint>(RGBA16F));
  upload_uniforms(f, kUpsampleUniforms, p.fields, u.values.data());
  bind_texture(ctx, unit::source, t.pass_taps, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::pass_strength, t.pass_strength, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::half_source, t.half_taps, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::half_result, t.half_result, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::half_tables, t.half_tables, ctx.objects.nearest_sampler);
  draw_cover(ctx, p.tile_grid);
}

// Into a separate output: the colour as it is where no pass writes (not translucent by alpha, or
// outside the host's stencil).
void copy_untouched(PassContext& ctx, const FilterRun& run) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss copy (not translucent)");
  if (run.stencil != nullptr) {
    f.Disable(DEPTH_TEST);
    set_stencil_test(f, run.stencil, NOTEQUAL);
    draw_copy(ctx, run.untouched_colour());
    set_stencil_test(f, run.stencil, EQUAL);
  }
  f.Enable(DEPTH_TEST);
  f.DepthFunc(LEQUAL);
  draw_copy(ctx, run.untouched_colour());
}

}  // namespace

// Steps 1 and 2 of the file's comment: the reduction and the passes at half size.
void draw_half_size(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, PlanMeasurement& measure) {
  const Functions& f = ctx.gl;
  const std::array<int, 4> half = math::half_rect(run.draw_rect);
  measure.get().begin(PassQueries::horizontal);
  set_viewport(f, half);
  // The bands at half size: the same tiles, 8 texels a side (uses_tiles: blocks never straddle them).
  const std::array<GLfloat, 4> full_grid = ctx.tile_grid;
  constexpr GLfloat kHalfTile = static_cast<GLfloat>(math::kTileSize / 2);
  ctx.tile_grid[2] = 2.0f * kHalfTile / static_cast<GLfloat>(half[2]);
  ctx.tile_grid[3] = 2.0f * kHalfTile / static_cast<GLfloat>(half[3]);
  f.Enable(DEPTH_TEST);
  f.DepthFunc(ALWAYS);  // the reduction marks every texel it draws
  f.DepthMask(1);
  draw_reduction(ctx, run, *p.half_inputs);
  f.DepthMask(0);
  f.DepthFunc(GREATER);  // the half-size passes: translucent texels only
  const FilterRun half_run = half_size_run(run, half);
  draw_half_pass(ctx, half_run, *p.half_horizontal, 0);
  draw_half_pass(ctx, half_run, *p.half_vertical, 1);
  ctx.tile_grid = full_grid;
}

// Steps 3 to 5: full size, into the host's colour or output. gpu_time_ms[0] spans the half-size
// draws, the upsample and the full-size horizontal pass; [1] the full-size vertical pass (as on the
// fragment path, the inputs draw is not measured).
void draw_full_size(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, PlanMeasurement& measurement) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const std::array<int, 4> half = math::half_rect(run.draw_rect);
  FrameMeasurement& measure = measurement.get();
  set_viewport(f, run.draw_rect);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t.output_framebuffer);
  if (run.keeps_untouched()) {
    f.ColorMask(1, 1, 1, 0);  // alpha keeps the host's exact value
  } else {
    copy_untouched(ctx, run);
  }
  f.Enable(DEPTH_TEST);
  set_stencil_test(f, run.stencil, EQUAL);  // the host's stencil culls too (no stencil: the test is off)
  f.DepthFunc(GREATER);
  f.DepthMask(1);
  draw_upsample(ctx, run, *p.half_upsample, half);
  f.DepthMask(0);
  // The pixels the upsample left (depth still 0), nearer than the marks' 0.5 and 1.
  f.set_depth_range(0.0f, 0.5f);
  {
    DebugGroup group(f, ctx.labels, "sss horizontal pass (full size, narrow kernels)");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.pass_intermediate_framebuffer);
    draw_blur(ctx, *p.half_horizontal, run, t.pass_taps, 0, 0);
  }
  measure.end(PassQueries::horizontal);
  {
    DebugGroup group(f, ctx.labels, "sss vertical pass (full size, narrow kernels)");
    measure.begin(PassQueries::vertical);
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t.output_framebuffer);
    bind_original(ctx, run);
    measure.begin_pixels();
    draw_blur(ctx, *p.full_vertical, run, t.pass_intermediate, 0, 1);
    measure.end_pixels();
    measure.end(PassQueries::vertical);
  }
  f.set_depth_range(0.0f, 1.0f);
  measure.end_frame();
}

// The checks before the half-size and full-size draws: the three half-size framebuffers, the
// culling depth on the horizontal pass's, the output (with a region into a separate output, the
// viewport's colour copied there first).
sss_result attach_half_targets(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Targets& t = ctx.targets.names();
  sss_result r = check_half_size_framebuffers(ctx, message);
  if (r == SSS_OK) r = attach_stencil(ctx, t.pass_intermediate_framebuffer, t.stencil_buffer, message);
  if (r == SSS_OK) r = attach_output(ctx, run, t.stencil_buffer, message);
  return r;
}

sss_result upload_half_tables(PassContext& ctx, const FilterRun& run, std::string* message) {
  // Only when the kernels changed: a steady frame allocates nothing.
  if (ctx.targets.half_tables_hold(tables_revision(run))) return SSS_OK;
  return ctx.targets.upload_half_tables(tables_revision(run), 2 * run.profile_count, table_texels(run), message);
}

}  // namespace sss::gl
