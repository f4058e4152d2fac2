// The arrangements of POV-Ray's pavement pattern as data (pavement_layouts.cpp): which
// edges and corners of each cell of an arrangement's repeating block are a tile's border.
#pragma once

#include <cmath>

#include <cstdint>
#include <vector>

namespace lucent::pavement {

// How a cell's whole coordinates (xv, zv) find its place in the block. Without shearZ:
// r = zv mod period, xv moves by shift * (r / step), and the cell is
// (xv mod outer) + (r mod inner) * stride. With shearZ the roles swap: r = xv mod period,
// zv moves by shift * (r / step), and the cell is (r mod inner) + (zv mod outer) * stride.
struct Fold {
  bool shearZ = false;
  int period = 1;
  int shift = 0;
  int step = 1;
  int inner = 1;
  int outer = 1;
  int stride = 0;
};

// Cell flags. Squares: edges 0x01 (z = 1), 0x02 (x = 1), 0x04 (z = 0), 0x08 (x = 0); inner
// corners 0x10 (0, 1), 0x20 (1, 1), 0x40 (1, 0), 0x80 (0, 0). Triangles (vertices (0, 0),
// (1, 0), (1/2, sqrt(3)/2)): edges 0x01 left, 0x02 right, 0x04 bottom; 0x80 and the higher
// bits mark the vertices where a tile's border turns (see pavement.cpp).
struct Layout {
  Fold fold;
  std::vector<std::uint16_t> cells;
};

struct Layouts {
  const Layout* data = nullptr;
  int count = 0;
};

// The arrangements of a pavement of `sides` (3, 4, 6) with `tiles` cells a tile (1..6), in
// POV-Ray's order (pattern 1 first); none for other combinations.
Layouts layouts(int sides, int tiles);

// The flags of cell (xv, zv) of arrangement `number` (1..count).
unsigned flagsAt(int sides, int tiles, int number, long xv, long zv);

// A whole cell coordinate (already floored) as a long, for values within ±2^60; beyond
// that, and for NaN, 0: such a cast is undefined, and the layouts repeat anyway.
inline long cellIndex(double whole) {
  return std::fabs(whole) < 0x1p60 ? static_cast<long>(whole) : 0;
}

}  // namespace lucent::pavement
