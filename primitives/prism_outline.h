// The outline a prism sweeps: closed contours of line, quadratic and cubic Bézier segments
// in the xz-plane (the text shape builds glyphs from FreeType's outlines the same way), and
// POV-Ray 3.7's rules for turning a prism's point list into such contours.
#pragma once

#include "math.h"

#include <string>
#include <vector>

namespace lucent {

// One piece of a contour: degree 1 (p[0], p[1]), 2 (p[0..2]) or 3 (p[0..3]) Bézier control
// points, x in .x and z in .y. The curve runs from p[0] to p[degree].
struct PrismSegment {
  int degree = 1;
  Vec2 p[4]{};
  Vec2 start() const { return p[0]; }
  Vec2 end() const { return p[degree]; }
};

// A closed contour: each segment starts where the one before ends, the last ends where the
// first starts. Several contours make holes by the even-odd rule.
using PrismContour = std::vector<PrismSegment>;

enum class PrismSpline { Linear, Quadratic, Cubic, Bezier };

struct PrismOutline {
  std::vector<PrismContour> contours;
  std::string error;        // non-empty when the points do not make a prism (then no contours)
  bool closedLast = false;  // a linear outline whose last polygon was closed for the caller
};

// POV-Ray's reading of `points` (x z pairs) for each spline:
//   linear: polygons, each closed by repeating its first point; a new polygon starts after
//     the closing point; the last one is closed if it is not (closedLast tells).
//   quadratic: per polygon, a control point, then the points, the first repeated to close;
//     each segment uses the point before it as a control point.
//   cubic: as quadratic, with one more control point after the closing point (Catmull-Rom).
//   bezier: groups of four (start, two controls, end); a group starting elsewhere than the
//     previous one ended starts a new contour, which must end where it started.
// Points closer than 1e-10 in both coordinates count as the same, as in POV-Ray.
PrismOutline prismOutline(const std::vector<Vec2>& points, PrismSpline spline);

}  // namespace lucent
