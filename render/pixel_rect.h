// A rectangle of pixels in the full image's coordinates, half-open: columns [x0, x1), rows
// [y0, y1). Regions (--region), tiles of a resumable or distributed render and the part of
// an image a renderer is asked for are all one of these.
#pragma once

#include <algorithm>
#include <vector>

namespace lucent {

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  long long pixels() const { return static_cast<long long>(width()) * height(); }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  bool contains(const PixelRect& r) const {
    return r.x0 >= x0 && r.x1 <= x1 && r.y0 >= y0 && r.y1 <= y1;
  }
  // Grown by `margin` on every side, then cut to `bounds`.
  PixelRect grown(int margin, const PixelRect& bounds) const {
    return {std::max(x0 - margin, bounds.x0), std::max(y0 - margin, bounds.y0),
            std::min(x1 + margin, bounds.x1), std::min(y1 + margin, bounds.y1)};
  }
  bool operator==(const PixelRect& o) const {
    return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1;
  }
};

inline PixelRect wholeImage(int width, int height) { return {0, 0, width, height}; }

// `area` cut into tiles of tileSize x tileSize (smaller at its right and bottom edges), in
// row order: the order a render hands them out and a checkpoint lists them.
inline std::vector<PixelRect> tilesOf(const PixelRect& area, int tileSize) {
  std::vector<PixelRect> tiles;
  const int n = std::max(1, tileSize);
  for (int y = area.y0; y < area.y1; y += n)
    for (int x = area.x0; x < area.x1; x += n)
      tiles.push_back({x, y, std::min(x + n, area.x1), std::min(y + n, area.y1)});
  return tiles;
}

}  // namespace lucent
