// <torus major="1" minor="0.25"/>
//   major  number > 0, default 1: radius of the circle the tube's centre follows
//   minor  number > 0, default 0.25: radius of the tube
// A solid ring in the xz-plane around the y axis, centred at the origin (POV-Ray's torus):
// the quartic (|p|² + R² − r²)² − 4R²(x² + z²) = 0, inside where it is negative. When
// minor > major (a spindle torus) that keeps POV-Ray's quartic surface, whose solid is the
// outer "apple" minus the inner "lemon". No (u,v).
//
// Intersection: the origin is first moved along the ray to its closest approach to the
// centre (so the coefficients are of the torus's size however far the ray starts), the
// quartic in that shifted, unit-speed parameter is solved on the chord of the bounding
// sphere by recursive derivative splitting (polynomial.h), and every root is then polished
// by Newton in double precision on the original ray, evaluating the quartic in its factored
// form ((ρ − R)² + y² − r²)·((ρ + R)² + y² − r²), ρ = √(x² + z²), whose small factor has
// no cancellation at the scale of R. Tangent (double) roots are polished as the minimum of
// the quartic along the ray instead, where its derivative vanishes.
#pragma once

#include "shape.h"

namespace lucent {

class Torus final : public Shape {
 public:
  // Throws std::invalid_argument unless both radii are positive.
  Torus(double major, double minor);

  const char* kind() const override { return "torus"; }
  AABB bounds() const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  // Every root of the whole line, ascending, a tangent root listed twice (so the line
  // alternates out/in starting outside). Returns the count (at most 4). For tests.
  int lineRoots(const Ray& ray, double t[4]) const;

 private:
  // Whether the line o + s·dn (dn unit, s in (-L, L)) surely misses the torus: a test of
  // its hull, so that lines near it skip the quartic.
  bool missesHull(const Vec3& o, const Vec3& dn, double a2, double a1, double a0, double L) const;

  double R_, r_;
};

}  // namespace lucent
