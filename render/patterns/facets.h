// POV-Ray 3.7's facets normal (normal.cpp, facets): flat facets on curved surfaces, from
// crackle's random points.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The bent pattern-space normal (not normalised) for the pattern-space normal n (any
// length) at the pattern point p. Without coords: the nearest random point to
// normalise(n)/size, itself the new normal. With coords c: the nearest random point q to
// p/size, then normalise(n) + c·(g − (g·n̂)n̂), g the noise gradient at q.
Vec3 facetsNormal(const FacetsParams& facets, const Vec3& n, const Vec3& p);

}  // namespace lucent
