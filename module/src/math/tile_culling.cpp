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

}  // namespace sss::math
