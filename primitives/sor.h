// <sor points="x y ..." open="false"/>: POV-Ray 3.7's surface of revolution. Points
// P0 … P(n−1) (n ≥ 4); P0 and P(n−1) only steer. Segment i (0 ≤ i < n − 3) spans
// y in [P(i+1).y, P(i+2).y] with r² = f(y), the cubic that takes P(i+1).x² and P(i+2).x²
// at its ends with the slopes 2x·Δx/Δy of the central differences there (POV-Ray's
// Hermite construction, Compute_Sor; Burger and Gillies, "Rapid ray tracing of general
// surfaces of revolution", CG International 1989). Here each f is kept in w = y − y(i+1)
// rather than in y, the same cubic with coefficients of the segment's own size. The solid
// is x² + z² ≤ f(y) between the lowest and highest joint, closed by the discs at the bottom
// and the top unless `open` (then a surface: no inside, as Lucent's open prism).
//
// Intersection, exact per segment: along the ray, x² + z² is quadratic in t and f(y(t))
// cubic, so g(t) = x(t)² + z(t)² − f(y(t)) is a cubic whose roots on the segment's
// t-interval (its heights, clipped to its bounding cylinder) are isolated by
// primitives/polynomial.h (monotone pieces, bracketed Newton: Yuksel, HPG 2022) and
// polished by Newton steps on g itself. A ray parallel to the axis solves f(w) = x² + z² in
// w instead, a horizontal ray the quadratic in t at its one height. The solid's spans along
// the ray are then the pieces between consecutive roots where g < 0 (the sign at the
// longest piece's middle, alternating across the roots), joined across the segments'
// shared joints: the crossings alternate by construction, and a span ending at the lowest
// or highest joint is a cap crossing.
#pragma once

#include "shape.h"

#include <vector>

namespace lucent {

class Sor final : public Shape {
 public:
  // Throws std::invalid_argument for fewer than 4 points, a non-finite coordinate, x < 0,
  // heights of P1 … P(n−2) not increasing, a control point at its neighbour's neighbour's
  // height (as POV-Ray: differences below 1e-10), or no point of P1 … P(n−2) off the axis.
  Sor(const std::vector<Vec2>& points, bool open);

  const char* kind() const override { return "sor"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return !open_; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  // One place where the whole line meets the surface: t along the ray, the segment (or
  // the bottom cap, numbered segments(), and the top cap after it), and for a solid
  // whether the line enters there. Ascending by t.
  struct Event {
    double t;
    uint32_t part;
    bool entering;
  };
  void lineEvents(const Ray& ray, std::vector<Event>& out) const;

  size_t segments() const { return segs_.size(); }
  // r² of the curve at height y (segment found as inside() finds it), for the tests.
  double radiusSquaredAt(double y) const;

 private:
  struct Segment {
    double a, b, c, e;  // f(w) = ((a·w + b)·w + c)·w + e, w = y − y0 in [0, h]
    double y0, h;
    double r;           // bounding cylinder radius: sqrt of f's largest value on [0, h]
    double bt, ct, et;  // the same cubic about the top: ((a·v + bt)·v + ct)·v + et, v = w − h
  };
  static double f(const Segment& s, double w) { return ((s.a * w + s.b) * w + s.c) * w + s.e; }
  static double df(const Segment& s, double w) { return (3.0 * s.a * w + 2.0 * s.b) * w + s.c; }
  // f from the nearer end: near a joint where r² is 0 (a pole) the value keeps its digits.
  static double fNear(const Segment& s, double w) {
    if (w <= 0.5 * s.h) return f(s, w);
    const double v = w - s.h;
    return ((s.a * v + s.bt) * v + s.ct) * v + s.et;
  }
  static double dfNear(const Segment& s, double w) {
    if (w <= 0.5 * s.h) return df(s, w);
    const double v = w - s.h;
    return (3.0 * s.a * v + 2.0 * s.bt) * v + s.ct;
  }
  size_t segmentAt(double y) const;
  struct End {
    double t;
    int joint;  // the joint height index the end lies at, or -1 for a root inside a segment
    int seg;
  };
  struct Span {
    End in, out;
  };
  void segmentSpans(size_t i, const Vec3& o, const Vec3& d, double ta, double tb, int ja, int jb,
                    std::vector<Span>& out) const;

  std::vector<Segment> segs_;
  std::vector<double> joints_;   // the heights P1.y … P(n−2).y
  std::vector<double> jointR2_;  // r² there: the points' x², exactly (not the cubics' values)
  double bottomR2_, topR2_;
  bool open_;
  AABB bounds_;
  double scale_ = 1.0;
};

}  // namespace lucent
