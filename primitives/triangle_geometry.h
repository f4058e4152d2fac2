// The surface geometry of a triangle hit, shared by <triangle> and <mesh>.
#pragma once

#include "hit.h"

namespace lucent {

// p[3] the corners; n[3] unit vertex normals or null; uv[3] texture coordinates or null;
// b1, b2 the barycentric weights of p[1] and p[2].
// The hit point is interpolated from the corners with the barycentrics, not taken from the
// ray equation: its error is then bounded by gamma(7)·Σ|b_i·p_i| (pbrt-v3 §3.9.4), however
// far the ray came from.
// When the interpolated normal and the geometric one disagree in side, one is turned:
// normalFollowsShading = true turns the geometric normal (a loose triangle, whose winding
// means nothing), false turns the shading normal (a closed mesh, whose outward geometric
// normal is part of the solid's definition).
SurfaceInfo triangleSurface(const Vec3* p, const Vec3* n, const Vec2* uv, double b1, double b2,
                            bool normalFollowsShading);

}  // namespace lucent
