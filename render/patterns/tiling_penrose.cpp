// The Penrose tilings of POV-Ray 3.7 (pattern.cpp). Each is drawn by deflation: the
// tiling around the origin has five-fold symmetry, so the point is first turned and
// mirrored into one tenth of the plane; its distance then says how many inflations of the
// central tile (by phi^2, or phi^4 for P1) reach it; the point is scaled down by as many
// and walked down the substitution rules, each step picking the sub-tile that holds it and
// carrying the point into that sub-tile's frame scaled by phi. At depth 0 the value comes
// from the distance to the tile's edges (with POV-Ray's empirical factors 5.55 and 4.46),
// each kind of tile clamped to a band of its own just inside the band's ends.
#include "tiling_penrose.h"

#include <algorithm>
#include <cmath>

namespace lucent::tiling {

namespace {

// Trigonometry of multiples of 18 degrees and the golden ratio.
constexpr double kSin18 = 0.30901699437494742410, kCos18 = 0.95105651629515357212;
constexpr double kSin36 = 0.58778525229247312917, kCos36 = 0.80901699437494742410;
constexpr double kSin72 = kCos18, kCos72 = kSin18;
constexpr double kSin108 = kSin72, kCos108 = -kCos72;
constexpr double kSin144 = kSin36, kCos144 = -kCos36;
constexpr double kSin162 = kSin18, kCos162 = -kCos18;
constexpr double kTan18 = 0.32491969623290632616, kTan36 = 0.72654252800536088590;
constexpr double kTan54 = 1.3763819204711735382, kTan72 = 3.0776835371752534026;
constexpr double kTan108 = -kTan72, kTan126 = -kTan54, kTan144 = -kTan36, kTan162 = -kTan18;
constexpr double kPhi = 1.6180339887498948482, kInvPhi = 0.61803398874989484820;
constexpr double kPhiSquared = 2.6180339887498948482, kInvPhiSquared = 0.38196601125010515180;
constexpr double kBandGap = 1e-6;  // keeps each tile's value strictly inside its band
constexpr double kCentre = 1e-10;  // POV-Ray's EPSILON: the origin itself is 1

double max3(double a, double b, double c) { return std::max(std::max(a, b), c); }

// Turn (and mirror) a point into the tenth 0 <= angle <= 36 degrees of the plane, by the
// five-fold symmetry about the origin; r is the point's distance from it.
void intoTenth(double& x, double& z, double r) {
  z = std::fabs(z);
  if (x < r * kCos36) {
    const bool far = x < r * kCos108;
    const double s = far ? kSin144 : kSin72, c = far ? kCos144 : kCos72;
    const double rx = x * c + z * s;
    const double rz = z * c - x * s;
    x = rx;
    z = std::fabs(rz);
  }
}
void intoTenth(double& x, double& z) { intoTenth(x, z, std::sqrt(x * x + z * z)); }

// --- P2 and P3: half kites and half darts (a half rhombus is one of each, deflated) ---

double halfDart(double x, double z, int depth, bool rhombi);

double halfKite(double x, double z, int depth, bool rhombi) {
  z = std::fabs(z);
  if (depth > 0) {
    if (z < (x - kInvPhi) * kTan144) return halfDart(x * kPhi, z * kPhi, depth - 1, rhombi);
    x -= kCos36;
    z -= kSin36;
    const double rx = x * kCos108 - z * kSin108;
    const double rz = z * kCos108 + x * kSin108;
    return halfKite(rx * kPhi, rz * kPhi, depth - 1, rhombi);
  }
  if (rhombi) {
    if (z < (x - kInvPhi) * kTan72) {  // part of a wide rhombus: the upper band
      const double d1 = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * 5.55;
      const double d2 = std::fabs(kSin108 * (x - 1) - kCos108 * z) * 5.55;
      return max3(1.0 - d1 / 2, 1.0 - d2 / 2, 0.5 + kBandGap);
    }
    const double d1 = std::fabs(z) * 5.55;
    const double d2 = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * 5.55;
    return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kBandGap);
  }
  const double d1 = std::fabs(kSin36 * x - kCos36 * z) * 4.46;  // a kite: the lower band
  const double d2 = std::fabs(kSin108 * (x - 1) - kCos108 * z) * 4.46;
  return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kBandGap);
}

