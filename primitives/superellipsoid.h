// <superellipsoid e="1" n="1"/>
//   e  number in [0.01, 10], default 1: the east-west exponent
//   n  number in [0.01, 10], default 1: the north-south exponent
// A solid filling [-1, 1]³ (POV-Ray's superellipsoid { <e, n> }, with its axes: the poles
// lie on the z axis): the points where (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) < 1.
// e = n = 1 is the unit sphere, small exponents tend to the cube, 2 to the octahedron;
// above 2 the faces curve inwards (the shape is no longer convex). No (u,v), as in POV-Ray.
//
// Evaluated as a gauge N(p) = ‖(‖(|x|, |y|)‖_p, |z|)‖_q, p = 2/e, q = 2/n (N − 1 has the
// sign of the equation above; N is 1-homogeneous, increasing in |x|, |y|, |z|, and each
// ‖(a, b)‖ is computed as max·(1 + (min/max)^p)^(1/p), which neither overflows nor
// underflows at any exponent).
//
// Intersection, by bounded root isolation (no fixed steps): the ray is clipped to the box
// [-B, B]³ (B slightly above 1, where N > 1) and cut at the planes x = 0, y = 0, z = 0.
// On each piece |x|, |y|, |z| are affine in t, so (interval analysis through monotonicity)
// N over a stretch of the piece lies between N at the low and at the high corner of
// those affine ranges, and dN/dt = Σ ∂N/∂X·X' with each ∂N/∂X a product of powers of
// ratios (X/R, R/N) that are themselves monotone in X, Y, Z: its lower and upper bounds
// come from the same corners; the mean-value form N(a) + [dN/dt]·(t − a) narrows the
// range where the corners are loose (a ray parallel to a flat face). A stretch whose range
// of N excludes 1 (by more than N's rounding) holds no root; one whose derivative bound has
// one sign is monotone and holds one root exactly when its ends differ in sign, as does
// one over which N varies less than its rounding; any other stretch is halved. For e, n
// <= 2, N is a norm and so convex along the line: its tangents bound it from below, so
// Newton's steps from an end of the clipped line outside the shape never pass a root (they
// climb to the first one, quadratically; a step meeting a rising slope or leaving the line
// proves a miss), and the line is decided from the ends alone in a few steps; the general
// search remains for what they leave undecided. Each step evaluates N and its gradient
// from the same four powers (no pow at all for e or n = 1 or 2). Each root is then
// refined by Newton steps kept inside its bracket (bisection when a step leaves it or
// converges slowly), to the last bits of double. Every crossing is a sign change between
// two evaluated points, each evaluated once, so crossings alternate and agree with
// inside() by construction. (Interval Newton-style isolation, e.g. Moore, Kearfott & Cloud,
// "Introduction to Interval Analysis", ch. 8; POV-Ray's own method, from the same plane
// cuts, samples chords and may miss roots.)
#pragma once

#include "shape.h"

#include <utility>

namespace lucent {

class Superellipsoid final : public Shape {
 public:
  static constexpr double kMinExponent = 0.01;
  static constexpr double kMaxExponent = 10.0;

  // Throws std::invalid_argument unless both exponents lie in [kMinExponent, kMaxExponent].
  Superellipsoid(double e, double n);

  const char* kind() const override { return "superellipsoid"; }
  AABB bounds() const override;
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // The gauge N (N < 1 inside, N = 1 on the surface) and its gradient (not normalised;
  // components may be infinite at the creases of exponents above 2). For tests.
  double gauge(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const { return gaugeAndGradient(p).second; }
  // Both from the same four powers: with S = 1 + (min/max)^p, the ratio powers of the
  // gradient are (max/R)^(p−1) = S^(1/p)/S and (min/R)^(p−1) = (min/max)^(p−1)·S^(1/p)/S,
  // and likewise one level up: no pow beyond those N itself needs.
  std::pair<double, Vec3> gaugeAndGradient(const Vec3& p) const;

  // The roots within [lo, hi] of the line o + t·d, ascending, and whether the point at lo
  // is inside (the count of roots before any t tells inside from outside). At most
  // kMaxRoots; `firstAfter` stops at the first root strictly above it. For tests.
  static constexpr int kMaxRoots = 32;
  struct Roots {
    double t[kMaxRoots];
    int count = 0;
    bool startsInside = false;
  };
  void roots(const Ray& ray, double lo, double hi, Roots& out, double firstAfter = kInf) const;

  double e() const { return e_; }
  double n() const { return n_; }

 private:
  double e_, n_;
  double p_, invP_, q_, invQ_;  // p = 2/e, q = 2/n
};

}  // namespace lucent
