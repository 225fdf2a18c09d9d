// The masked path's tile culling rule (module/src/math/tile_culling.hpp), which the GL draws
// compute the same way (tile_mark.frag, fullscreen.vert's SSS_TILE_SPANS): on random sparse masks
// of awkward sizes, the bands the passes draw hold every translucent pixel, and the bands the
// inputs draw hold every pixel in the row or column of one (all a tap can read: the taps of a
// pass stay on its axis and inside the rectangle); and they are no wider than the rule says.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "math/tile_culling.hpp"

namespace {

using sss::math::kTileBand;
using sss::math::kTileSize;
using sss::math::TileDraw;
using sss::math::TileSpan;

struct Culling {
  int width = 0, height = 0, across = 0, down = 0;
  std::vector<unsigned char> marks, columns;
  explicit Culling(const std::vector<unsigned char>& translucent, int w, int h)
      : width(w), height(h), across(sss::math::tiles_across(w)), down(sss::math::tiles_across(h)) {
    marks.assign(static_cast<std::size_t>(across * down), 0);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (translucent[static_cast<std::size_t>(y * w + x)]) {
          marks[static_cast<std::size_t>((y / kTileSize) * across + x / kTileSize)] = 1;
        }
      }
    }
    columns = sss::math::column_marks(marks, across, down);
  }
  // Whether a draw covers pixel (x, y).
  bool covers(int x, int y, TileDraw draw) const {
    const int band = y / kTileSize / kTileBand;
    const TileSpan span = sss::math::tile_span(marks, columns, across, down, band, draw);
    return !span.empty() && x / kTileSize >= span.first && x / kTileSize <= span.last;
  }
};

TEST(TileCulling, TheBandsHoldEveryPixelTheDrawsNeed) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = std::uniform_int_distribution<int>(1, 300)(rng);
    const int h = std::uniform_int_distribution<int>(1, 300)(rng);
    const int dots = std::uniform_int_distribution<int>(0, 6)(rng);
    std::vector<unsigned char> translucent(static_cast<std::size_t>(w * h), 0);
    for (int i = 0; i < dots; ++i) {
      const int x = std::uniform_int_distribution<int>(0, w - 1)(rng);
      const int y = std::uniform_int_distribution<int>(0, h - 1)(rng);
      translucent[static_cast<std::size_t>(y * w + x)] = 1;
    }
    const Culling c(translucent, w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!translucent[static_cast<std::size_t>(y * w + x)]) continue;
        ASSERT_TRUE(c.covers(x, y, TileDraw::passes)) << w << "x" << h << " at " << x << "," << y;
        for (int other = 0; other < w; ++other) ASSERT_TRUE(c.covers(other, y, TileDraw::inputs));  // its row
        for (int other = 0; other < h; ++other) ASSERT_TRUE(c.covers(x, other, TileDraw::inputs));  // its column
      }
    }
  }
}

TEST(TileCulling, NothingTranslucentDrawsNothingAndOnePixelLittle) {
  const int w = 200, h = 150;
  std::vector<unsigned char> translucent(static_cast<std::size_t>(w * h), 0);
  const Culling none(translucent, w, h);
  for (int band = 0; band < sss::math::tile_bands(none.down); ++band) {
    EXPECT_TRUE(sss::math::tile_span(none.marks, none.columns, none.across, none.down, band, TileDraw::passes).empty());
    EXPECT_TRUE(sss::math::tile_span(none.marks, none.columns, none.across, none.down, band, TileDraw::inputs).empty());
  }
  translucent[static_cast<std::size_t>(70 * w + 100)] = 1;  // tile (6, 4): band 1
  const Culling one(translucent, w, h);
  int passes = 0, inputs = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      passes += one.covers(x, y, TileDraw::passes) ? 1 : 0;
      inputs += one.covers(x, y, TileDraw::inputs) ? 1 : 0;
    }
  }
  EXPECT_EQ(passes, kTileSize * kTileSize * kTileBand);  // its tile's column in its band
  // Its band whole (the row of its tile, widened to the band), and its column of tiles elsewhere.
  EXPECT_EQ(inputs, w * kTileSize * kTileBand + kTileSize * (h - kTileSize * kTileBand));
}

}  // namespace
