// POV-Ray 3.7's tilings 1 to 18 (pattern.cpp, J. Grimbert's tiling patterns), restated:
// each tiling folds the point into one fundamental cell by its translations and mirrors,
// then measures how far the point is from the edges of the tile it landed in. The values
// follow POV-Ray's arithmetic step by step, so that they agree to rounding; the odd
// constants just above a band's start (0.500000000001, 2.0000001, ...) are POV-Ray's, kept
// because they decide which colour an edge gets. Tilings 19 to 27 are in tiling_more.cpp.
#include "tiling.h"
#include "tiling_shapes.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace tiling {

double wrap(double v, double period) { return v - period * std::floor(v / period); }

// The lozenge tiling's last fold and measure, shared with tiling 5 (whose rhombi are
// lozenges in three orientations): in the strip 0 <= z <= sqrt(3)/2 with x near 0, 1 minus
// the scaled distance to the nearer of the lozenge's two edges: 1 on them, 0 at its centre.
double lozengeInStrip(double x, double z) {
  if (2.0 * z > kS3h) {
    z = kS3h - z;
    x = 1.5 - x;
  }
  if (x > 0.75) x -= 1.0;
  if (x != 0.0 && z / x > kS3) {
    z = kS3h - z;
    x = 0.5 - x;
  }
  const double d1 = 1.0 - z * 4.0 * kS3 / 3.0;
  const double d2 = 1.0 - std::fabs(kS3 * x - z) * kS3 * 2.0 / 3.0;
  return std::max(d1, d2);
}

// A 2x1 rectangle with its long side along z (alongZ) or x, the point relative to the
// middle of its long side's centre line: 0 on the middle half of that line, 1 on the edges.
double rectangleEdge(double x, double z, bool alongZ) {
  if (alongZ) return std::max(2.0 * std::fabs(x - 0.5), 2.0 * (std::max(std::fabs(z), 0.5) - 0.5));
  return std::max(2.0 * (std::max(std::fabs(x), 0.5) - 0.5), 2.0 * std::fabs(z - 0.5));
}

double triangleThird(double x, double z, int flip) {
  if (x != 0.0) {
    if (z / x > kS3) {  // inside the neighbouring triangle of the other orientation
      z = kS3h - z;
      x = 0.5 - x;
      flip ^= 1;
    }
  } else {
    z = kS3h - z;
    x = 0.5;
    flip ^= 1;
  }
  const double d1 = 1.0 - z * 2 * kS3;
  const double d2 = 1.0 - (kS3 * x - z) * kS3;
  return (flip + std::max(d1, d2)) / 3.0;
}

double hexagonThird(double x, double z, double floor) {
  const double d1 = 2 + 2 * (z * kS3);
  const double d2 = 2 + 2 * (kS3 * x + z - kS3h) * kS3h;
  return std::max(5.0 - std::min(d1, d2), floor) / 3.0;
}

}  // namespace tiling