double halfDart(double x, double z, int depth, bool rhombi) {
  z = std::fabs(z);
  if (depth > 0) {
    if (z < (x - kInvPhi) * kTan108) {
      const double rx = x * kCos36 + z * kSin36;
      const double rz = z * kCos36 - x * kSin36;
      return halfKite(rx * kPhi, rz * kPhi, depth - 1, rhombi);
    }
    x -= 1;
    const double rx = x * kCos144 + z * kSin144;
    const double rz = z * kCos144 - x * kSin144;
    return halfDart(rx * kPhi, rz * kPhi, depth - 1, rhombi);
  }
  if (rhombi) {  // part of a narrow rhombus: the lower band
    const double d1 = std::fabs(kSin36 * x - kCos36 * z) * 5.55;
    const double d2 = std::fabs(kSin144 * (x - 1) - kCos144 * z) * 5.55;
    return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kBandGap);
  }
  const double d1 = std::fabs(z) * 4.46;  // a dart: the upper band
  const double d2 = std::fabs(kSin144 * (x - 1) - kCos144 * z) * 4.46;
  return max3(1.0 - d1 / 2, 1.0 - d2 / 2, 0.5 + kBandGap);
}

// --- P1: pentagons of three kinds (by their neighbours), stars, boats and diamonds,
// in sixths of [0, 1] in that order ---

double pentagon2(double x, double z, int depth, bool insideQuad);
double pentagon3(double x, double z, int depth, bool insideWedge);
double star(double x, double z, int depth);
double boat(double x, double z, int depth, bool insideWedge);
double diamond(double x, double z, int depth, bool sideA);

// The distance measure from a pentagon's edge, the point turned into its tenth.
double pentagonEdge(double x) { return std::fabs(x - 0.5 / kTan36) * 5.55 * kInvPhi; }

// The value band [k/6, (k+1)/6] of a tile kind, `d` its edge measure.
double band(int k, double d) {
  return std::min(std::max((k + 1.0) / 6 - d / 6, k / 6.0 + kBandGap), (k + 1.0) / 6 - kBandGap);
}

double pentagon1(double x, double z, int depth) {
  z = std::fabs(z);
  intoTenth(x, z);
  if (depth == 0) return std::min(std::max(1.0 / 6 - pentagonEdge(x) / 6, 0.0), 1.0 / 6 - kBandGap);
  if (z < (x - 0.5 / kTan36) * kTan54 + 0.5) {
    const double rx = x - 0.5 / kTan36 - kInvPhi * 0.5 * kCos72 / kSin36;
    return pentagon2(rx * kPhi, z * kPhi, depth - 1, false);
  }
  const double rx = x * kCos36 + z * kSin36;
  const double rz = z * kCos36 - x * kSin36;
  return star(rx * kPhi, rz * kPhi, depth - 1);
}

double pentagon2(double x, double z, int depth, bool insideQuad) {
  z = std::fabs(z);
  if (depth == 0) {
    intoTenth(x, z);
    return band(1, pentagonEdge(x));
  }
  if (insideQuad) {
    if (z < (x - kInvPhiSquared * 0.5 / kSin36) * kTan54)
      return pentagon1((x - 0.5 / kSin36) * kPhi, z * kPhi, depth - 1);
    if (z < (x - kInvPhiSquared * 0.5 / kSin36) * kTan162)
      return diamond(-x * kPhi, z * kPhi, depth - 1, true);
    const double rx = x * kCos108 - z * kSin108 + kInvPhi * 0.5 / kSin36;
    const double rz = z * kCos108 + x * kSin108;
    return pentagon2(rx * kPhi, rz * kPhi, depth - 1, true);
  }
  if (z < (x + 0.5 / kSin36) * kTan18) {
    const double rx = x + 0.5 / kSin36 - kInvPhiSquared * 0.5 / kSin36;
    return diamond(rx * kPhi, z * kPhi, depth - 1, false);
  }
  const double rx = -(x * kCos36 + z * kSin36) - kCos72 * 0.5 / kSin36;
  const double rz = (z * kCos36 - x * kSin36) - kSin72 * 0.5 / kSin36;
  return pentagon3(rx * kPhi, rz * kPhi, depth - 1, false);
}

