// <sphere center="0 0 0" radius="1"/>
//   center  vector, default 0 0 0
//   radius  number > 0, default 1
// A solid ball. (u,v): u = φ/2π with φ = atan2(x, z) + π the longitude about +y, so
// u = 0.5 faces +z (the default camera) and u grows towards +x, the seam lies at −z;
// v = 1 − θ/π with θ the angle from the +y pole (v = 1 at the top, 0 at the bottom), so an
// image's top row lands on the north pole, as in pbrt and POV-Ray's spherical map.
#pragma once

#include "shape.h"
#include "span.h"

namespace lucent {

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

  const Vec3& center() const { return center_; }
  double radius() const { return radius_; }

 private:
  // Where the whole line is inside (both roots); false when it misses.
  bool span(const Ray& ray, Span& out) const;

  Vec3 center_;
  double radius_;
};

}  // namespace lucent
