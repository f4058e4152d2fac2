// POV-Ray 3.7's tilings 16, 17 and 19 to 27 (pattern.cpp), restated as in tiling.cpp:
// fold the point into a fundamental region, then measure it in the tile it lands in.
// The Penrose tilings (25 to 27) are found by deflation: from the point's distance to the
// centre, the number of inflation steps whose tile holds it, then tile by tile down the
// substitution rules to the smallest tile. The scale factors 5.55 and 4.46 of their edge
// measures are POV-Ray's (chosen by eye there), kept so that the values agree.
#include "tiling.h"
#include "tiling_penrose.h"
#include "tiling_shapes.h"

#include <algorithm>
#include <cmath>

namespace lucent::tiling {

namespace {

// Tilings 16 and 17 fold into the corner region 0 <= x, z <= 1 + sqrt(3)/2 of a hexagon
// (centre at (sqrt(3)/2, 1/2 + ...)) with a square and triangles; the flags record the
// mirrors and the turn used, which tell the orientations of squares and triangles apart.
struct HstFold {
  double x, z;
  int mirX = 0, mirZ = 0, turned = 0;
};

HstFold foldHexagonsSquaresTriangles(double x, double z) {
  HstFold f;
  x = wrap(x + 0.5, 3.0 + kS3);
  z = wrap(z, 2.0 * (1.0 + kS3));
  if (x > kS3h + 1.5) {  // the half-period shifted column
    x -= kS3h + 1.5;
    z += z < kS3 + 1.0 ? kS3h + 0.5 : -1 * (kS3h + 0.5);
  }
  if (z > kS3 + 1.0) z -= kS3 + 1.0;
  if (z > 0.5 + kS3h) {
    z = kS3 + 1.0 - z;
    f.mirZ ^= 1;
  }
  if (x > 1.0 + kS3h) {
    x = kS3 + 2.0 - x;
    f.mirX ^= 1;
  }
  if (kS3 * x + z < kS3h + 2.0 && x < 0.5 + kS3h) {
    // The lower left: turn by 60 degrees about (1 + sqrt(3)/2, 1/2 + sqrt(3)/2) onto the
    // square and triangle at the bottom.
    z -= 0.5 + kS3h;
    x -= 1.0 + kS3h;
    const double rx = x / 2.0 - z * kS3h;
    const double rz = z / 2.0 + x * kS3h;
    z = rz + (0.5 + kS3h);
    x = rx + (1.0 + kS3h);
    f.turned ^= 1;
    if (z < 0) z *= -1;
    if (x > 1.0 + kS3h) {
      x = kS3 + 2.0 - x;
      f.mirX ^= 1;
      f.mirZ ^= 1;
    }
  }
  f.x = x;
  f.z = z;
  return f;
}

}  // namespace

double hexagonsSquaresTriangles(double x0, double z0, bool sixBands) {
  HstFold f = foldHexagonsSquaresTriangles(x0, z0);
  double x = f.x, z = f.z;
  if (!(kS3 * x + z < kS3h + 2.0) && !(z < 0.5)) {  // the hexagon
    z = std::fabs(z - 0.5);
    x = std::fabs(x - kS3h);
    const double d = std::min(2 * z * kS3, (kS3 * x + z) * kS3 - 1.5);
    if (sixBands) return std::max(6.0 - d, 5.000001) / 6.0;
    return std::max(3.0 - d, 2.0000001) / 3.0;
  }
  if (!(z < 0.5)) return 0.0;
  if (x > kS3h + 0.5) {  // the square
    x -= kS3h + 0.5;
    z -= 0.5;
    const double m = std::max(std::max(1.0 + z * 2 * kS3, 0.0), std::max(1.0 - x * 2 * kS3, 0.0));
    if (!sixBands) return m / 3.0;
    return (m + f.turned * (1.000001 + ((f.mirX + f.mirZ) % 2))) / 6.0;
  }
  x = std::fabs(x - (kS3h + 0.5));  // the triangle
  const double m = std::max(2.0 - x * 2.0 * kS3, (kS3 * z + x) * kS3 + 0.5);
  if (!sixBands) return m / 3.0;
  return (((f.turned + f.mirX) % 2 ? 2.0 : 3.0) + m) / 6.0;
}

namespace {

// Tilings 19 and 20: hexagons of side 1 each ringed by triangles, in rows that step
// sideways by half a unit every 3 sqrt(3)/2 along z (the snub hexagonal tiling, right-
// and left-handed). Triangles of the two orientations take the lower two thirds.
double snubHexagonal(double x, double z, bool right) {
  int row = static_cast<int>(z / kS3h);  // truncated, as POV-Ray's int
  row /= 3;
  if (z < 0) row -= 1;
  x += (right ? 1 : -1) * (row / 2.0);
  z = wrap(z, 3 * kS3h);
  x = wrap(x + 7.0, 7.0);
  // Three moves bring each hexagon's neighbourhood onto the one at x in [0, 2.5).
  auto move = [&](bool when, double dx, double dz) {
    if (!when) return;
    x -= dx;
    z += dz;
  };
  if (right) {
    move(x > 4.5 && z > kS3, 4.5, -kS3h);
    move(x > 5.0 && z < kS3h, 5, kS3);
    move(x > 2.5 && z < kS3, 2.5, kS3h);
  } else {
    move(x > 2.0 && z < kS3h, 2.0, kS3);
    move(x > 4.5 && z < kS3, 4.5, kS3h);
    move(x > 2.5 && z > kS3, 2.5, -kS3h);
  }
  int flip = 0;
  int band = static_cast<int>(z / kS3h);
  if (band == 2) {
    band = 1;
    z = 2 * kS3 - z;
    flip ^= 1;
  }
  if (band == 0 || x > 2.0 || z + kS3 * x < kS3 || kS3 * x - z > kS3) {
    x = wrap(x, 1.0);
    z = wrap(z, kS3);
    if (z > kS3h) {
      z = kS3 - z;
      flip ^= 1;
    }
    if (x > 0.5) x = 1.0 - x;
    return triangleThird(x, z, flip);
  }
  z -= kS3h;  // the hexagon
  if (x > 1.0) x = 2.0 - x;
  return hexagonThird(x, z, 2.000001);
}

// Tiling 21: squares and triangles in the snub square tiling, period 1 + sqrt(3). Folded
// by two mirrors and a turn into one quarter; `gamma` numbers the triangle's orientation
// (sixths 0..4), squares of the two orientations the top two sixths.
double snubSquare(double x, double z) {
  int mirrored = 0, gamma = 0, mirX = 0;
  const double period = 1.0 + kS3, half = 0.5 + kS3h;
  x = wrap(x, period);
  z = wrap(z, period);
  if (z > half) {
    z = 1.0 + kS3 - z;
    mirrored ^= 1;
  }
  if (x > half) {
    x = 1.0 + kS3 - x;
    mirrored ^= 1;
    mirX = 1;
  }
  const int flopX = 2.0 * x + (kS3 - 1.0) * 2.0 * z / (kS3 + 1.0) > kS3 ? 1 : 0;
  const int flopZ = 2.0 * z * kS3 + (kS3 - 3.0) * 2.0 * x / (kS3 + 1.0) > kS3 ? 1 : 0;
  switch (flopX + 2 * flopZ) {
    case 0:
      gamma = 2 * mirX;
      break;
    case 1: {  // a quarter turn one way
      gamma = mirX ? 1 + 2 * mirrored : 3 - 2 * mirrored;
      const double t = x;
      x = z;
      z = kS3h + 0.5 - t;
      break;
    }
    case 2: {  // and the other
      gamma = mirX ? 3 - 2 * mirrored : 1 + 2 * mirrored;
      const double t = z;
      z = x;
      x = kS3h + 0.5 - t;
      break;
    }
    case 3:  // a half turn
      gamma = mirX ? 0 : 2;
      x = kS3h + 0.5 - x;
      z = kS3h + 0.5 - z;
      break;
  }
  if (x == 0.0) z = 0.0;
  double side = (z * 2 * kS3) - kS3 + x * 2;
  if (side < 0) {  // the triangle
    const double d = std::min(-1.5 / kS3 * side, 2.0 * x * kS3);
    return (gamma + 1.0 - d) / 6.0;
  }
  side = std::min(side * (1.5 / kS3), 1.0);  // the square
  if (mirrored) return std::min(std::max((-side + 6.0) / 6.0, 5.000001 / 6.0), 1.0);
  return std::max(std::min((-side + 5.0) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

// Tiling 22: regular dodecagons with triangles in the gaps (the truncated hexagonal
// tiling). Triangles of two orientations the lower two thirds, dodecagons the top.
double dodecagonsTriangles(double x, double z) {
  int flip = 0;
  x = wrap(x, 2.0 + kS3);
  z = wrap(z, 3.0 + 2.0 * kS3);
  if (z > kS3 + 1.5) {  // the next row, half a period over
    z -= kS3 + 1.5;
    x += (x < 1.0 + kS3h ? 1.0 : -1.0) * (1.0 + kS3h);
  }
  if (x > 1.0 + kS3h) x = 2.0 + kS3 - x;
  if (z > 1.0 + kS3h) {
    z = 2.0 + kS3 - z;
    flip ^= 1;
  }
  double d2 = x - kS3h - 0.5 + z * kS3;
  if (d2 < 0.0) {  // beyond the slanted mirror: reflect across it
    const double tx = x, tz = z;
    x = (1.0 + kS3) / 4.0 + 0.5 * tx - kS3h * tz;
    z = (3.0 + kS3) / 4.0 - kS3h * tx - 0.5 * tz;
    d2 *= -1.0;
  }
  const double d1 = z * 3.0;
  const double d3 = (z - kS3h - 0.5 + x * kS3) * kS3;
  d2 *= kS3;
  const double d4 = x * 3.0;
  if (d3 < 0.0) return (std::max(d3, -1.0) + (1 + flip)) / 3.0;  // the triangle
  const double d = std::min(std::min(std::min(std::min(d1, d2), d3), d4), 1.0);
  return (3.0000001 - d) / 3.0;
}

// Tilings 23 and 24: dodecagons, hexagons and squares (the truncated trihexagonal
// tiling). In thirds (23): hexagons, squares, dodecagons; in fifths (24) the squares of
// the two orientations are told apart and the dodecagons take the top fifth.
double dodecagonsHexagons(double x, double z, bool fifths) {
  int mirX = 0, mirZ = 0;
  x = wrap(x, 3.0 + kS3);
  z = wrap(z, 3.0 + 3.0 * kS3);
  if (z > 1.5 * kS3 + 1.5) {
    z -= 1.5 * kS3 + 1.5;
    x += (x < 1.5 + kS3h ? 1.0 : -1.0) * (1.5 + kS3h);
  }
  if (x > 1.5 + kS3h) {
    x = 3.0 + kS3 - x;
    mirX ^= 1;
  }
  if (z > 1.0 + kS3) {
    z = 2.0 + 2.0 * kS3 - z;
    mirZ ^= 1;
  }
  if (x - kS3h - 1.5 + z * kS3 < 0.0) {
    const double tx = x, tz = z;
    x = (3.0 + kS3) / 4.0 + 0.5 * tx - kS3h * tz;
    z = (3.0 + 3.0 * kS3) / 4.0 - kS3h * tx - 0.5 * tz;
  }
  const double d2 = x - kS3h - 2.5 + z * kS3;
  const double d1 = (z * 2.0) - kS3;
  const double d3 = z - 1.5 * kS3 - 0.5 + x * kS3;
  const double d4 = (x - 0.5) * 2.0;
  const double bands = fifths ? 5.0 : 3.0;
  if (d2 >= 0.0 && d1 >= 0.0 && d3 >= 0.0 && d4 >= 0.0) {  // the dodecagon
    const double d = std::min(std::min(std::min(std::min(d1, d2), d3), d4), 1.0);
    return ((fifths ? 5.000001 : 3.000001) - d) / bands;
  }
  const double d5 = 2 * z - 2 * kS3 - 1.0;
  if (d5 >= 0) return (2.0 - std::min(d5, -d4)) / bands;  // the square above
  const double d6 = kS3 * x - z - kS3h + 0.5;
  const double d7 = d6 - 2.0;
  switch ((d6 >= 0 ? 0 : 1) + (d7 >= 0.0 ? 2 : 0)) {
    case 1:  // the hexagon on the left
      return (1.0 - std::min(std::min(std::min(-d6, -d3), -d5), 1.0)) / bands;
    case 2:  // the hexagon below
      return (1.0 - std::min(std::min(d7, -d1), 1.0)) / bands;
    default: {  // the slanted square
      const double d = std::min(std::min(d6, -d2), -d7);
      return (fifths ? (mirZ + mirX) % 2 + 3.0 - d : 2.0 - d) / bands;
    }
  }
}

}  // namespace

double moreTilings(int number, double x, double z) {
  switch (number) {
    case 19:
      return snubHexagonal(x, z, true);
    case 20:
      return snubHexagonal(x, z, false);
    case 21:
      return snubSquare(x, z);
    case 22:
      return dodecagonsTriangles(x, z);
    case 23:
      return dodecagonsHexagons(x, z, false);
    case 24:
      return dodecagonsHexagons(x, z, true);
    case 25:
      return penroseP1(x, z);
    case 26:
      return penroseP2P3(x, z, false);
    default:
      return penroseP2P3(x, z, true);
  }
}

}  // namespace lucent::tiling
