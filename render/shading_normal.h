// The contract's normal perturbations (<normal> and <bump-map> in a material): the shading normal
// bent by a pattern's slope in the shape's object space. Only shading sees it; hit points, shadows
// and CSG keep the geometric surface.
#pragma once

#include "texture.h"

#include "scenegraph/pattern.h"

#include "primitives/hit.h"
#include "primitives/transform.h"

namespace lucent {

// n: the unit shading normal already facing the viewer (v, unit, towards the viewer).
// Returns the perturbed unit normal in the world. A perturbed normal that would face away
// from the viewer (a deep bump seen at a grazing angle) is not used: the surface keeps n
// there, so no shading point ever looks at its own back; unless normal.keepFacingAway
// (POV-Ray's rule), which keeps it.
Vec3 perturbedShadingNormal(const NormalSpec& normal, const Transform& worldFromObject,
                            const SurfaceInfo& surface, const Vec3& n, const Vec3& v);

// The same for a <bump-map> (render/bump_map.h) with its loaded image: read at the hit's
// (u,v), or at (0,0) on a shape without one (as an <image> is), in world space; or
// projected from its pattern space, where the normal is bent (as POV-Ray's bump_map).
Vec3 bumpedShadingNormal(const ImageMap& map, const BumpMapSpec& bump,
                         const Transform& worldFromObject, const SurfaceInfo& surface,
                         const Vec3& n, const Vec3& v);

}  // namespace lucent
