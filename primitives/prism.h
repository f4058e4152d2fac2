// <prism points="x z ..." height1="0" height2="1" spline="linear" sweep="linear" open="false"/>
// POV-Ray 3.7's prism: closed contours in the xz-plane (lines, quadratic and cubic Bézier
// segments; several contours make holes by the even-odd rule) swept along y from height1
// to height2. A linear sweep extrudes them; a conic sweep scales the outline by y (the
// outline is the cross-section at y = 1, the apex at the origin). `open` removes the caps
// (then the shape is not a solid). No (u, v), as in POV-Ray.
//
// Intersection (exact per segment, no marching): the ray's plane through the sweep
// direction (linear: the vertical plane through the ray; conic: the plane through the ray
// and the apex) meets the outline's plane in a line L, g(c) = a·(c.x − q.x) + b·(c.z − q.z)
// = 0. Along each segment g is a polynomial in the curve parameter of the segment's degree
// (<= 3), as in POV-Ray (Kajiya 1983, "New techniques for ray tracing procedurally defined
// objects"); its roots are isolated as in primitives/polynomial.h (Yuksel 2022): the
// derivative's roots split [0, 1] into monotone pieces, each piece whose ends differ in
// sign holds one crossing, refined by bracketed Newton steps. The sign at a segment's end
// is g at the contour's vertex itself (0 counts as positive), shared by the two segments
// that meet there, so a ray through a vertex crosses once or not at all, never twice, and
// every closed contour is crossed an even number of times. The inside of L is then known
// exactly by toggling from outside at L's far end through the crossings in order along L;
// intersected with the slab height1 <= y <= height2 it gives the spans along the ray,
// whose ends are the side or cap crossings: they alternate by construction. A segment
// whose ends and bounding box lie strictly on one side of L is skipped unexamined.
#pragma once

#include "prism_outline.h"
#include "shape.h"

#include <vector>

namespace lucent {

class Prism final : public Shape {
 public:
  enum class Sweep { Linear, Conic };

  // Throws std::invalid_argument for an empty outline, an open contour, equal heights or
  // non-finite values. Heights in either order (POV-Ray swaps them).
  Prism(const std::vector<PrismContour>& contours, double height1, double height2,
        Sweep sweep = Sweep::Linear, bool open = false);

  const char* kind() const override { return "prism"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return !open_; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // Even-odd membership of the outline's point (x, z) (a ray towards +x, half-open in z).
  bool insideOutline(double x, double z) const;
  size_t segmentCount() const { return pieces_.size(); }

  // Hit::part of the caps; a side's part is its segment index, with kEntering set where
  // the ray enters the solid.
  static constexpr uint32_t kLowCap = 0x7FFFFFFEu, kHighCap = 0x7FFFFFFFu;
  static constexpr uint32_t kEntering = 0x80000000u;

 private:
  struct Piece {
    int degree;
    Vec2 p0, p1;        // the exact end points (shared with the neighbours)
    double x[4], z[4];  // power-basis coefficients of x(s), z(s), s in [0, 1]
    Vec2 lo, hi;        // box of the control points
  };
  // A z-monotone part of a piece, for the even-odd test.
  struct Monotone {
    uint32_t piece;
    double s0, s1;
    Vec2 a, b;  // its ends
    double xlo, xhi;
  };
  struct Event {
    double t;
    uint32_t piece;
    double s;
  };
  struct Span {
    double t0, t1;
    uint32_t part0, part1;
    double s0, s1;
  };

  // The spans of the whole line inside the solid, sorted (for open prisms: the side
  // crossings within the slab, as zero-length spans).
  void spans(const Ray& ray, std::vector<Span>& out) const;
  void lineCrossings(const Ray& ray, double a, double b, const Vec2& q,
                     std::vector<Event>& ev) const;
  void addPieceCrossings(const Piece& pc, uint32_t index, const Ray& ray, double a, double b,
                         const Vec2& q, std::vector<Event>& ev) const;
  double eventT(const Ray& ray, const Vec2& c) const;
  Vec2 curve(const Piece& pc, double s) const;
  Vec2 tangent(const Piece& pc, double s) const;

  std::vector<Piece> pieces_;
  std::vector<Monotone> monotone_;
  Vec2 outlineLo_, outlineHi_;
  double h1_, h2_;
  Sweep sweep_;
  bool open_;
  AABB bounds_;
};

}  // namespace lucent
