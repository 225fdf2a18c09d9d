// The tiles debug view (sss.h SSS_DEBUG_VIEW_TILES): the masked path's tile marks (tile_culling.cpp)
// and what its band draws cover, written into the separate output. The bands are drawn by the
// vertex stage the masked path's own draws use, so the view shows what that path rasterises; a
// colour mask per draw puts each draw in its own channel, which needs no blending state.
#include "debug_label.hpp"
#include "plan_steps.hpp"

namespace sss::gl {

namespace {
// One of the band draws, into the channels `red`, `green` of the output.
void draw_bands(PassContext& ctx, const TileViewProgram& p, bool red, bool green) {
  const Functions& f = ctx.gl;
  f.ColorMask(red ? 1 : 0, green ? 1 : 0, 0, 0);
  f.UseProgram(p.program);
  draw_cover(ctx, p.tile_grid);
}
}  // namespace

sss_result attach_tile_view(PassContext& ctx, const FilterRun& run, std::string* message) {
  return attach_output(ctx, run, 0, message);
}

void draw_tile_view(PassContext& ctx, const FilterRun& run, const PlanPrograms& p) {
  const Functions& f = ctx.gl;
  const TileViewProgram& marks = *p.tile_view[static_cast<std::size_t>(TileSpans::none)];
  DebugGroup group(f, ctx.labels, "sss tiles view");
  f.Disable(DEPTH_TEST);
  f.Disable(STENCIL_TEST);
  // Every pixel of the rectangle: (0, 0, its tile's mark, 1); one triangle, whatever the bands.
  f.UseProgram(marks.program);
  f.Uniform4i(marks.rect, run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  draw_bands(ctx, *p.tile_view[static_cast<std::size_t>(TileSpans::inputs)], false, true);
  draw_bands(ctx, *p.tile_view[static_cast<std::size_t>(TileSpans::passes)], true, false);
  f.ColorMask(1, 1, 1, 1);
}

}  // namespace sss::gl
