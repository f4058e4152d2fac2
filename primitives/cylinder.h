// <cylinder base="0 0 0" cap="0 1 0" radius="1" open="false"/>
//   base, cap  vectors, the centres of the two end discs (defaults 0 0 0 and 0 1 0)
//   radius     number > 0, default 1
//   open       boolean, default false: true removes the end discs and with them the
//              volume (an open cylinder is a surface, not a solid), as in POV-Ray
// No (u,v). Hit::part: 0 the side, 1 the base disc, 2 the cap disc. Normals point away
// from the axis on the side, along base − cap and cap − base on the discs.
#pragma once

#include "axis_frame.h"
#include "open_or_solid.h"
#include "span.h"

namespace lucent {

class Cylinder final : public OpenOrSolidShape<Cylinder> {
 public:
  // Throws std::invalid_argument when base == cap or the radius is not positive.
  Cylinder(const Vec3& base, const Vec3& cap, double radius, bool open);

  const char* kind() const override { return "cylinder"; }
  AABB bounds() const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

 private:
  friend class OpenOrSolidShape<Cylinder>;                      // intersect() and crossings()
  bool solidSpan(const Ray& local, Span& out) const;            // closed cylinder
  int sideRoots(const Ray& local, SurfaceRoot roots[2]) const;  // open cylinder

  Vec3 base_, cap_;
  double radius_, height_;
  bool open_;
  AxisFrame frame_;
};

}  // namespace lucent
