// <lathe points spline/>: a curve in the (x, y) half-plane turned about the y axis,
// POV-Ray 3.7's lathe with the same points and spline types.
//
// The curve, as POV-Ray reads the points: linear, a polygon through all of them (2 or
// more); quadratic, one piece per point after the second, from point i+1 to i+2 with point i
// steering its start (3 or more, the first a control point); cubic, Catmull-Rom pieces from
// point i+1 to i+2 (4 or more, the first and last control points); bezier, a piece per
// group of four (a multiple of 4). The solid is POV-Ray's inside test: a point is inside
// when a ray from it away from the axis crosses the curve an odd number of times. Where the
// curve does not close, that parity changes across the disc from an open end to the axis, so
// Lucent closes the solid with those discs (POV-Ray draws no surface there). `open` (POV-Ray's
// look): without the discs; a surface then, not a solid (no inside, as Lucent's other open
// shapes), its normals still facing out of the closed solid.
//
// Intersection: on a piece x(s), y(s) (cubics in s on [0, 1]), the ray o + t·d meets the
// surface where d.y·(x² + z²) = d.y·x(s)², with t = (y(s) − o.y)/d.y; multiplied out,
// |d.y·o_xz + (y(s) − o.y)·d_xz|² − (d.y·x(s))² = 0, a polynomial in s of degree 2 (a cone
// piece for linear), 4 or 6, solved by primitives/polynomial.h (monotone pieces between the
// derivative's roots, bracketed Newton: Yuksel, HPG 2022), with the magnitudes of its terms
// for the tangent test. Each root (s, t) is polished by Newton steps on the two equations
// themselves, so t does not inherit the 1/d.y of the elimination. A nearly horizontal ray
// (|d.y| below 1e-6·|d|, where the roots in s pair up too closely) takes the other order:
// the roots of y(s) = o.y, then the quadratic in t for each, then the same polish. Each
// piece's bounding cylinder (its x and y extents) skips it for most rays.
#pragma once

#include "lathe_spline.h"
#include "shape.h"

#include <vector>

namespace lucent {

class Lathe final : public Shape {
 public:
  // The fewest points each spline takes (bezier also needs a multiple of 4).
  static int minPoints(LatheSpline spline);

  // Throws std::invalid_argument for too few points (or a bezier count not a multiple of 4),
  // a non-finite coordinate, x < 0, or a curve of no extent.
  Lathe(LatheSpline spline, const std::vector<Vec2>& points, bool open = false);

  const char* kind() const override { return "lathe"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return !open_; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  // One place where the line meets the surface: t along the ray, the piece (or a closing
  // disc, numbered after the pieces) and the curve parameter s on it.
  struct LineRoot {
    double t;
    uint32_t part;
    double s;
  };
  // Every crossing of the whole line, ascending by t (a tangent contact within rounding is
  // a pair at one t or nothing, as the inside test there says); the line is outside before
  // the first, and they alternate entering and leaving.
  void lineRoots(const Ray& ray, std::vector<LineRoot>& out) const;

 private:
  struct Piece {
    Vec2 a, b, c, d;    // (x, y)(s) = ((a·s + b)·s + c)·s + d, s in [0, 1]
    int degree;         // the highest power of s with a nonzero coefficient (1 to 3)
    double r2, h1, h2;  // bounding cylinder: |x| <= r2, y in [h1, h2]
    bool endsFree;      // the curve ends at s = 1 here (s = 1 belongs to this piece)
    int segment = 0;    // POV-Ray's number of the spline segment (its i1), for povUV
  };
  struct Disc {
    double y, radius;
    double v = 0.0;  // POV-Ray's v at the curve's end the disc closes
  };
  Vec2 at(const Piece& p, double s) const { return ((p.a * s + p.b) * s + p.c) * s + p.d; }
  Vec2 slope(const Piece& p, double s) const { return (3.0 * p.a * s + 2.0 * p.b) * s + p.c; }
  bool onAxis(const Piece& p, double s) const { return std::abs(at(p, s).x) <= 1e-9 * scale_; }
  void pieceRoots(const Piece& p, uint32_t index, const Vec3& o, const Vec3& d,
                  std::vector<LineRoot>& out) const;
  bool polish(const Piece& p, const Vec3& o, const Vec3& d, double& s, double& t) const;
  // Whether the sorted roots of the line o + t·d can be trusted to alternate by their
  // order alone; where not, decideByInside keeps those across which inside() changes.
  bool alternates(const std::vector<LineRoot>& roots, double dd) const;
  void decideByInside(const Vec3& o, const Vec3& d, std::vector<LineRoot>& roots) const;

  std::vector<Piece> pieces_;
  int segments_ = 0;       // POV-Ray's number of segments, degenerate ones included
  std::vector<int> next_;  // the piece each one's end joins, or -1
  std::vector<Disc> discs_;
  AABB bounds_;
  double scale_ = 1.0;                   // the largest coordinate of the curve
  bool open_ = false;                    // the discs are not drawn
  bool isDisc(const LineRoot& r) const;  // one of the discs that close an open curve
  // POV-Ray's parity test, which the roots' order follows whether or not the lathe is open.
  bool solidInside(const Vec3& q) const;
};

}  // namespace lucent
