// <cone base="0 0 0" base-radius="1" cap="0 1 0" cap-radius="0" open="false"/>
//   base, cap                 vectors, the centres of the two ends (defaults 0 0 0, 0 1 0)
//   base-radius, cap-radius   numbers >= 0, not both 0 (defaults 1 and 0): a pointed cone
//                             when one is 0, a truncated cone otherwise (equal radii give
//                             a cylinder)
//   open                      boolean, default false: true removes the end discs and the
//                             volume (a surface, not a solid), as in POV-Ray
// Only the nappe between base and cap exists (never the mirrored one beyond the apex).
// No (u,v). Hit::part: 0 the side, 1 the base disc, 2 the cap disc.
#pragma once

#include "axis_frame.h"
#include "open_or_solid.h"
#include "span.h"

namespace lucent {

class Cone final : public OpenOrSolidShape<Cone> {
 public:
  // Throws std::invalid_argument when base == cap, a radius is negative or both are 0.
  Cone(const Vec3& base, double baseRadius, const Vec3& cap, double capRadius, bool open);

  const char* kind() const override { return "cone"; }
  AABB bounds() const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

 private:
  friend class OpenOrSolidShape<Cone>;  // intersect() and crossings()
  // The side's quadratic along the line, in a parameter s shifted by tShift (t = tShift + s);
  // false when the line misses the cone's bounding sphere.
  struct Quadratic {
    double tShift, a, h, c;
    Vec3 o, d;  // the shifted local line
  };
  bool sideQuadratic(const Ray& local, Quadratic& q) const;
  bool solidSpan(const Ray& local, Span& out) const;
  int sideRoots(const Ray& local, SurfaceRoot roots[2]) const;
  double radiusAt(double z) const { return rBase_ + slope_ * z; }

  Vec3 base_, cap_;
  double rBase_, rCap_, height_, slope_;  // slope_ = dr/dz
  bool open_;
  AxisFrame frame_;
};

}  // namespace lucent