namespace {

using namespace tiling;

// Tiling 1: unit squares; 0 at each centre, 1 on the edges (the larger of |x| and |z| from
// the centre, doubled).
double squares(double x, double z) {
  auto edge = [](double v) {
    v = std::fabs(v);
    v -= std::floor(v);
    return 2.0 * std::fabs(v - 0.5);
  };
  return std::max(edge(x), edge(z));
}

// Tiling 2: regular hexagons of side 1 with two vertices on the x axis, centres 3 apart
// along x and sqrt(3) apart along z. Folded to a twelfth of a hexagon around the corner
// (1, sqrt(3)/2); 0 at centres, 1 on edges.
double hexagons(double x, double z) {
  x = wrap(x + 0.5, 3.0);
  z = wrap(z, kS3);
  if (z > kS3h) z = kS3 - z;
  if (x > 1.5) {  // the half-period shifted row
    x -= 1.5;
    z = kS3h - z;
  }
  if (kS3 * x + z < kS3h) {  // the neighbour's corner: reflect into this hexagon
    x = 0.5 - x;
    z = kS3h - z;
  }
  if (x > 1.0) x = 2.0 - x;
  const double d1 = 1.0 - z / kS3h;
  const double d2 = 1.0 - (kS3 * x + z - kS3h) / kS3;
  return std::clamp(std::max(d1, d2), 0.0, 1.0);
}

// Tiling 3: equilateral triangles of side 1 (one side along x), pointing up and down.
// Up triangles take [0, 0.5], down ones [0.5, 1]; each 1/2 band falls from its edges
// to its centre.
double triangles(double x, double z) {
  x = wrap(x, 1.0);
  z = wrap(z, kS3);
  int down = 0;
  if (z > kS3h) {
    z = kS3 - z;
    down ^= 1;
  }
  if (x > 0.5) x = 1.0 - x;
  if (x != 0.0) {
    if (z / x > kS3) {  // inside the neighbouring triangle of the other orientation
      z = kS3h - z;
      x = 0.5 - x;
      down ^= 1;
    }
  } else {  // on the line x = 0 POV-Ray moves the point without changing the orientation
    z = kS3h - z;
    x = 0.5;
  }
  const double d1 = 1.0 - z * 2 * kS3;
  const double d2 = 1.0 - (kS3 * x - z) * kS3;
  return down / 2.0 + 0.5 * std::max(d1, d2);
}

// Tiling 4: lozenges (60-degree rhombi of side 1, long diagonal along x), all alike.
double lozenges(double x, double z) {
  x = wrap(x, 1.0);
  z = wrap(z, kS3);
  if (z > kS3h) {  // the next row sits half a period over
    z -= kS3h;
    x += 0.5;
  }
  return lozengeInStrip(x, z);
}

// Tiling 5: the same rhombi in three orientations (the "tumbling blocks" of three faces of
// a cube around each hexagon of tiling 2): one third of [0, 1] per orientation.
double rhombi(double x, double z) {
  x = wrap(x + 0.5, 3.0);
  z = wrap(z, kS3);
  int orientation = 0;
  if (z > kS3h) {
    z = kS3 - z;
    orientation = 2 - orientation;
  }
  if (x > 1.5) {
    x -= 1.5;
    z = kS3h - z;
    orientation = 2 - orientation;
  }
  if (x < 0.5) {
    x = 1.0 - x;
    orientation = 2 - orientation;
  }
  x -= 0.5;
  if (x == 0.0 || z / x > kS3) {  // the rhombus standing at 60 degrees: turn it down
    const double rx = x / 2.0 + z * kS3h;
    const double rz = z / 2.0 - x * kS3h;
    x = rx;
    z = rz;
    orientation = 1;
  }
  double v = lozengeInStrip(x, z) / 3.0;
  v += orientation / 3.0;
  return std::clamp(v, 0.0, 1.0);
}

// One 2x1 rectangle of a block of rectangles: the offset that puts the point relative to
// the rectangle's reference corner, and its direction.
struct RectangleCell {
  signed char dx, dz;
  bool alongZ;
};

// Tiling 6: 2x1 rectangles in a 4x4 block, horizontal and vertical ones interlocking
// (a basket weave of single bricks): horizontal [0, 0.5], vertical [0.5, 1].
double rectangles(double x, double z) {
  // Which rectangle each unit cell of the 4x4 block belongs to, row by row (z), then x.
  static constexpr RectangleCell kBlock[16] = {
      {0, 1, true},  {2, 0, false}, {2, 0, false}, {3, 0, true},   // z in [0, 1)
      {0, 1, true},  {1, 2, true},  {3, 1, false}, {3, 1, false},  // [1, 2)
      {0, 2, false}, {1, 2, true},  {2, 3, true},  {4, 2, false},  // [2, 3)
      {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 4, true}};  // [3, 4)
  x = wrap(x, 4.0);
  z = wrap(z, 4.0);
  const int cell = static_cast<int>(x) + static_cast<int>(z) * 4;
  bool alongZ = true;  // a point wrapped to the block's far edge is left unshifted
  if (cell >= 0 && cell < 16) {
    x -= kBlock[cell].dx;
    z -= kBlock[cell].dz;
    alongZ = kBlock[cell].alongZ;
  }
  return rectangleEdge(x, z, alongZ) / 2.0 + (alongZ ? 1.0 : 0.0) / 2.0;
}

// Tiling 7: regular octagons and small squares (the truncated square tiling), period
// 1 + sqrt(2). Squares take [0, 0.5), octagons (0.5, 1].
double octagonsSquares(double x, double z) {
  const double period = kS2 + 1.0, centre = kS2h + 0.5;
  z = std::fabs(wrap(z, period) - centre);
  x = std::fabs(wrap(x, period) - centre);
  if (z > x) std::swap(x, z);
  if (x + z < kS2h) return (x + z) / kS2;  // the square between four octagons
  const double d1 = 1.0 - z;
  const double d2 = (kS2 + kS2h - (x + z)) / kS2;
  return std::max(0.500000000001, std::max(d1, d2));
}

// Tiling 8: rows of unit squares between rows of equilateral triangles (the elongated
// triangular tiling). Squares take [2/3, 1], up and down triangles the two lower thirds.
double squaresTriangles(double x, double z) {
  x = wrap(x, 1.0);
  z = wrap(z, 2.0 + kS3);
  if (z > kS3h + 1.0) {  // the second square-and-triangle row, half a square over
    z -= kS3h + 1.0;
    x += x > 0.5 ? -0.5 : 0.5;
  }
  if (x > 0.5) x = 1.0 - x;
  z -= 1.0;
  if (z > 0.0) return triangleThird(x, z, 0);  // the triangle row
  if (z < -0.5) z = -1.0 - z;                  // the square row
  if (x > 0.5) x = 1.0 - x;
  const double dx = std::min(2 + 2 * kS3 * std::fabs(x), 3.0);
  const double dz = std::min(2 + 2 * kS3 * std::fabs(z), 3.0);
  return (5.0000001 - std::min(dx, dz)) / 3.0;
}

// Tiling 9: regular hexagons of side 1 with a triangle in each gap (the trihexagonal
// tiling). Up and down triangles the lower two thirds, hexagons the top third.
double hexagonsTriangles(double x, double z) {
  x = wrap(x + 0.5, 2.0);
  z = wrap(z, 2.0 * kS3);
  int down = 0;
  if (z > kS3) {
    z -= kS3;
    x += x < 1.0 ? 1.0 : -1.0;
  }
  if (z > kS3h) {
    z = kS3 - z;
    down ^= 1;
  }
  if (x > 1.0) x = 2.0 - x;
  if (kS3 * x + z < kS3h) {  // the triangle at the corner
    const double d1 = 1.0 - z * 2 * kS3;
    const double d2 = 1.0 + (kS3 * x + z - kS3h) * kS3;
    return (down + std::max(d1, d2)) / 3.0;
  }
  return hexagonThird(x, z, 2.0000001);
}

// Tiling 10: unit squares, every other row shifted by half a square (a running bond).
double squaresOffset(double x, double z) {
  z = wrap(z, 2.0);
  if (z > 1.0) {
    x += 0.5;
    z -= 1.0;
  }
  x -= std::floor(x);
  return std::max(2 * std::fabs(x - 0.5), 2 * std::fabs(z - 0.5));
}

// One tile of a 3x3 block of a unit square and 2x1 rectangles: 0 the square, 1 a rectangle
// along x, 2 along z (also its value band, in thirds).
struct PinwheelCell {
  signed char dx, dz, kind;
};

// Tilings 11 and 12: a unit square with four 2x1 rectangles turning around it (a
// pinwheel), in the 3x3 block x, z (tiling 12 mirrors the block into 6x6).
double pinwheel(double x, double z) {
  static constexpr PinwheelCell kBlock[9] = {{0, 1, 2}, {2, 0, 1}, {2, 0, 1},   // z in [0, 1)
                                             {0, 1, 2}, {1, 1, 0}, {2, 2, 2},   // [1, 2)
                                             {1, 2, 1}, {1, 2, 1}, {2, 2, 2}};  // [2, 3)
  const int cell = static_cast<int>(x) + static_cast<int>(z) * 3;
  int kind = 2;
  if (cell >= 0 && cell < 9) {
    x -= kBlock[cell].dx;
    z -= kBlock[cell].dz;
    kind = kBlock[cell].kind;
  }
  double m;
  if (kind == 0) m = std::max(2.0 * std::fabs(x - 0.5), 2.0 * std::fabs(z - 0.5));
  else m = rectangleEdge(x, z, kind == 2);
  return (m + kind) / 3.0;
}

double squareRectangles(double x, double z) { return pinwheel(wrap(x, 3.0), wrap(z, 3.0)); }

double rectangleSquares(double x, double z) {
  return pinwheel(std::fabs(wrap(x, 6.0) - 3.0), std::fabs(wrap(z, 6.0) - 3.0));
}

// Tilings 13 and 14 fold to the quarter 0 <= x, z < 2 of a cell of side 4 / sqrt(2): a
// square in the middle ringed by four squares cut by its diagonals.
struct FoldedQuarter {
  double x, z;
  int cell;  // 0 the middle square, 1 beside it along x, 2 along z, 3 the corner
};
FoldedQuarter foldQuarter(double x, double z) {
  x = std::fabs(wrap(x * kS2, 4.0) - 2.0);
  z = std::fabs(wrap(z * kS2, 4.0) - 2.0);
  return {x, z, static_cast<int>(x) + static_cast<int>(z) * 2};
}

// Tiling 13: squares, each ringed by four triangles' worth of a rotated square: the middle
// square [0, 1/3], the pieces beside it along x [2/3, 1] and along z [1/3, 2/3].
double squaresInternal(double x0, double z0) {
  const auto [x, z, cell] = foldQuarter(x0, z0);
  auto alongX = [&] {
    return std::max((2.0 + std::fabs(1.5 - x) * 2.0) / 3.0, (3.0 - kS2 * std::fabs(x - z)) / 3.0);
  };
  auto alongZ = [&] {
    return std::max((1.0 + std::fabs(1.5 - z) * 2.0) / 3.0, (2.0 - kS2 * std::fabs(x - z)) / 3.0);
  };
  switch (cell) {
    case 0:
      return std::max(std::max(x - 0.5, 0.0) * 2.0, std::max(z - 0.5, 0.0) * 2.0) / 3.0;
    case 1:
      return z > 0.5 ? alongX() : (2.0 + std::fabs(1.5 - x) * 2.0) / 3.0;
    case 2:
      return x > 0.5 ? alongZ() : (1.0 + std::fabs(1.5 - z) * 2.0) / 3.0;
    case 3:
      return x > z ? alongX() : alongZ();
    default:
      return 0.0;
  }
}

// Tiling 14: tiling 13 with the four pieces around a square told apart by side: fifths,
// the square the top one, the pieces on the -x, +x, -z and +z sides the four below.
double squaresInternal5(double x0, double z0) {
  const int sideX = wrap(x0 * kS2, 4.0) - 2.0 < 0 ? 1 : 0;
  const int sideZ = wrap(z0 * kS2, 4.0) - 2.0 < 0 ? 2 : 3;
  const auto [x, z, cell] = foldQuarter(x0, z0);
  auto alongX = [&] {
    return std::max(std::fabs(1.5 - x) * 2.0, 1.0 - kS2 * std::fabs(z - x)) + sideX;
  };
  auto alongZ = [&] {
    return std::max(std::fabs(1.5 - z) * 2.0, 1.0 - kS2 * std::fabs(x - z)) + sideZ;
  };
  switch (cell) {
    case 0:
      return (4.000001 + std::max(std::max(x - 0.5, 0.0) * 2.0, std::max(z - 0.5, 0.0) * 2.0)) /
             5.0;
    case 1:
      return (z > 0.5 ? alongX() : std::fabs(1.5 - x) * 2.0 + sideX) / 5.0;
    case 2:
      return (x > 0.5 ? alongZ() : std::fabs(1.5 - z) * 2.0 + sideZ) / 5.0;
    case 3:
      return (x > z ? alongX() : alongZ()) / 5.0;
    default:
      return 0.0;
  }
}

// Tiling 15: 2x2 squares with unit squares in their gaps, in a 5x5 block. Unit squares
// [0, 0.5], big ones just above 0.5.
double squaresDouble(double x, double z) {
  struct Cell {
    signed char dx, dz;
    bool big;
  };
  static constexpr Cell kBlock[25] = {
      {0, 0, false}, {2, 0, true},  {2, 0, true},  {4, 1, true},  {4, 1, true},   // z [0, 1)
      {1, 2, true},  {1, 2, true},  {2, 1, false}, {4, 1, true},  {4, 1, true},   // [1, 2)
      {1, 2, true},  {1, 2, true},  {3, 3, true},  {3, 3, true},  {4, 2, false},  // [2, 3)
      {0, 4, true},  {1, 3, false}, {3, 3, true},  {3, 3, true},  {5, 4, true},   // [3, 4)
      {0, 4, true},  {2, 5, true},  {2, 5, true},  {3, 4, false}, {5, 4, true}};  // [4, 5)
  x = wrap(x, 5.0);
  z = wrap(z, 5.0);
  const int cell = static_cast<int>(x) + static_cast<int>(z) * 5;
  bool big = true;
  if (cell >= 0 && cell < 25) {
    x -= kBlock[cell].dx;
    z -= kBlock[cell].dz;
    big = kBlock[cell].big;
  }
  if (!big) return std::max(2 * std::fabs(x - 0.5), 2 * std::fabs(z - 0.5)) / 2.0;
  const double m =
      std::max(2 * (std::max(std::fabs(x), 0.5) - 0.5), 2 * (std::max(std::fabs(z), 0.5) - 0.5));
  return m / 2.0 + 0.50000001;
}

// Tiling 18: pairs of 2x1 rectangles, side by side, the pairs alternating direction in a
// 4x4 block (a basket weave). Rectangles along x [0, 0.5], along z [0.5, 1].
double rectanglePairs(double x, double z) {
  static constexpr RectangleCell kBlock[16] = {
      {0, 1, true},  {1, 1, true},  {3, 0, false}, {3, 0, false},  // z in [0, 1)
      {0, 1, true},  {1, 1, true},  {3, 1, false}, {3, 1, false},  // [1, 2)
      {1, 2, false}, {1, 2, false}, {2, 3, true},  {3, 3, true},   // [2, 3)
      {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 3, true}};  // [3, 4)
  x = wrap(x, 4.0);
  z = wrap(z, 4.0);
  const int cell = static_cast<int>(x) + static_cast<int>(z) * 4;
  bool alongZ = true;
  if (cell >= 0 && cell < 16) {
    x -= kBlock[cell].dx;
    z -= kBlock[cell].dz;
    alongZ = kBlock[cell].alongZ;
  }
  return (rectangleEdge(x, z, alongZ) + (alongZ ? 1.0 : 0.0)) / 2.0;
}

}  // namespace

double tilingValue(int number, const Vec3& p) {
  const double x = p.x, z = p.z;
  switch (number) {
    case 2:
      return hexagons(x, z);
    case 3:
      return triangles(x, z);
    case 4:
      return lozenges(x, z);
    case 5:
      return rhombi(x, z);
    case 6:
      return rectangles(x, z);
    case 7:
      return octagonsSquares(x, z);
    case 8:
      return squaresTriangles(x, z);
    case 9:
      return hexagonsTriangles(x, z);
    case 10:
      return squaresOffset(x, z);
    case 11:
      return squareRectangles(x, z);
    case 12:
      return rectangleSquares(x, z);
    case 13:
      return squaresInternal(x, z);
    case 14:
      return squaresInternal5(x, z);
    case 15:
      return squaresDouble(x, z);
    case 16:
      return hexagonsSquaresTriangles(x, z, false);
    case 17:
      return hexagonsSquaresTriangles(x, z, true);
    case 18:
      return rectanglePairs(x, z);
    default:
      if (number >= 19 && number <= kTilingCount) return moreTilings(number, x, z);
      return squares(x, z);
  }
}

}  // namespace lucent
