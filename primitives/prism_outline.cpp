#include "prism_outline.h"

#include <cmath>
#include <string>

namespace lucent {

namespace {

constexpr double kSame = 1e-10;  // POV-Ray's EPSILON for closing points

bool same(const Vec2& a, const Vec2& b) {
  return std::abs(a.x - b.x) < kSame && std::abs(a.y - b.y) < kSame;
}

PrismSegment line(const Vec2& a, const Vec2& b) {
  PrismSegment s;
  s.degree = 1;
  s.p[0] = a;
  s.p[1] = b;
  return s;
}

// POV-Ray's quadratic spline piece through p1 to p2 (p0 the control before), as a Bézier:
// its polynomial has derivative (p2 - p0)/2 at p1, so the middle control point is
// p1 + (p2 - p0)/4.
PrismSegment quadratic(const Vec2& p0, const Vec2& p1, const Vec2& p2) {
  PrismSegment s;
  s.degree = 2;
  s.p[0] = p1;
  s.p[1] = p1 + 0.25 * (p2 - p0);
  s.p[2] = p2;
  return s;
}

// POV-Ray's cubic spline (Catmull-Rom) piece from p1 to p2 as a Bézier: tangents
// (p2 - p0)/2 and (p3 - p1)/2 at the ends, so the controls are a sixth of them inside.
PrismSegment catmullRom(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  PrismSegment s;
  s.degree = 3;
  s.p[0] = p1;
  s.p[1] = p1 + (p2 - p0) / 6.0;
  s.p[2] = p2 - (p3 - p1) / 6.0;
  s.p[3] = p2;
  return s;
}

// The contour's closing point is written as its first (within kSame): make it exactly so.
void closeExactly(PrismContour& c) { c.back().p[c.back().degree] = c.front().p[0]; }

PrismOutline failed(std::string message) {
  PrismOutline o;
  o.error = std::move(message);
  return o;
}

PrismOutline linearOutline(const std::vector<Vec2>& pts) {
  if (pts.size() < 3) return failed("a linear prism needs at least 3 points");
  PrismOutline o;
  size_t first = 0;
  PrismContour cur;
  for (size_t i = 1; i < pts.size(); ++i) {
    cur.push_back(line(pts[i - 1], pts[i]));
    if (same(pts[i], pts[first])) {
      if (cur.size() < 3)
        return failed("the polygon starting at point " + std::to_string(first + 1) +
                      " closes with fewer than 3 corners");
      closeExactly(cur);
      o.contours.push_back(std::move(cur));
      cur.clear();
      first = ++i;  // the next polygon starts after the closing point
    }
  }
  if (first < pts.size()) {  // an unclosed last polygon: closed for the caller, as POV-Ray does
    if (pts.size() - first < 3)
      return failed("the last polygon (from point " + std::to_string(first + 1) +
                    ") has fewer than 3 points");
    cur.push_back(line(pts.back(), pts[first]));
    o.contours.push_back(std::move(cur));
    o.closedLast = true;
  }
  return o;
}

// Quadratic and cubic splines: `tail` is 0 (quadratic) or 1 (cubic: a control point after
// the closing point).
PrismOutline splineOutline(const std::vector<Vec2>& pts, bool cubic) {
  const size_t minPoints = cubic ? 6 : 5;
  const char* name = cubic ? "a cubic" : "a quadratic";
  if (pts.size() < minPoints)
    return failed(std::string(name) + " spline prism needs at least " + std::to_string(minPoints) +
                  " points");
  PrismOutline o;
  size_t start = 0;  // the contour's leading control point; its first point is start + 1
  while (start < pts.size()) {
    PrismContour cur;
    size_t i = start + 2;
    for (; i < pts.size(); ++i) {
      if (cubic) {
        if (i + 1 >= pts.size()) break;
        cur.push_back(catmullRom(pts[i - 2], pts[i - 1], pts[i], pts[i + 1]));
      } else {
        cur.push_back(quadratic(pts[i - 2], pts[i - 1], pts[i]));
      }
      if (same(pts[i], pts[start + 1])) break;
    }
    if (i >= pts.size() || (cubic && i + 1 >= pts.size()) || !same(pts[i], pts[start + 1]))
      return failed(std::string("the curve starting at point ") + std::to_string(start + 2) +
                    " is not closed: repeat that point" +
                    (cubic ? " and add one control point after it" : ""));
    closeExactly(cur);
    o.contours.push_back(std::move(cur));
    start = i + (cubic ? 2 : 1);
  }
  return o;
}

PrismOutline bezierOutline(const std::vector<Vec2>& pts) {
  if (pts.size() < 4 || pts.size() % 4 != 0)
    return failed("a bezier prism needs four points per segment (a multiple of 4), got " +
                  std::to_string(pts.size()));
  PrismOutline o;
  PrismContour cur;
  size_t loopStart = 0;
  auto finish = [&](size_t endIndex) {
    if (!same(pts[endIndex], pts[loopStart])) return false;
    closeExactly(cur);
    o.contours.push_back(std::move(cur));
    cur.clear();
    return true;
  };
  for (size_t i = 0; i < pts.size(); i += 4) {
    if (!cur.empty() && !same(pts[i], pts[i - 1])) {
      if (!finish(i - 1))
        return failed("the segments from point " + std::to_string(loopStart + 1) +
                      " do not end where they start (point " + std::to_string(i) + ")");
      loopStart = i;
    }
    PrismSegment s;
    s.degree = 3;
    for (int k = 0; k < 4; ++k) s.p[k] = pts[i + k];
    if (!cur.empty()) s.p[0] = cur.back().p[3];  // the same point, exactly
    cur.push_back(s);
  }
  if (!finish(pts.size() - 1))
    return failed("the segments from point " + std::to_string(loopStart + 1) +
                  " do not end where they start (the last point)");
  return o;
}

}  // namespace

PrismOutline prismOutline(const std::vector<Vec2>& points, PrismSpline spline) {
  switch (spline) {
    case PrismSpline::Linear:
      return linearOutline(points);
    case PrismSpline::Quadratic:
      return splineOutline(points, false);
    case PrismSpline::Cubic:
      return splineOutline(points, true);
    case PrismSpline::Bezier:
      return bezierOutline(points);
  }
  return failed("unknown spline");
}

}  // namespace lucent
