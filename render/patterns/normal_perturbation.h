// Perturbed surface normals: POV-Ray 3.7's `normal { PATTERN depth }` (normal.cpp,
// Perturb_Normal), with its default bump scaling.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// POV-Ray's `accuracy`: the step of the slope sampling (kept at its default).
constexpr double kNormalAccuracy = 0.02;

// The unit object-space normal at objPoint. `objNormal` must already face the viewer:
// POV-Ray flips the surface normal towards the incoming ray before perturbing it, and
// the perturbation is not symmetric under that flip.
//
// The normal is carried into pattern space (inverse transpose of the pattern transform)
// and normalised; bumps, dents, wrinkles, ripples and waves then add their own vector
// (facets puts its own in place, render/patterns/facets.h)
// (POV-Ray's functions of those names), any other type POV-Ray's slope estimate: the
// pattern value at four points 0.02 from the (turbulence-displaced) point along a regular
// tetrahedron's vertex directions, each pushing the normal along its direction by
// value·depth·−5. The result goes back to object space and is normalised. `depth` is
// POV-Ray's bump_size, used in single precision as POV-Ray stores it.
Vec3 perturbNormal(const NormalSpec& normal, const Vec3& objPoint, const Vec3& objNormal);

}  // namespace lucent
