// <blob threshold="1"> with <component type="sphere" center radius strength/> and
// <component type="cylinder" base cap radius strength/> children: POV-Ray 3.7's blob.
// Each component adds s·(1 − r²/R²)² within its radius R, 0 outside (s its strength, which
// may be negative): r is the distance to a sphere's centre; for a cylinder, the distance to
// its axis between base and cap and, beyond them, to the nearer end point (hemispherical
// ends). The solid is where the summed field exceeds the threshold (> 0). No (u,v), as in
// POV-Ray.
//
// Intersection, exactly, by root isolation: along the line each component's field is
// s·g(t)² with g quadratic in t on the interval where the line is within its radius (for
// a cylinder, three convex pieces: the body and the two end balls), so between consecutive
// entry and exit points of those intervals (sorted) the field is one quartic. On each such
// piece, expressed in t around the piece's midpoint so its coefficients are of the
// components' size, field − threshold is solved with primitives/polynomial.h (Yuksel's
// derivative splitting, robust at double and tangent roots). POV-Ray does the same
// decomposition (blob.cpp, after Wyvill & Trotman's "Ray-Tracing Soft Objects") but solves
// each piece with its general quartic solver. The field is C¹ everywhere (each term and
// its slope vanish at its radius), so a root at a piece's end is found from the signs at
// the ends, which are carried from piece to piece: crossings alternate by construction.
#pragma once

#include "blob_component.h"
#include "shape.h"

#include <vector>

namespace lucent {

class Blob final : public Shape {
 public:
  // Throws std::invalid_argument unless threshold > 0, there is at least one component,
  // every radius is > 0 and finite, every strength finite and a cylinder's ends differ.
  Blob(double threshold, std::vector<BlobComponent> components);

  const char* kind() const override { return "blob"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return field(p) > threshold_; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // The summed field at p and its gradient. For tests.
  double field(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  double threshold() const { return threshold_; }
  // Each component's |field| at p, in the components' order: POV-Ray's weights of the
  // components' textures there (a cylinder's body and ends add up to its one).
  void componentFields(const Vec3& p, std::vector<double>& out) const;
  size_t componentCount() const { return componentCount_; }

  // Where the field's support pieces are: a ball (optionally cut by a plane through its
  // centre: a cylinder's ends) or a cylinder's body.
  // A cylinder's three pieces share its base and axis, so that their bounds along a line
  // are the same numbers (a gap of one ulp between them would drop the field there).
  struct Piece {
    enum Kind { Ball, Body } kind = Ball;
    Vec3 c{0.0};                     // the ball's centre, or the body's base
    Vec3 base{0.0};                  // a cylinder's base
    Vec3 axis{0.0};                  // a cylinder's unit axis (zero for a sphere)
    double zlo = -kInf, zhi = kInf;  // the piece keeps zlo <= axis·(p − base) < zhi
    double r2 = 1.0;                 // radius²
    double s = 1.0;                  // strength
    // The component's own space, when it has a transform: q = toLocal·p + localOffset, and
    // every field above is in that space.
    bool local = false;
    Mat3 toLocal{1.0};
    Vec3 localOffset{0.0};
    uint32_t component = 0;  // the index of the component it is part of
  };

 private:
  // Walks the line over [lo, hi], calling emit(t, entering) at every crossing in order;
  // emit returns false to stop. Returns whether the point at lo is inside.
  template <class Emit>
  bool walk(const Ray& ray, double lo, double hi, Emit&& emit) const;

  double threshold_;
  std::vector<Piece> pieces_;
  AABB bounds_;
  double scale_ = 1.0;  // the largest extent of the bounds, for error bounds
  size_t componentCount_ = 0;
};

}  // namespace lucent
