// POV-Ray's uv_mapping: a texture, normal or map whose placement says `uv` reads its
// pattern at the shape's (u, v, 0) instead of the object point.
#pragma once

#include "primitives/hit.h"
#include "scenegraph/pattern.h"

namespace lucent {

// The point a uv-mapped pattern reads at the surface, and the surface as such a pattern sees
// it: the object point is POV-Ray's (u, v, 0)
// (SurfaceInfo::mappedUV, which the world fills in for leaves whose material asks; a
// surface made without it, as by a test, reads its own (u, v) or (0, 0, 0) without),
// exact (no rounding error to carry).
inline Vec3 uvPointOf(const SurfaceInfo& s) {
  return s.hasMappedUV ? Vec3(s.mappedUV.x, s.mappedUV.y, 0.0)
         : s.hasUV     ? Vec3(s.uv.x, s.uv.y, 0.0)
                       : Vec3(0.0);
}
inline SurfaceInfo uvMappedSurface(const SurfaceInfo& s) {
  SurfaceInfo t = s;
  t.pObject = uvPointOf(s);
  t.pError = Vec3(0.0);
  return t;
}

// `s` itself, or its uv-mapped view when the placement asks for it (kept in `scratch`).
inline const SurfaceInfo& surfaceFor(const PatternPlacement& place, const SurfaceInfo& s,
                                     SurfaceInfo& scratch) {
  if (!place.uv) return s;
  scratch = uvMappedSurface(s);
  return scratch;
}

}  // namespace lucent
