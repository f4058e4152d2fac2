// The contract's normal perturbation (<normal> in a material): the shading normal bent by
// a pattern's slope in the shape's object space. Only shading sees it; hit points,
// shadows and CSG keep the geometric surface.
#pragma once

#include "scenegraph/pattern.h"

#include "primitives/hit.h"
#include "primitives/transform.h"

namespace lucent {

// n: the unit shading normal already facing the viewer (v, unit, towards the viewer).
// Returns the perturbed unit normal in the world. A perturbed normal that would face away
// from the viewer (a deep bump seen at a grazing angle) is not used: the surface keeps n
// there, so no shading point ever looks at its own back.
Vec3 perturbedShadingNormal(const NormalSpec& normal, const Transform& worldFromObject,
                            const SurfaceInfo& surface, const Vec3& n, const Vec3& v);

}  // namespace lucent
