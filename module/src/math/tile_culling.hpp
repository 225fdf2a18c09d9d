// The masked path's tile culling (module/src/gl/tile_marks.cpp, module/shaders/tile_mark.frag and
// fullscreen.vert's SSS_TILE_SPANS), as plain functions: the GL draws compute exactly this, and the
// unit tests check on it that the rows it draws hold every pixel the passes read or write.
//
// The drawn rectangle is cut into kTileSize-pixel tiles (the last row and column may be narrower).
// A tile is marked when one of its pixels is translucent (alpha above 0). Per row of tiles, the
// blur passes need its marked tiles; the inputs draw (what the taps read) needs a row with a marked
// tile whole (the horizontal taps of its pixels read along the row) and in any other row the
// columns holding a marked tile (the vertical taps read down them). Both are conservative: the
// taps' reach is not known before the inputs draw, and a bound on it would need every pixel's
// depth. The draws cover bands of kTileBand rows, each from the first to the last tile any of its
// rows needs: one quad a band (llvmpipe rasterised quads one tile high at more than the culling
// saved on a full frame; its bins are 64 pixels).
#pragma once

#include <array>
#include <vector>

namespace sss::math {

inline constexpr int kTileSize = 16;
inline constexpr int kTileBand = 4;  // rows of tiles a band

// Tiles over `pixels` pixels along one axis; bands over `rows` rows of tiles.
inline int tiles_across(int pixels) { return (pixels + kTileSize - 1) / kTileSize; }
inline int tile_bands(int rows) { return (rows + kTileBand - 1) / kTileBand; }

enum class TileDraw { passes, inputs };

// The first and last tile of a band a draw covers; last < first when it covers none.
struct TileSpan {
  int first = 0, last = -1;
  bool empty() const { return last < first; }
};

// `marks`: across × down, row-major, nonzero where a tile holds a translucent pixel.
std::vector<unsigned char> column_marks(const std::vector<unsigned char>& marks, int across, int down);
TileSpan tile_span(const std::vector<unsigned char>& marks, const std::vector<unsigned char>& columns, int across,
                   int down, int band, TileDraw draw);

// The tiles' marks of `rect` (x, y, width, height) in an RGBA image `width` pixels wide, row 0 at
// the bottom: across × down, 1 where a tile's alpha is above 0 somewhere (NaN is not).
std::vector<unsigned char> tile_marks(const float* rgba, int width, const std::array<int, 4>& rect);

// The tiles debug view (sss.h SSS_DEBUG_VIEW_TILES) over `rect` of `out` (RGBA, `width` wide; the
// rest left as it is): (r, g, b, 1) with r 1 where the blur passes' bands cover the pixel, g where
// the inputs draw's do, b where the pixel's own tile is marked. `rgba` and `out` may not alias.
void write_tile_view(const float* rgba, int width, const std::array<int, 4>& rect, float* out);

}  // namespace sss::math
