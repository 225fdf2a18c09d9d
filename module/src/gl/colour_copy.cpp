// The module's copy of the colour that the passes read instead of the host's (frame_plan.hpp
// passes_run), for two things a host's colour may hold that the passes must not blur as they are:
// - a strength in a separate texture (sss.h sss_frame.strength_texture): the common deferred layout
//   of an R11F_G11F_B10F colour, which has no alpha, and a mask. The copy takes the colour's rgb and
//   the strength's red as alpha;
// - an albedo the texturing mode keeps out of the blur (sss.h sss_texturing): the copy's rgb is the
//   colour over A_post (module/shaders/albedo.glsl), which the pass that writes the target
//   multiplies back.
// It has the precision of the intermediate the colour gets (RGBA16F, or RGBA32F for RGBA32F
// colour); every path that copies (frame_plan.hpp copies_colour: a strength texture on any path, an
// albedo on the compute and cross-bilateral passes; the others divide in their inputs draw) then
// runs on it as its colour, so each reads the strength where it reads alpha
// today (blur weights and widths, the stencil marks, the copies of untouched pixels), and writes the
// host's colour as a separate output: its rgb, and the untouched pixels' exact values (the copy
// holds an R11F_G11F_B10F value exactly: RGBA16F has more bits in every field and the same exponent
// range; a divided copy is not the colour, so those pixels come from the host's: FilterRun::original).
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

namespace sss::gl {

sss_result draw_colour_copy(PassContext& ctx, const FilterRun& run, const FramePlan& plan, const PlanPrograms& p,
                            std::string* message) {
  const Functions& f = ctx.gl;
  const bool albedo = plan.copy.albedo != 0;
  DebugGroup group(f, ctx.labels, albedo ? "sss colour over the albedo" : "sss colour with the strength texture");
  begin_passes(ctx, run.viewport);
  f.Disable(STENCIL_TEST);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().colour_copy_framebuffer);
  const sss_result r = check_framebuffer(ctx, albedo ? "colour over the albedo" : "colour with the strength texture",
                                         message);
  if (r != SSS_OK) return r;
  const ColourCopyProgram& program = *p.colour_copy;
  f.UseProgram(program.program);
  // The copy has the intermediate's format (passes_run): rounded to nearest where that is RGBA16F.
  const ColourCopyUniforms u = fill_colour_copy_uniforms(run);
  upload_uniforms(f, kColourCopyUniforms, program.fields, u.values.data());
  bind_texture(ctx, unit::source, run.color.name, ctx.objects.sampler);
  // GL_NEAREST on ES, where an R32F texture is not filterable (texelFetch needs it complete).
  if (plan.copy.strength_texture) bind_texture(ctx, unit::strength, run.strength.name, ctx.objects.depth_sampler);
  if (albedo) bind_albedo(ctx, run, plan.copy.albedo, program.texturing);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  return SSS_OK;
}

}  // namespace sss::gl
