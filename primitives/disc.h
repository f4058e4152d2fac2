// <disc center="0 0 0" normal="0 1 0" radius="1" inner-radius="0"/>
//   center        vector, default 0 0 0
//   normal        vector, default 0 1 0 (normalised on load)
//   radius        number > 0, default 1
//   inner-radius  number in [0, radius), default 0: a hole (an annulus, POV-Ray's
//                 hole_radius)
// A flat, one-layer surface: not a solid. Hit points with inner-radius <= |p − center| <=
// radius count (the rims belong to the disc). (u,v): world (object) units from the centre
// along the plane's tangent directions (planeTangents() in plane.h): for normal +y,
// u = x − cx and v = −(z − cz).
#pragma once

#include "shape.h"

namespace lucent {

class Disc final : public Shape {
 public:
  // Throws std::invalid_argument unless 0 <= innerRadius < radius and the normal is non-zero.
  Disc(const Vec3& center, const Vec3& unitNormal, double radius, double innerRadius);

  const char* kind() const override { return "disc"; }
  AABB bounds() const override;
  bool isSolid() const override { return false; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3&) const override { return false; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

 private:
  bool root(const Ray& ray, double& t) const;

  Vec3 center_, n_;
  double radius_, inner_;
  Vec3 t1_, t2_;
};

}  // namespace lucent
