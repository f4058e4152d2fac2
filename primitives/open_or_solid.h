// The closest hit and the crossings of a shape that is either an open surface (at most two
// roots, `sideRoots`) or a convex solid (one span, `solidSpan`), both found on the ray
// carried into the shape's frame (`local`): what the cylinder and the cone share.
#pragma once

#include "span.h"

namespace lucent {

template <class SideRoots, class SolidSpan>
bool intersectOpenOrSolid(bool open, const Ray& local, SideRoots sideRoots, SolidSpan solidSpan,
                          const Ray& ray, const Shape* shape, Hit& hit) {
  if (open) {
    SurfaceRoot roots[2];
    int n = sideRoots(local, roots);
    return intersectRoots(roots, n, ray, shape, hit);
  }
  Span s;
  return solidSpan(local, s) && intersectSpan(s, ray, shape, hit);
}

template <class SideRoots, class SolidSpan>
void crossingsOpenOrSolid(bool open, const Ray& local, SideRoots sideRoots, SolidSpan solidSpan,
                          const Ray& ray, const Shape* shape, CrossingList& out) {
  if (open) {
    SurfaceRoot roots[2];
    int n = sideRoots(local, roots);
    crossingsOfRoots(roots, n, ray, shape, out);
    return;
  }
  Span s;
  if (!solidSpan(local, s)) s = Span();
  crossingsOfSpan(s, ray, shape, out);
}

}  // namespace lucent
