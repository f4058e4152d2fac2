// Where a secondary ray starts: Lucent's one strategy against self-intersection.
#pragma once

#include "math.h"

namespace lucent {

// The origin for a ray leaving surface point p (absolute error bound pError, per component)
// in direction w: p moved along the geometric normal ng, to the side w points to, just far
// enough to leave the box of points p may really be, and then rounded one more ulp away
// (Pharr, Jakob, Humphreys, "Physically Based Rendering", 3rd ed., §3.9.5). The new ray
// keeps tmin = 0. No scene-dependent epsilon is involved: every shape's surface() returns
// a conservative pError, so the offset scales with the rounding error of the hit itself.
Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& ng, const Vec3& w);

// The neighbouring doubles of v towards +∞ and −∞: std::nextafter(v, ±∞) without the call
// (NaN stays NaN; +∞ stays +∞ going up, −∞ stays −∞ going down).
double nextUp(double v);
double nextDown(double v);

}  // namespace lucent
