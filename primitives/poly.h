// <poly order="2..35" coefficients="..."/>: the solid where a polynomial P(x, y, z) of
// degree 2 to 35 (POV-Ray's MAX_ORDER) is below 0, POV-Ray's poly { order, <coefficients> }
// with the same coefficients in the same order.
//
// POV-Ray's order: the terms x^i y^j z^k of degree at most n, with i descending, then j,
// then k (for n = 2: x², xy, xz, x, y², yz, y, z², z, 1); (n+1)(n+2)(n+3)/6 of them.
//
// Intersection: P along the line o + s·d is a polynomial of degree <= n in s, expanded
// exactly from the terms, together with the magnitudes of what each of its coefficients
// sums, from an origin shifted to the line's point closest to the object's origin (so the
// coefficients stay of the shape's size however far a ray starts). Its real roots on the
// whole line come from primitives/polynomial.h (monotone pieces between the derivative's
// roots, bracketed Newton: Yuksel, HPG 2022), inside Cauchy's or Fujiwara's bound of the roots
// (capped where the top power would overflow: 10^(250/n) from the line's closest point); each is
// polished by one Newton step on P evaluated at the point itself. A root is a crossing
// only where the sign of P differs on its two sides (a tangent ray touches without
// crossing), which also decides entering or leaving. The shape is unbounded, like
// POV-Ray's poly (clip it with a CSG intersection), but for an ellipsoid of order 2, which
// gets the quadric's exact box.
#pragma once

#include "shape.h"

#include <vector>

namespace lucent {

class Poly final : public Shape {
 public:
  static constexpr int kMaxOrder = 35;  // POV-Ray's MAX_ORDER
  static int termCount(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

  // Throws std::invalid_argument for an order outside 2 to 35, a wrong number of
  // coefficients, a non-finite one, or when every coefficient but the constant is 0.
  Poly(int order, const std::vector<double>& coefficients);

  const char* kind() const override { return "poly"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return value(p) < 0.0; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;

  // The sign changes of P along the ray's stretch [tmin, tmax] (a little wider), ascending
  // (room for the order), each marked entering (P turns negative) or not; startsInside
  // tells the state before the first.
  int lineCrossings(const Ray& ray, double t[kMaxOrder], bool entering[kMaxOrder],
                    bool& startsInside) const;

 private:
  struct Term {
    int i, j, k;  // the powers of x, y and z
    double c;
  };
  int order_;
  std::vector<Term> terms_;    // the non-zero ones
  std::vector<double> dense_;  // c_ijk at (i·(n+1) + j)·(n+1) + k, zero where absent
  AABB bounds_ = AABB::everything();

  // P(o + u·d) as a polynomial in u (degree order_), with its coefficients' magnitudes.
  void linePolynomial(const Vec3& o, const Vec3& d, double* c, double* cAbs) const;
};

}  // namespace lucent
