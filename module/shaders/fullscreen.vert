// One triangle that covers the viewport; no vertex buffer needed (gl_VertexID 0, 1, 2).
//
// SSS_TILE_SPANS (the masked path's inputs draw, 2, and its blur passes, 1: module/src/gl/tile_culling.cpp)
// adds vertices 3-6 of an instanced triangle strip: instance b is band b of the drawn rectangle's
// rows of 16-pixel tiles (SSS_TILE_BAND rows a band; tile_mark.frag marked the tiles holding a
// translucent pixel), spanned from the first to the last tile any of its rows needs, or nothing.
// So the rasteriser never visits what no pass reads or writes, where the depth test alone would
// still visit every pixel. (Bands and not single rows: on llvmpipe, whose bins are 64 pixels, a
// quad 16 pixels high cost more to rasterise than the culling saved on a full frame.) What a row
// needs:
//   1 (the passes): the tiles holding a translucent pixel: only those are blurred
//   2 (the inputs): every tile of a row holding one (its horizontal taps read along that row), and
//     in the other rows the span of the columns holding one (their vertical taps read down them):
//     the taps of a translucent pixel stay in its row or column, and inside the rectangle
// The draws keep their triangle's depth (0), which is what the culling depth is tested against.
#ifdef SSS_TILE_SPANS
SSS_BINDING(5) uniform highp sampler2D u_tiles;         // r: 1 for a tile holding a translucent pixel
#if SSS_TILE_SPANS == 2
SSS_BINDING(2) uniform highp sampler2D u_tile_columns;  // r: 1 for a column of tiles holding one
#endif
uniform vec4 u_tile_grid;  // xy: the tiles across and down the rectangle, zw: a tile's size in NDC

// The first and last tile (x, y) of `band` that the draw needs; y < x when none.
ivec2 tile_span(int band) {
  int across = int(u_tile_grid.x);
  int first = across, last = -1;
  int end = min(SSS_TILE_BAND * (band + 1), int(u_tile_grid.y));
  for (int row = SSS_TILE_BAND * band; row < end; ++row) {
    for (int c = 0; c < across; ++c) {
      if (texelFetch(u_tiles, ivec2(c, row), 0).r > 0.5) {
        first = min(first, c);
        last = max(last, c);
      }
    }
  }
#if SSS_TILE_SPANS == 2
  if (last >= 0) return ivec2(0, across - 1);
  for (int c = 0; c < across; ++c) {
    if (texelFetch(u_tile_columns, ivec2(c, 0), 0).r > 0.5) {
      first = min(first, c);
      last = c;
    }
  }
#endif
  return ivec2(first, last);
}
#endif

void main() {
#ifdef SSS_TILE_SPANS
  if (gl_VertexID >= 3) {
    int corner = gl_VertexID - 3;  // strip order: (first, top), (last + 1, top), (first, bottom), (last + 1, bottom)
    ivec2 span = tile_span(gl_InstanceID);
    if (span.y < span.x) {
      gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // four equal corners: no area, nothing drawn
      return;
    }
    vec2 tile = vec2(float((corner & 1) == 0 ? span.x : span.y + 1),
                     float(SSS_TILE_BAND * (gl_InstanceID + (corner >> 1))));
    gl_Position = vec4(min(tile * u_tile_grid.zw - 1.0, vec2(1.0)), 0.0, 1.0);
    return;
  }
#endif
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
