// <lathe points="x y ..." spline="linear"/>: a curve in the (x, y) half-plane turned about
// the y axis, POV-Ray's lathe with the same points (primitives/lathe.h).
#include "profile_points.h"
#include "scenegraph/shape_type.h"

#include "primitives/lathe.h"

#include <fmt/format.h>

namespace lucent {

namespace {

const std::vector<std::string_view> kSplineNames = {"linear", "quadratic", "cubic", "bezier"};
const char* const kPovSpline[] = {"linear_spline", "quadratic_spline", "cubic_spline",
                                  "bezier_spline"};

}  // namespace

template <>
ShapeEntry<LatheSpec> shapeEntry<LatheSpec>() {
  ShapeEntry<LatheSpec> e(
      "lathe", "lathes",
      [](const LatheSpec& s) { return std::make_shared<Lathe>(s.spline, s.points, s.open); },
      [](const LatheSpec& s, PovShapeOut& out) {
        out.open("lathe");
        out.line(kPovSpline[static_cast<int>(s.spline)]);
        std::string list = fmt::format("{}", s.points.size());
        for (const Vec2& p : s.points)
          list += fmt::format(", <{}, {}>", out.number(p.x), out.number(p.y));
        out.line(list);
        // sturm: POV-Ray's exact root isolation for the spline pieces' polynomials.
        if (s.spline != LatheSpline::Linear) out.line("sturm");
      });
  e.doc =
      "A curve of x y points (x >= 0) turned about the y axis (solid; open: without the discs "
      "that close an open curve, as POV-Ray's).";
  Field<LatheSpec> points =
      readByEntry<LatheSpec>("points", AttrType::NumberList, "", {}, 2)
          .doc(
              "The curve's points as x y pairs, x >= 0: linear 2 or more, quadratic 3 or more (the "
              "first steers), cubic 4 or more (the first and last steer), bezier groups of 4.");
  points.info.required = true;
  e.fields = {std::move(points),
              readByEntry<LatheSpec>("spline", AttrType::Choice, "linear", kSplineNames)
                  .doc("linear (a polygon) | quadratic | cubic (Catmull-Rom) | bezier (groups of 4 "
                       "points), as POV-Ray's."),
              booleanField("open", &LatheSpec::open)
                  .doc("Leave out the discs to the axis that close a curve ending off the axis "
                       "and away from its start, as POV-Ray's lathe (then a surface, not a "
                       "solid).")};
  e.finish = [](LatheSpec& s, AttributeInput& in) {
    s.spline = static_cast<LatheSpline>(in.choice("spline", 0, kSplineNames));
    if (in.failed()) return;
    auto v = readProfilePairs(in, "lathe");
    if (!v) return;
    const size_t n = v->size();
    const size_t want = static_cast<size_t>(Lathe::minPoints(s.spline));
    const char* name = kSplineNames[static_cast<size_t>(s.spline)].data();
    if (n < want) {
      in.attrError("points",
                   fmt::format("a {} lathe needs at least {} points, not {}", name, want, n));
      return;
    }
    if (s.spline == LatheSpline::Bezier && n % 4 != 0) {
      in.attrError("points", fmt::format("a bezier lathe needs groups of 4 points, not {}", n));
      return;
    }
    bool extent = false;
    for (size_t i = 0; i < n; ++i) {
      const Vec2 p = (*v)[i];
      if (!profilePointValid(in, p, i)) return;
      if (i > 0 && p != s.points.back()) extent = true;
      s.points.push_back(p);
    }
    if (!extent) {
      in.attrError("points", "all the points are the same: there is no surface");
      return;
    }
  };
  e.notSolid = [](const LatheSpec& s) {
    return s.open ? std::string("it is open") : std::string();
  };
  // No image mapping; POV-Ray's uv_mapping reads u the other way (ImageMapping::uvMirrored).
  e.povImageMapping = [](const LatheSpec&) {
    ImageMapping m;
    m.uvMirrored = true;
    return m;
  };
  e.samples = [] {
    using V = std::vector<Vec2>;
    return std::vector<std::pair<std::string, LatheSpec>>{
        {"linear lathe cylinder", {LatheSpline::Linear, V{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}},
        {"linear lathe ring",
         {LatheSpline::Linear, V{{0.5, -0.5}, {1, -0.5}, {1, 0.5}, {0.5, 0.5}, {0.5, -0.5}}}},
        {"open linear lathe cone", {LatheSpline::Linear, V{{0, 1}, {1, 0}}}},
        {"linear lathe cup without its disc",
         {LatheSpline::Linear, V{{0, 0}, {1, 0}, {1, 1}}, true}},
        {"quadratic lathe",
         {LatheSpline::Quadratic, V{{0, -1}, {0, -0.5}, {0.8, 0}, {0.5, 0.6}, {0, 1}}}},
        {"cubic lathe vase",
         {LatheSpline::Cubic,
          V{{0, -0.2}, {0, 0}, {0.6, 0.1}, {0.9, 0.5}, {0.4, 1}, {0.6, 1.4}, {0, 1.5}, {0, 1.7}}}},
        {"bezier lathe", {LatheSpline::Bezier, V{{0, 0}, {1.2, 0}, {1.2, 1}, {0, 1}}}}};
  };
  return e;
}

}  // namespace lucent
