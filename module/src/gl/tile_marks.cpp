// The masked path's tile culling (SSS_PATH_FRAGMENT_MASKED; the rule and its CPU form:
// math/tile_culling.hpp). The depth the inputs draw marks keeps the blur to translucent pixels, but
// the rasteriser still visits every pixel of the rectangle for each draw, and the inputs draw
// writes 36 bytes at each: on a far shot or an empty frame that is nearly all of the frame's cost.
// Two small draws first mark which 16x16 tiles hold a translucent pixel (tile_mark.frag: one
// fragment per tile, stopping at the first such pixel) and which columns of tiles do; the inputs
// draw and the blur passes then draw bands of tiles (fullscreen.vert's SSS_TILE_SPANS) instead of
// one triangle. The passes' bands lie inside the inputs draw's, so they never test a pixel whose
// culling depth that draw did not write; into a separate output, whose copy of the untouched
// pixels tests every pixel, the inputs draw clears the culling depth first (not translucent).
#include "debug_label.hpp"
#include "plan_steps.hpp"
#include "texture_units.hpp"

#include "../math/tile_culling.hpp"

namespace sss::gl {

void mark_tiles(PassContext& ctx, const FilterRun& run, const PlanPrograms& p) {
  const Functions& f = ctx.gl;
  const Targets& t = ctx.targets.names();
  const std::array<int, 4>& rect = run.draw_rect;
  const int across = math::tiles_across(rect[2]), down = math::tiles_across(rect[3]);
  const TileMarkProgram* tiles = p.tile_marks;
  const TileMarkProgram* columns = p.tile_columns;
  DebugGroup group(f, ctx.labels, "sss tile marks (masked path)");
  f.Disable(DEPTH_TEST);
  f.Disable(STENCIL_TEST);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t.tiles_framebuffer);
  f.Viewport(0, 0, across, down);
  f.UseProgram(tiles->program);
  f.Uniform4i(tiles->rect, rect[0], rect[1], rect[2], rect[3]);
  if (tiles->color_image >= 0) {
    // As the passes' inputs draw (draw_pass_inputs): the colour through image unit 0, then off it.
    f.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
    f.BindImageTexture(0, run.color.name, 0, 0, 0, READ_ONLY, kComputeImageFormats[tiles->color_image].internal_format);
  } else {
    bind_texture(ctx, unit::source, run.color.name, ctx.objects.sampler);
  }
  f.DrawArrays(TRIANGLES, 0, 3);
  if (tiles->color_image >= 0) f.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  ++ctx.draws;
  // The columns read the tiles' marks, which stay on their unit for the span draws' vertex stage.
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t.tile_columns_framebuffer);
  f.Viewport(0, 0, across, 1);
  f.UseProgram(columns->program);
  f.Uniform4i(columns->rect, 0, down, 0, 0);
  bind_texture(ctx, unit::tiles, t.tiles, ctx.objects.nearest_sampler);
  f.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
  bind_texture(ctx, unit::tile_columns, t.tile_columns, ctx.objects.nearest_sampler);
  f.Viewport(rect[0], rect[1], rect[2], rect[3]);
  // A tile's size in NDC of the rectangle's viewport; its corners land on whole pixels.
  ctx.tile_bands = math::tile_bands(down);
  ctx.tile_grid = {static_cast<GLfloat>(across), static_cast<GLfloat>(down),
                   2.0f * static_cast<GLfloat>(math::kTileSize) / static_cast<GLfloat>(rect[2]),
                   2.0f * static_cast<GLfloat>(math::kTileSize) / static_cast<GLfloat>(rect[3])};
}

}  // namespace sss::gl
