// <sphere-sweep spline="linear" spheres="x y z r, x y z r, ..." tolerance="1e-6"/>:
// POV-Ray 3.7's sphere_sweep, the solid a sphere sweeps while its centre and radius follow
// a spline through the control spheres.
//   linear   (2 spheres or more): segment i runs from sphere i to sphere i + 1, centre and
//            radius linear in u. The solid is the union of the spheres and, between each
//            two, the frustum of the cone tangent to both (their convex hull); a sphere
//            within its neighbour adds no frustum.
//   cubic    (4 or more): POV-Ray's Catmull-Rom spline; segment i (0 <= i < n − 3) uses
//            spheres i … i + 3 and runs from sphere i + 1 to sphere i + 2.
//   b-spline (4 or more): the uniform cubic B-spline; segment i uses spheres i … i + 3 and
//            passes near, not through, them.
// A spline segment's centre c(u) and radius r(u) are cubics in u in [0, 1], with POV-Ray's
// basis matrices (sphsweep.cpp); the solid is the union of the balls of radius |r(u)|
// about c(u) over every segment and u (what POV-Ray's envelope and end spheres bound).
//
// Intersection. Linear: each sphere and each frustum exactly (the quadratic of the cone
// through the two tangent circles, cut by their planes). Splines: along the line o + t·d
// (d unit) the ball at u covers t0(u) ≤ t ≤ t1(u), t0,1 = m(u) ∓ √D(u), m = d·(c − o),
// D = r² − |c − o|⊥² (a sextic in u). Over each interval of u where D ≥ 0 those spans
// overlap continuously, so the union is one span from min t0 to max t1. The extremes lie
// at the interval's ends or where t0' or t1' vanish, i.e. at roots of
// P = 4·D·m'² − D'² (degree 10), isolated by primitives/polynomial.h; every candidate is
// a real ball's span, so a spurious root cannot move a surface, and at a true extreme t is
// stationary in u, so an error δu in the root moves t by O(δu²) only. The entry and exit
// are then the ball's own quadratic roots at that u. The spans of all the segments (and
// spheres and frustums) are joined into the solid's.
#pragma once

#include "shape.h"
#include "span.h"

#include <vector>

namespace lucent {

enum class SweepSpline { Linear, Cubic, BSpline };

struct SweepSphere {
  Vec3 center{0.0};
  double radius = 0.0;
};

class SphereSweep final : public Shape {
 public:
  static int minSpheres(SweepSpline s) { return s == SweepSpline::Linear ? 2 : 4; }

  // Throws std::invalid_argument for fewer spheres than minSpheres, a non-finite value, a
  // negative radius, or radii all 0 (nothing is swept).
  SphereSweep(SweepSpline spline, const std::vector<SweepSphere>& spheres);

  const char* kind() const override { return "sphere-sweep"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // Where the whole line o + t·d is inside, in the ray's own t, ascending and disjoint.
  // Linear: part i < spheres is sphere i, part spheres + j the frustum after sphere j.
  // Splines: part = segment, b1 = u of the ball the span's end lies on.
  void lineSpans(const Ray& ray, std::vector<Span>& out) const;

  // A spline segment's centre and radius at u (segments() of them; linear too).
  size_t segments() const { return segs_.size(); }
  Vec3 centerAt(size_t seg, double u) const;
  double radiusAt(size_t seg, double u) const;
  // The u of the ball of a spline segment touching the surface at p, refined from u.
  double contactParameter(size_t seg, const Vec3& p, double u) const;

 private:
  // Power-basis cubics: c(u) = Σ c[k]·u^k, r(u) = Σ r[k]·u^k (linear: c[2..3] = 0).
  struct Segment {
    Vec3 c[4];
    double r[4];
    Vec3 bc;    // bounding sphere of the swept balls: centre
    double br;  //   and radius
  };
  // The frustum of the cone tangent to spheres j and j + 1, in s = (p − c0)·a along the
  // unit axis a: between the tangent circles at s0 and s1, radius R0 + (s − s0)·g.
  struct Frustum {
    bool present = false;
    Vec3 c0{0.0}, a{0.0};
    double s0 = 0.0, s1 = 0.0, R0 = 0.0, g = 0.0;
  };
  void linearSpans(const Vec3& o, const Vec3& d, std::vector<Span>& out) const;
  void splineSpans(size_t seg, const Vec3& o, const Vec3& d, std::vector<Span>& out) const;
  bool insideFrustum(const Frustum& f, const Vec3& p) const;
  bool insideSegment(const Segment& s, const Vec3& p) const;

  SweepSpline spline_;
  std::vector<SweepSphere> spheres_;
  std::vector<Segment> segs_;
  std::vector<Frustum> frusta_;  // linear only, one per segment
  AABB bounds_;
  double scale_ = 1.0;
};

}  // namespace lucent
