// POV-Ray's uv_mapping: a texture, normal or map whose placement says `uv` reads its
// pattern at the shape's (u, v, 0) instead of the object point.
#pragma once

#include "primitives/hit.h"
#include "scenegraph/pattern.h"

namespace lucent {

// The surface as a uv-mapped pattern sees it: the object point is (u, v, 0) ((0, 0, 0) on a
// shape without (u,v), as an <image> reads (0,0) there), exact (no rounding error to carry).
inline SurfaceInfo uvMappedSurface(const SurfaceInfo& s) {
  SurfaceInfo t = s;
  t.pObject = s.hasUV ? Vec3(s.uv.x, s.uv.y, 0.0) : Vec3(0.0);
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