double pentagon3(double x, double z, int depth, bool insideWedge) {
  z = std::fabs(z);
  if (depth == 0) {
    intoTenth(x, z);
    return band(2, pentagonEdge(x));
  }
  if (insideWedge && x > kInvPhiSquared * 0.5 * kCos72 / kSin36) {
    const double rx = -(x - kInvPhiSquared * 0.5 * kCos72 / kSin36 - kInvPhi * 0.5 / kTan36);
    return pentagon2(rx * kPhi, z * kPhi, depth - 1, true);
  }
  if (!insideWedge && x < 0.5 * kCos108 / kSin36) {
    const double rx = x * kCos144 + z * kSin144 - 0.5 / kSin36;
    const double rz = z * kCos144 - x * kSin144;
    return pentagon2(rx * kPhi, rz * kPhi, depth - 1, false);
  }
  if (!insideWedge && z > (x - kInvPhiSquared * 0.5 / kSin36) * kTan126) {
    const double rx = -(x * kCos36 - z * kSin36) - kCos72 * 0.5 / kSin36;
    const double rz = (z * kCos36 + x * kSin36) - kSin72 * 0.5 / kSin36;
    return pentagon3(rx * kPhi, rz * kPhi, depth - 1, false);
  }
  return boat(x * kPhi, z * kPhi, depth - 1, insideWedge);
}

// The distance measure from a star's (or a boat's) point edge.
double starEdge(double x, double z) {
  return std::fabs(kSin162 * (x - kPhi * 0.5 / kSin36) - kCos162 * z) * 5.55 * kInvPhi;
}

double star(double x, double z, int depth) {
  z = std::fabs(z);
  if (depth == 0) return band(3, starEdge(x, z));
  if (x < kInvPhi * 0.5 / kTan36) return pentagon1(x * kPhi, z * kPhi, depth - 1);
  const double rx = -(x - kInvPhi / kTan36);
  return pentagon3(rx * kPhi, z * kPhi, depth - 1, true);
}

double boat(double x, double z, int depth, bool insideWedge) {
  z = std::fabs(z);
  if (depth == 0) {
    const double d1 = std::fabs(x - kInvPhi * 0.5 * kCos72 / kSin36) * 5.55 * kInvPhi;
    x = -x;
    intoTenth(x, z);
    const double d2 = starEdge(x, z);
    return std::min(max3(5.0 / 6 - d1 / 6, 5.0 / 6 - d2 / 6, 4.0 / 6 + kBandGap),
                    5.0 / 6 - kBandGap);
  }
  if (insideWedge && x > kPhi * 0.5 * kCos108 / kSin36)
    return pentagon1(-x * kPhi, z * kPhi, depth - 1);
  double rx = x, rz = z;
  if (!insideWedge) {
    rx = x * kCos72 - z * kSin72;
    rz = z * kCos72 + x * kSin72;
  }
  rx += 0.5 / kSin36;
  return pentagon3(rx * kPhi, rz * kPhi, depth - 1, true);
}

double diamond(double x, double z, int depth, bool sideA) {
  z = std::fabs(z);
  if (depth == 0) {
    const double d = std::fabs(kSin18 * (x + kInvPhi * 0.5 / kSin36) - kCos18 * z) * 5.55 * kInvPhi;
    return band(5, d);
  }
  if (sideA) return pentagon1(x * kPhi, z * kPhi, depth - 1);
  return pentagon3(x * kPhi, z * kPhi, depth - 1, true);
}

}  // namespace

double penroseP2P3(double x, double z, bool rhombi) {
  const double r = std::sqrt(x * x + z * z);
  if (r <= kCentre) return 1.0;
  intoTenth(x, z, r);
  if (rhombi) {
    x *= kInvPhi;
    z *= kInvPhi;
  }
  const double reach = std::fabs(kSin108 * x - kCos108 * z) / kCos18;
  int depth = std::max(0, static_cast<int>(std::ceil(std::log(reach) / std::log(kPhiSquared))));
  x *= std::pow(kInvPhiSquared, depth);
  z *= std::pow(kInvPhiSquared, depth);
  if (depth % 2) {  // an odd number of inflations turns the central star by 36 degrees
    const double rx = x * kCos36 + z * kSin36;
    const double rz = z * kCos36 - x * kSin36;
    x = rx;
    z = std::fabs(rz);
  }
  return halfKite(x, z, depth * 2, rhombi);
}

double penroseP1(double x, double z) {
  const double r = std::sqrt(x * x + z * z);
  if (r <= kCentre) return 1.0;
  intoTenth(x, z, r);
  const double reach = x * 2 * kTan36;
  const int depth = std::max(
      0, static_cast<int>(std::ceil(std::log(reach) / std::log(kPhiSquared * kPhiSquared))));
  x *= std::pow(kInvPhiSquared * kInvPhiSquared, depth);
  z *= std::pow(kInvPhiSquared * kInvPhiSquared, depth);
  return pentagon1(x, z, depth * 4);
}

}  // namespace lucent::tiling
