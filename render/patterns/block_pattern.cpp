#include "block_pattern.h"

#include <cmath>

namespace lucent {

namespace {

constexpr double kEpsilon = 1.0e-10;      // POV-Ray's EPSILON
constexpr double kXFactor = 0.5;          // each triangle split in half for the grid
constexpr double kZFactor = 0.866025404;  // √3/2 as POV-Ray writes it: a triangle's height

// POV-Ray's FLOOR macro: floor, written another way for negative values.
double povFloor(double x) { return x >= 0.0 ? std::floor(x) : (0.0 - std::floor(0.0 - x) - 1.0); }

// The fractional part the way POV-Ray's brick takes it: v − (int)v, then +1 below zero.
// std::trunc gives (int)'s value without its overflow for huge coordinates.
double brickFraction(double v) {
  v -= std::trunc(v);
  if (v < 0.0) v += 1.0;
  return v;
}

}  // namespace

int hexagonIndex(const Vec3& point) {
  double x = std::fabs(point.x);
  double z = point.z;
  if (!std::isfinite(x) || !std::isfinite(z)) return 0;
  // Below the x axis z is mapped so the tiling does not mirror; 5.196152424 is 6·√3/2
  // (the grid is six blocks high).
  z = z < 0.0 ? 5.196152424 - std::fabs(z) : z;
  double xs = x / kXFactor;
  double zs = z / kZFactor;
  xs -= std::floor(xs / 6.0) * 6.0;
  zs -= std::floor(zs / 6.0) * 6.0;
  const int xm = static_cast<int>(povFloor(xs)) % 6;
  const int zm = static_cast<int>(povFloor(zs)) % 6;

  int value = 0;
  switch (xm) {
    case 0:
    case 5:
      value = (zm == 1 || zm == 2) ? 1 : (zm == 3 || zm == 4) ? 2 : 0;
      break;
    case 2:
    case 3:
      value = (zm == 0 || zm == 1) ? 2 : (zm == 4 || zm == 5) ? 1 : 0;
      break;
    case 1:
    case 4: {
      // Blocks cut by a hexagon edge: flip the ones whose edge slopes down, then see
      // which side of the diagonal the point is on.
      double xl = xs - xm;
      const double zl = zs - zm;
      if ((xm + zm) % 2 == 1) xl = 1.0 - xl;
      if (xl == 0.0) xl = 0.0001;  // POV-Ray's guard against dividing by zero
      if (zl / xl < 1.0) value = (zm == 0 || zm == 3) ? 0 : (zm == 2 || zm == 5) ? 1 : 2;
      else value = (zm == 0 || zm == 3) ? 2 : (zm == 2 || zm == 5) ? 0 : 1;
      break;
    }
    default:
      break;
  }
  return value;
}

int brickIndex(const BrickSpec& brick, const Vec3& point) {
  const double mortar = static_cast<float>(brick.mortar - kEpsilon * 2.0);
  const double fudge = kEpsilon + mortar;
  const double x = point.x + fudge, y = point.y + fudge, z = point.z + fudge;
  const double width = brick.size.x, height = brick.size.y, depth = brick.size.z;
  const double mortarWidth = mortar / width;
  const double mortarHeight = mortar / height;
  const double mortarDepth = mortar / depth;

  // Horizontal mortar between rows.
  if (brickFraction(y / height) <= mortarHeight) return 0;
  // Which of a pair of rows (the second is shifted by half a brick).
  const double row = brickFraction((y / height) * 0.5);

  // Mortar at brick ends, across x then across z, in the row's own offset.
  if (brickFraction(x / width) <= mortarWidth && row <= 0.5) return 0;
  if (brickFraction((x / width) + 0.5) <= mortarWidth && row > 0.5) return 0;
  if (brickFraction(z / depth) <= mortarDepth && row > 0.5) return 0;
  if (brickFraction((z / depth) + 0.5) <= mortarDepth && row <= 0.5) return 0;
  return 1;
}

Color hexagonColor(const HexagonSpec& hexagon, const Vec3& patternPoint) {
  return hexagon.colors[hexagonIndex(patternPoint)];
}

Color brickColor(const BrickSpec& brick, const Vec3& patternPoint) {
  return brickIndex(brick, patternPoint) == 0 ? brick.color1 : brick.color2;
}

}  // namespace lucent
