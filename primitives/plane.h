// <plane normal="0 1 0" offset="0"/>
//   normal  vector, default 0 1 0 (normalised on load)
//   offset  number, default 0
// The points x with normal·x = offset; the half-space normal·x < offset is inside (a solid,
// as in POV-Ray), so the normal points out of the solid. Unbounded: bounds() is
// AABB::everything().
// (u,v): coordinates in world (object) units along two fixed tangent directions, see
// planeTangents(): for the ground plane (normal +y), u = x and v = −z.
#pragma once

#include "shape.h"

namespace lucent {

// The tangent frame (t1, t2, n), right-handed, used for the (u,v) of planes and discs:
// t1 = normalize(h × n), t2 = n × t1, with the helper h = +y for normals within 45° of the
// horizontal (walls: u to the right seen from the front, v = +y up) and h = −z otherwise
// (floors: normal +y gives u = +x, v = −z, "up" away from the default camera).
void planeTangents(const Vec3& n, Vec3& t1, Vec3& t2);

class Plane final : public Shape {
 public:
  // The normal is normalised again (idempotent for the spec's unit normal). Throws
  // std::invalid_argument for a zero or non-finite normal.
  Plane(const Vec3& unitNormal, double offset);

  const char* kind() const override { return "plane"; }
  // Unbounded; a plane square to an axis bounds its half-space on that axis only, so a
  // solid it cuts (a slab of a cylinder, in CSG or a clip) gets a finite box.
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

 private:
  Vec3 n_;
  double offset_;
  AABB bounds_ = AABB::everything();
  Vec3 t1_, t2_;
};

}  // namespace lucent
