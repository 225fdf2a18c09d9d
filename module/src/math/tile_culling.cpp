#include "tile_culling.hpp"

#include <algorithm>

namespace sss::math {

std::vector<unsigned char> column_marks(const std::vector<unsigned char>& marks, int across, int down) {
  std::vector<unsigned char> columns(static_cast<std::size_t>(across), 0);
  for (int row = 0; row < down; ++row) {
    for (int c = 0; c < across; ++c) {
      if (marks[static_cast<std::size_t>(row * across + c)] != 0) columns[static_cast<std::size_t>(c)] = 1;
    }
  }
  return columns;
}

TileSpan tile_span(const std::vector<unsigned char>& marks, const std::vector<unsigned char>& columns, int across,
                   int down, int band, TileDraw draw) {
  TileSpan span{across, -1};
  const auto widen = [&span](int c) {
    if (c < span.first) span.first = c;
    if (c > span.last) span.last = c;
  };
  const int end = std::min(kTileBand * (band + 1), down);
  for (int row = kTileBand * band; row < end; ++row) {
    for (int c = 0; c < across; ++c) {
      if (marks[static_cast<std::size_t>(row * across + c)] != 0) widen(c);
    }
  }
  if (draw == TileDraw::passes) return span;
  if (!span.empty()) return TileSpan{0, across - 1};
  for (int c = 0; c < across; ++c) {
    if (columns[static_cast<std::size_t>(c)] != 0) widen(c);
  }
  return span;
}

std::vector<unsigned char> tile_marks(const float* rgba, int width, const std::array<int, 4>& rect) {
  const int across = tiles_across(rect[2]), down = tiles_across(rect[3]);
  std::vector<unsigned char> marks(static_cast<std::size_t>(across) * static_cast<std::size_t>(down), 0);
  for (int y = 0; y < rect[3]; ++y) {
    for (int x = 0; x < rect[2]; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(rect[1] + y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(rect[0] + x);
      if (rgba[pixel * 4 + 3] > 0.0f) {
        marks[static_cast<std::size_t>((y / kTileSize) * across + x / kTileSize)] = 1;
      }
    }
  }
  return marks;
}

void write_tile_view(const float* rgba, int width, const std::array<int, 4>& rect, float* out) {
  const int across = tiles_across(rect[2]), down = tiles_across(rect[3]);
  const std::vector<unsigned char> marks = tile_marks(rgba, width, rect);
  const std::vector<unsigned char> columns = column_marks(marks, across, down);
  TileSpan passes, inputs;  // the spans of the band `y` is in, found once a band
  for (int y = 0; y < rect[3]; ++y) {
    const int row = y / kTileSize, band = row / kTileBand;
    if (y == band * kTileBand * kTileSize) {
      passes = tile_span(marks, columns, across, down, band, TileDraw::passes);
      inputs = tile_span(marks, columns, across, down, band, TileDraw::inputs);
    }
    for (int x = 0; x < rect[2]; ++x) {
      const int column = x / kTileSize;
      const auto covers = [column](const TileSpan& span) { return column >= span.first && column <= span.last; };
      float* p = out + (static_cast<std::size_t>(rect[1] + y) * static_cast<std::size_t>(width) +
                        static_cast<std::size_t>(rect[0] + x)) * 4;
      p[0] = covers(passes) ? 1.0f : 0.0f;
      p[1] = covers(inputs) ? 1.0f : 0.0f;
      p[2] = marks[static_cast<std::size_t>(row * across + column)] != 0 ? 1.0f : 0.0f;
      p[3] = 1.0f;
    }
  }
}

}  // namespace sss::math
