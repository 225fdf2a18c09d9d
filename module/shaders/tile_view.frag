// The tiles debug view (sss.h SSS_DEBUG_VIEW_TILES; module/src/gl/tile_view.cpp): what the masked
// path's draws cover, drawn by the same vertex stage those draws use (fullscreen.vert's
// SSS_TILE_SPANS), so the picture is the rasteriser's, not a second account of the rule.
// Three draws into the output, each with its own program of this shader:
//   the full-screen triangle: (0, 0, mark, 1), mark 1 where the pixel's own tile holds a
//     translucent pixel (tile_mark.frag's marks, on unit 5)
//   SSS_TILE_VIEW_BANDS 1, the inputs draw's bands, colour mask green only: green 1
//   SSS_TILE_VIEW_BANDS 1, the blur passes' bands, colour mask red only: red 1
out vec4 o_view;

#ifdef SSS_TILE_VIEW_BANDS
void main() { o_view = vec4(1.0); }  // the band draw's colour mask picks the channel
#else
SSS_BINDING(5) uniform highp sampler2D u_tiles;  // r: 1 for a tile holding a translucent pixel
uniform ivec4 u_rect;  // the drawn rectangle (x, y, width, height): the tiles start at its corner

void main() {
  ivec2 tile = (ivec2(gl_FragCoord.xy) - u_rect.xy) / 16;
  o_view = vec4(0.0, 0.0, texelFetch(u_tiles, tile, 0).r, 1.0);
}
#endif
