#include "offset.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace lucent {

// The next double up from v, as std::nextafter(v, +inf), by stepping its bit pattern
// (pbrt-v3 §3.9.2, NextFloatUp): std::nextafter is an out-of-line libm call that honours
// the floating-point environment, and it showed in profiles of renders dominated by
// area-light shadow rays (docs/performance-history.md).
double nextUp(double v) {
  if (std::isnan(v) || (std::isinf(v) && v > 0.0)) return v;
  if (v == 0.0) v = 0.0;  // −0 steps to the smallest positive value, like +0
  uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  bits = v >= 0.0 ? bits + 1 : bits - 1;
  std::memcpy(&v, &bits, sizeof bits);
  return v;
}

double nextDown(double v) { return -nextUp(-v); }

Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& ng, const Vec3& w) {
  // d is the distance along ng to the plane through the corner of the error box that lies
  // farthest along ng (pbrt-v3 §3.9.5, OffsetRayOrigin).
  double d = glm::dot(glm::abs(ng), pError);
  Vec3 side = glm::dot(w, ng) < 0.0 ? -ng : ng;
  Vec3 po = p + d * side;
  // The addition above may round back towards the surface: step one ulp further away.
  // Stepping by the sign of the side rather than of the offset (as pbrt does) also moves
  // the point when pError is 0 along the normal (a box face is exact), so the new origin
  // never lies on the surface it leaves.
  for (int i = 0; i < 3; ++i) {
    if (side[i] > 0.0) po[i] = nextUp(po[i]);
    else if (side[i] < 0.0) po[i] = nextDown(po[i]);
  }
  return po;
}

}  // namespace lucent
