// <quadric a="A B C" b="D E F" c="G H I" d="J"/>
// The solid where Q(p) = A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J < 0
// (POV-Ray's quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }, whose Inside is Q ≤ 0). The normal is
// ∇Q normalised, pointing out of the solid; where ∇Q vanishes (a cone's apex) it is +x, as
// POV-Ray's. No (u,v). Bounded only when the quadratic part is positive definite (an
// ellipsoid): the box is then the ellipsoid's exact box; otherwise AABB::everything().
//
// Intersection: Q along the ray is the quadratic a·t² + 2h·t + c, solved without
// cancellation (quadratic.h) from a shifted origin (the ray's point closest to the
// quadric's centre, or to the origin when it has none), so that the coefficients are of
// the shape's size however far the ray starts; each root is then polished by one Newton
// step on Q evaluated at the point itself. Along the whole line Q is negative between the
// roots (a > 0), outside them (a < 0), on one side of the one root (a = 0), or never
// changes sign (a double root or no root: a tangent ray does not cross).
#pragma once

#include "shape.h"

namespace lucent {

struct QuadricCoefficients {
  Vec3 squares{0.0};      // A B C: x², y², z²
  Vec3 mixed{0.0};        // D E F: xy, xz, yz
  Vec3 linear{0.0};       // G H I: x, y, z
  double constant = 0.0;  // J
};

class Quadric final : public Shape {
 public:
  // Throws std::invalid_argument for a non-finite coefficient or when every coefficient
  // but J is 0 (no surface).
  explicit Quadric(const QuadricCoefficients& q);

  const char* kind() const override { return "quadric"; }
  AABB bounds() const override { return bounds_; }
  // Along an axis that Q holds only as a·t² + b·t (no mixed term with it), where the section
  // across it is an ellipse: within the clip's range of t, the widest section bounds the
  // rest (a cone, a hyperboloid or a paraboloid about an axis, cut to a slab).
  AABB boundsWithin(const AABB& clip) const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return value(p) < 0.0; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;

  // The sign changes of Q along the whole line, ascending, each marked entering (Q turns
  // negative) or not; returns how many (0 to 2), and in startsInside whether the line is
  // inside before the first one. For tests too.
  int lineCrossings(const Ray& ray, double t[2], bool entering[2], bool& startsInside) const;

 private:
  Mat3 m_{0.0};  // the symmetric matrix of the quadratic part: Q = pᵀMp + g·p + J
  Vec3 g_{0.0};
  double j_ = 0.0;
  Vec3 centre_{0.0};  // where ∇Q = 0 when M is invertible, else the origin
  AABB bounds_ = AABB::everything();

  void boundCylinder();
  // The box of the ellipse Qᵢⱼ(pᵢ, pⱼ) + constant ≤ 0 across axis k (pᵢ, pⱼ the other two
  // coordinates), unbounded along k; empty when there is no such point. False when the
  // section is not an ellipse or Q mixes p_k with the others.
  bool sectionBounds(int k, double constant, AABB& out) const;
};

}  // namespace lucent
