// The surface of an implicit solid (the points where F < 0: quadric, poly) at a hit: shared
// so that each such shape adds only what is its own to the point's error bound.
#pragma once

#include "shape.h"

namespace lucent {

// The hit point p = ray.at(hit.t), the normal ∇F(p) normalized ((1, 0, 0) where the
// gradient vanishes, a singular point), and a point error of the rounding of t·d and of
// the origin, bounded generously by the size of the numbers involved.
inline SurfaceInfo implicitSurface(const Ray& ray, const Hit& hit, const Vec3& p,
                                   const Vec3& gradient) {
  SurfaceInfo s;
  s.p = p;
  const double len = glm::length(gradient);
  s.ng = len > 0.0 ? gradient / len : Vec3(1.0, 0.0, 0.0);
  s.ns = s.ng;
  s.pError = gamma(8) * (glm::abs(ray.o) + glm::abs(hit.t * ray.d)) + gamma(4) * glm::abs(p);
  return s;
}

}  // namespace lucent
