// When two children's surfaces count as the same surface along a ray (docs/csg.md,
// "Coincident surfaces").
#pragma once

#include "primitives/math.h"
#include "primitives/ray.h"

#include <algorithm>
#include <cfloat>

namespace lucent {

// Crossings of different children whose distances differ by at most this window are one
// event. Two children that reach the same surface through the same arithmetic (same
// shape, same transform) give bit-identical t; through different arithmetic (a box of
// size 2 scaled by 0.5 against a box of size 1, a sphere against a mesh) their t differ by
// rounding: a few units in the last place of the coordinates of the points involved. The
// window is 2^10 of those units, measured on the largest coordinate of the ray's origin
// and of the point at t, and converted to t by the direction's largest component, so it
// scales with the scene and stays far below any feature a user can model (about 2e-13 of
// the scene's coordinates; the CSG tests hold hits to 1e-6 relative).
inline double coincidenceWindow(const Ray& ray, double t) {
  auto maxAbs = [](const Vec3& v) {
    return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
  };
  const double dMax = maxAbs(ray.d);
  const double extent = maxAbs(ray.o) + std::abs(t) * dMax;
  return 1024.0 * DBL_EPSILON * extent / dMax;
}

}  // namespace lucent
