// <sphere center="0 0 0" radius="1"/>
//   center  vector, default 0 0 0
//   radius  number > 0, default 1
// A solid ball. (u,v): u = φ/2π with φ = atan2(x, z) + π the longitude about +y, so
// u = 0.5 faces +z (the default camera) and u grows towards +x, the seam lies at −z;
// v = 1 − θ/π with θ the angle from the +y pole (v = 1 at the top, 0 at the bottom), so an
// image's top row lands on the north pole, as in pbrt and POV-Ray's spherical map.
#pragma once

#include "quadratic.h"
#include "shape.h"
#include "span.h"

namespace lucent {

// The one ray test of a sphere, shared by Sphere and by the world-space spheres an
// Aggregate keeps in its leaves (aggregate.h), so both find the same hits to the last bit.
// The roots tIn <= tOut of |o + t·d − center|² = r2 along the whole line, by the
// precision-improved quadratic (Ray Tracing Gems ch. 7, quadratic.h); false when the line
// misses.
inline bool sphereRoots(const Vec3& center, double r2, const Ray& ray, double& tIn, double& tOut) {
  return solveDistanceQuadratic(ray.o - center, ray.d, r2, tIn, tOut);
}

// The closest hit's distance: the nearer root strictly inside (ray.tmin, ray.tmax), else
// the farther (intersectSpan's rule); false when neither is.
inline bool sphereHitDistance(const Vec3& center, double r2, const Ray& ray, double& t) {
  double tIn, tOut;
  if (!sphereRoots(center, r2, ray, tIn, tOut)) return false;
  if (ray.tmin < tIn && tIn < ray.tmax) t = tIn;
  else if (ray.tmin < tOut && tOut < ray.tmax) t = tOut;
  else return false;
  return true;
}

class Sphere final : public Shape {
 public:
  // Throws std::invalid_argument unless the radius is positive (and everything finite).
  Sphere(const Vec3& center, double radius);

  const char* kind() const override { return "sphere"; }
  AABB bounds() const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  const Vec3& center() const { return center_; }
  double radius() const { return radius_; }

 private:
  // Where the whole line is inside (both roots); false when it misses.
  bool span(const Ray& ray, Span& out) const;

  Vec3 center_;
  double radius_;
};

}  // namespace lucent
