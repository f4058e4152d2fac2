// <julia-fractal c="1 0 0 0" algebra="quaternion" function="sqr" max-iteration="20"
//                precision="20" slice="0 0 0 1" distance="0"/>
// POV-Ray 3.7's julia_fractal: the 3-D slice of a 4-D Julia set (primitives/julia_map.h), a
// solid. Traced as POV-Ray traces it (fractal.cpp, taken as facts), so that its surface lies
// where POV-Ray's does:
//   - the ray (its direction made unit) is clipped to the sphere about the origin of the
//     map's radius (2 at most for quaternions, 4 for hypercomplex), starting 1e-7 past the
//     origin at the nearest; a start inside the set moves 2e-7 on and tests again;
//   - it marches by the step the map gives at each point (at least 1 / precision), until a
//     point's membership differs from the last's; the crossing is bisected between them
//     with POV-Ray's own inside test down to 1e-7, and the hit is the point on the inside
//     side (so a hit lies in the set, within 1e-7 of where the test changes);
//   - the march goes on from the point past the crossing for the further crossings (CSG).
//     POV-Ray then counts the depth from the crossing, not from that point (its later
//     crossings a part of a step too near); Lucent keeps the true depth.
// The normal is POV-Ray's, from the orbit of the hit point as POV-Ray's tests leave it
// (computed during the search, where POV-Ray computes it, and kept in the hit). Crossings alternate
// by construction; inside() is POV-Ray's inside test (for the hypercomplex functions started from
// (x, y, y), as POV-Ray 3.7's; the march's own test uses (x, y, z)).
#pragma once

#include "julia_map.h"
#include "shape.h"

namespace lucent {

class JuliaFractal final : public Shape {
 public:
  // Throws std::invalid_argument as JuliaMap does.
  explicit JuliaFractal(const JuliaParams& p);

  const char* kind() const override { return "julia-fractal"; }
  AABB bounds() const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  const JuliaMap& map() const { return map_; }

 private:
  // Calls onHit(t, entering, normal) for each crossing in order, the normal POV-Ray's (not
  // unit) computed there as POV-Ray computes it (false from onHit stops); returns
  // whether the march started inside the set (false when the ray misses the sphere).
  template <class OnHit>
  bool march(const Ray& ray, double tmax, OnHit&& onHit) const;

  JuliaMap map_;
};

}  // namespace lucent
