// <polygon points="x y z, ..."/>: POV-Ray 3.7's polygon, a flat surface bounded by one or
// more closed outlines in one plane (not a solid).
//
// The points are read by POV-Ray's rules (polygonOutline): each outline is closed by
// repeating its first point (a point within 1e-10 of it in every coordinate counts, and is
// made exactly equal); the next outline starts after the closing point; an unclosed last
// outline is closed by appending its first point. Inside is the even-odd rule over every
// outline's edges (so an outline inside another makes a hole). The plane is spanned, as in
// POV-Ray, from the first point o: the normal n = a × b, with a towards the first point
// away from o and b towards the next point away from o not on the line o + s·a. Every point must
// lie in that plane (within 1e-10, POV-Ray's tolerance, else POV-Ray ignores the polygon). Points
// on an outline's edges follow POV-Ray's half-open rule (a point whose v equals an edge end's
// counts as above it). No (u,v), as in POV-Ray.
#pragma once

#include "shape.h"

#include <string>
#include <vector>

namespace lucent {

struct PolygonOutline {
  std::vector<Vec3> points;  // closed: the closing repeats made exact, the last one appended
  bool closedLast = false;   // the last outline was not closed, and was closed here
};
// POV-Ray's reading of a polygon's points (parser's Parse_Polygon rules). Needs 3 or more.
PolygonOutline polygonOutline(const std::vector<Vec3>& points);

// Why a closed list of points makes no polygon ("" when it makes one): fewer than three
// points, all on one line, or not in one plane (POV-Ray ignores such a polygon).
std::string polygonProblem(const std::vector<Vec3>& closedPoints);

class Polygon final : public Shape {
 public:
  // closedPoints as polygonOutline returns them. Throws std::invalid_argument when
  // polygonProblem names a problem.
  explicit Polygon(const std::vector<Vec3>& closedPoints);

  const char* kind() const override { return "polygon"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return false; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3&) const override { return false; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  // Whether the point (x, y) of the plane's frame (along u and v from o) is inside.
  bool insideOutline(double x, double y) const;

 private:
  bool root(const Ray& ray, double& t) const;

  Vec3 o_, u_, v_, n_;                      // the plane's frame: origin, unit u and v, unit normal
  std::vector<Vec2> points_;                // in the frame
  std::vector<std::pair<int, int>> edges_;  // indices into points_
  AABB bounds_;
};

}  // namespace lucent
