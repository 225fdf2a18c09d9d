// The tiles debug view (sss.h SSS_DEBUG_VIEW_TILES): the masked path's tile marks (tile_culling.cpp)
// and what its band draws cover, written into the separate output. The bands are drawn by the
// vertex stage the masked path's own draws use, so the view shows what that path rasterises; a
// colour mask per draw puts each draw in its own channel, which needs no blending state.
#include "debug_label.hpp"
#include "runners.hpp"

namespace sss::gl {

namespace {
struct TileViewPrograms {
  TileViewProgram* marks = nullptr;   // the full-screen triangle
  TileViewProgram* inputs = nullptr;  // the inputs draw's bands
  TileViewProgram* passes = nullptr;  // the blur passes' bands
};

sss_result build_tile_view(PassContext& ctx, const FilterRun& run, TileViewPrograms* p, std::string* message) {
  sss_result r = ctx.programs.tile_view(TileSpans::none, &p->marks, message);
  if (r == SSS_OK) r = ctx.programs.tile_view(TileSpans::inputs, &p->inputs, message);
  if (r == SSS_OK) r = ctx.programs.tile_view(TileSpans::passes, &p->passes, message);
  if (r == SSS_OK) r = prepare_tile_culling(ctx, run, message);
  return r;
}

// One of the band draws, into the channels `red`, `green` of the output.
void draw_bands(PassContext& ctx, const TileViewProgram& p, bool red, bool green) {
  const Functions& f = ctx.gl;
  f.ColorMask(red ? 1 : 0, green ? 1 : 0, 0, 0);
  f.UseProgram(p.program);
  draw_cover(ctx, p.tile_grid);
}
}  // namespace

sss_result run_tile_view(PassContext& ctx, const FilterRun& run, std::string* message) {
  const Functions& f = ctx.gl;
  TileViewPrograms programs;
  sss_result r = build_tile_view(ctx, run, &programs, message);
  if (r != SSS_OK) return r;
  begin_passes(ctx, run.draw_rect);
  r = mark_tiles(ctx, run, message);  // the marks on their units, the bands in ctx.tile_bands
  if (r == SSS_OK) r = attach_output(ctx, run, 0, message);
  if (r == SSS_OK) {
    DebugGroup group(f, ctx.labels, "sss tiles view");
    f.Disable(DEPTH_TEST);
    f.Disable(STENCIL_TEST);
    // Every pixel of the rectangle: (0, 0, its tile's mark, 1); one triangle, whatever the bands.
    f.UseProgram(programs.marks->program);
    f.Uniform4i(programs.marks->rect, run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
    f.DrawArrays(TRIANGLES, 0, 3);
    ++ctx.draws;
    draw_bands(ctx, *programs.inputs, false, true);
    draw_bands(ctx, *programs.passes, true, false);
    f.ColorMask(1, 1, 1, 1);
  }
  ctx.tile_bands = 0;
  detach_output(ctx);
  return r;
}

}  // namespace sss::gl
