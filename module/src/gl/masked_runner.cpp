// SSS_PATH_FRAGMENT_MASKED: the fragment passes (which cull by the depth their inputs draw marks
// from alpha) with their draws kept to the tiles that hold translucent pixels (tile_culling.cpp);
// and the stencil the MSAA path marks from alpha: the paper's stencil culling, where the stencil is
// initialised from the strength mask so that both blur passes run only on translucent pixels.
#include "debug_label.hpp"
#include "runners.hpp"
#include "texture_units.hpp"

namespace sss::gl {

bool masked_available(const FilterRun& run) {
  return !run.color.multisampled() && !run.cross_bilateral && run.stencil == nullptr && !run.identity;
}

sss_result stencil_mark_resources(PassContext& ctx, int width, int height, GLuint* program, std::string* message) {
  const sss_result r = ctx.programs.stencil_mark(program, message);
  if (r != SSS_OK) return r;
  return ctx.targets.ensure_stencil_buffer(static_cast<GLint>(DEPTH24_STENCIL8), width, height, message);
}

sss_result mark_stencil_from_alpha(PassContext& ctx, const FilterRun& run, GLuint source, std::string* message) {
  const Functions& f = ctx.gl;
  GLuint program = 0;
  sss_result r = stencil_mark_resources(ctx, run.color.width, run.color.height, &program, message);
  if (r != SSS_OK) return r;
  r = attach_stencil(ctx, horizontal_framebuffer(ctx, run), ctx.targets.names().stencil_buffer, message,
                     "stencil mark");
  if (r != SSS_OK) return r;
  DebugGroup group(f, ctx.labels, "sss stencil from alpha");
  f.StencilMaskSeparate(FRONT_AND_BACK, 0xFF);
  const GLint zero = 0;
  f.ClearBufferiv(STENCIL, 0, &zero);  // glClearBuffer leaves the host's clear values alone
  f.ColorMask(0, 0, 0, 0);
  f.Enable(STENCIL_TEST);
  f.StencilFuncSeparate(FRONT_AND_BACK, ALWAYS, 1, 0xFF);
  f.StencilOpSeparate(FRONT_AND_BACK, KEEP, KEEP, REPLACE);
  f.UseProgram(program);
  bind_texture(ctx, unit::msaa_color, source, ctx.objects.sampler);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  f.ColorMask(1, 1, 1, 1);
  f.StencilMaskSeparate(FRONT_AND_BACK, 0);
  f.Disable(STENCIL_TEST);
  return SSS_OK;
}

sss_result run_masked(PassContext& ctx, const FilterRun& run, std::string* message) {
  // The fragment passes cull by the depth their inputs draw marks from alpha (fragment_runner.cpp)
  // whenever no stencil is given; the tiles add what that culling cannot: the rasteriser skips the
  // rest of the frame instead of testing every pixel of it in every draw.
  return run_separable(ctx, run, masked_available(run), message);
}

}  // namespace sss::gl
