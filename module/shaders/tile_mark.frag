// The masked path's tile marks (module/src/gl/tile_culling.cpp), drawn at one fragment per 16x16
// tile of the drawn rectangle: 1 where the tile holds a translucent pixel (alpha above 0, the test
// pass_inputs.frag marks the culling depth with, so a NaN alpha is not one), else 0. The scan stops
// at the first such pixel, so a tile of skin costs one fetch and only the tiles with none read
// every pixel (alpha only: a fetch and a compare each, no depth, no writes).
// SSS_TILE_COLUMNS 1: instead one fragment per column of tiles, 1 where any tile of it is marked
// (from the marks above, on unit 5).
// SSS_COLOR_IMAGE 1: the colour is read through image unit 0 (its format SSS_COLOR_IMAGE_FORMAT), as
// pass_inputs.frag reads it where the context has image units and the colour is complete: on
// llvmpipe a texelFetch from a float texture is a call to a sampling function, and on a frame
// with little skin this scan of the tiles without any was most of the frame's work (1080p empty
// frame: 6.7e7 instructions with the sampler, 2.9e7 with the image).
#if SSS_TILE_COLUMNS
SSS_BINDING(5) uniform highp sampler2D u_tiles;
#elif SSS_COLOR_IMAGE
layout(binding = 0, SSS_COLOR_IMAGE_FORMAT) readonly uniform highp image2D u_color_image;  // as below, complete
#else
SSS_BINDING(0) uniform sampler2D u_color;  // the colour the passes read (its alpha is the strength)
#endif
uniform ivec4 u_rect;  // the drawn rectangle (x, y, width, height); SSS_TILE_COLUMNS: y the rows of tiles
out vec4 o_mark;

void main() {
  float mark = 0.0;
#if SSS_TILE_COLUMNS
  int column = int(gl_FragCoord.x);
  for (int row = 0; row < u_rect.y; ++row) {
    if (texelFetch(u_tiles, ivec2(column, row), 0).r > 0.5) {
      mark = 1.0;
      break;
    }
  }
#else
  ivec2 origin = u_rect.xy + 16 * ivec2(gl_FragCoord.xy);
  ivec2 end = min(origin + 16, u_rect.xy + u_rect.zw);
  for (int y = origin.y; y < end.y && mark == 0.0; ++y) {
    for (int x = origin.x; x < end.x; ++x) {
#if SSS_COLOR_IMAGE
      float alpha = imageLoad(u_color_image, ivec2(x, y)).a;
#else
      float alpha = texelFetch(u_color, ivec2(x, y), 0).a;
#endif
      if (alpha > 0.0) {
        mark = 1.0;
        break;
      }
    }
  }
#endif
  o_mark = vec4(mark);
}
