// A colour whose strength is in a separate texture (sss.h sss_frame.strength_texture): the common
// deferred layout of an R11F_G11F_B10F colour, which has no alpha, and a mask. One draw puts the
// colour's rgb and the strength's red channel together into the module's copy, in the precision of
// the intermediate the colour gets (RGBA16F, or RGBA32F for RGBA32F colour); every path then runs
// on that copy as its colour, so each reads the strength where it reads alpha today (blur weights
// and widths, the stencil marks, the copies of untouched pixels), and writes the host's colour as
// a separate output: its rgb, and the untouched pixels' exact values (the copy holds an
// R11F_G11F_B10F value exactly: RGBA16F has more bits in every field and the same exponent range).
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

namespace sss::gl {

sss_result draw_strength_source(PassContext& ctx, const FilterRun& run, const PlanPrograms& p, std::string* message) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss colour with the strength texture");
  begin_passes(ctx, run.viewport);
  f.Disable(STENCIL_TEST);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().strength_framebuffer);
  const sss_result r = check_framebuffer(ctx, "colour with the strength texture", message);
  if (r != SSS_OK) return r;
  f.UseProgram(p.strength->program);
  // The copy has the intermediate's format (passes_run): rounded to nearest where that is RGBA16F.
  f.Uniform1i(p.strength->round_to_half, run.intermediate_format() == static_cast<GLint>(RGBA16F) ? 1 : 0);
  bind_texture(ctx, unit::source, run.color.name, ctx.objects.sampler);
  // GL_NEAREST on ES, where an R32F texture is not filterable (texelFetch needs it complete).
  bind_texture(ctx, unit::strength, run.strength.name, ctx.objects.depth_sampler);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  return SSS_OK;
}

}  // namespace sss::gl
