// Where a pattern is evaluated: the object point carried into pattern space, then displaced
// by the warps and turbulence (POV-Ray 3.7's warp list: warps.cpp, Warp_EPoint).
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// m·(p, 1), summed in POV-Ray's order (MInvTransPoint): x·m0 + y·m1 + z·m2 + m3.
Vec3 toPatternSpace(const Mat4& patternFromObject, const Vec3& objectPoint);

// Whether turbulence moves the point of this type: POV-Ray leaves marble's and wood's
// point alone and applies their turbulence inside the pattern.
constexpr bool turbulenceDisplaces(PatternType type) {
  return !patternTypeInfo(type).turbulenceInside;
}

// The pattern-space point carried through the warps, plus dturbulence·turbulence (per axis) when
// `displace` and the turbulence is not zero. Hexagon and brick take their point from here (displace
// = true).
Vec3 warpPoint(const PatternPlacement& placement, const Vec3& objectPoint, bool displace = true);

}  // namespace lucent
