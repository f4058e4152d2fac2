// <ovus bottom-radius="1" top-radius="0.5"/>
//   bottom-radius  number >= 0, default 1: the sphere centred at the origin
//   top-radius     number >= 0, default 0.5: the sphere centred at (0, bottom-radius, 0)
//   (not both 0)
// POV-Ray 3.7's ovus, an egg about the y axis: the two spheres joined by the surface of
// revolution of a circular arc of radius C, twice the larger radius, whose circle holds both
// spheres and touches each (its centre (−H, V) in a meridian, on the far side of the axis:
// the inner "lemon" sheet of a spindle torus). Below the bottom seam the surface is the bottom
// sphere, above the top seam the top sphere, between them the arc. With top-radius at or
// above twice bottom-radius the top sphere holds the bottom one: the ovus is that sphere
// (POV-Ray substitutes it, with a warning). (u,v): POV-Ray's, a sphere's about
// (0, top-radius/2, 0).
//
// The solid is the union of the two balls and the lemon's slab between the seams, each of
// them convex and the union convex (its profile is a convex C¹ curve), so along a line it
// is one span, from the least entry to the greatest exit of the three. The lemon's span is
// exact without a quartic: h(p) = sqrt((ρ + H)² + (y − V)²) − C, the greatest distance from
// p to the ring of the arc's centres less C, is convex in p, so along the line it has at
// most two roots, which Newton's method reaches monotonically from outside (from each end
// of the line's stretch within the slab and the lemon's bounding ball). No apple roots to
// sort out, and a tangent ray converges to its double root.
#pragma once

#include "shape.h"
#include "span.h"

namespace lucent {

class Ovus final : public Shape {
 public:
  // The pieces the spans come from (Hit::part).
  enum Part : uint32_t { kBottom = 0, kTop = 1, kLemon = 2 };

  // The derived quantities of POV-Ray's parser, in a meridian (ρ, y).
  struct Geometry {
    double bottomRadius = 0.0, topRadius = 0.0;
    bool sphereOnly = false;  // top-radius >= 2·bottom-radius: the top sphere alone
    bool lemon = false;       // a connecting surface between the seams
    double connecting = 0.0;  // C: the arc's radius
    double horizontal = 0.0;  // H: the arc's centre at ρ = −H ...
    double vertical = 0.0;    // V: ... and y = V
    double bottomSeam = 0.0;  // y where the arc meets the bottom sphere
    double topSeam = 0.0;     // y where it meets the top sphere
  };
  static Geometry geometryOf(double bottomRadius, double topRadius);

  // Throws std::invalid_argument unless both radii are finite and >= 0, not both 0.
  Ovus(double bottomRadius, double topRadius);

  const char* kind() const override { return "ovus"; }
  AABB bounds() const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  const Geometry& geometry() const { return g_; }

 private:
  // Where the whole line is inside; false when it misses.
  bool span(const Ray& ray, Span& out) const;
  // The line's span inside the lemon between the seams.
  bool lemonSpan(const Ray& ray, double& tIn, double& tOut) const;

  Geometry g_;
};

}  // namespace lucent
