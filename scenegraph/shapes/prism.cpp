// <prism points="x z ..." height1="0" height2="1" spline="linear" sweep="linear"
// open="false"/>: POV-Ray 3.7's prism (primitives/prism.h), its points read by POV-Ray's
// rules (primitives/prism_outline.h). POV-Ray closes an unclosed linear prism with a
// warning, and so does Lucent; an unclosed spline outline, which POV-Ray ignores with a
// warning, is an error here, as is a polygon of fewer than three corners.
#include "scenegraph/shape_type.h"

#include "primitives/prism.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

void readPrism(PrismSpec& s, AttributeInput& in) {
  s.spline =
      static_cast<PrismSpline>(in.choice("spline", 0, {"linear", "quadratic", "cubic", "bezier"}));
  s.conic = in.choice("sweep", 0, {"linear", "conic"}) == 1;
  if (!in.has("points")) {
    in.error("<prism> needs 'points' (x z pairs of the outline)");
    return;
  }
  auto list = in.numbers("points");
  if (!list) return;
  if (list->size() % 2 != 0) {
    in.attrError("points", fmt::format("expected x z pairs (an even count of numbers), got {}",
                                       list->size()));
    return;
  }
  s.points.clear();
  for (size_t i = 0; i < list->size(); i += 2) s.points.emplace_back((*list)[i], (*list)[i + 1]);
  const PrismOutline outline = prismOutline(s.points, s.spline);
  if (!outline.error.empty()) {
    in.attrError("points", outline.error);
    return;
  }
  if (outline.closedLast)
    in.warning(
        "<prism>: the last polygon is not closed (its first point is not repeated); closed it");
  if (s.height1 == s.height2) in.attrError("height2", "equals height1: the prism would be flat");
}

std::shared_ptr<const Shape> buildPrism(const PrismSpec& s) {
  const PrismOutline outline = prismOutline(s.points, s.spline);
  if (!outline.error.empty()) throw std::invalid_argument("makeShape: <prism>: " + outline.error);
  return std::make_shared<Prism>(outline.contours, s.height1, s.height2,
                                 s.conic ? Prism::Sweep::Conic : Prism::Sweep::Linear, s.open);
}

void writePrism(const PrismSpec& s, PovShapeOut& out) {
  out.open("prism");
  const char* spline[] = {"linear_spline", "quadratic_spline", "cubic_spline", "bezier_spline"};
  std::vector<Vec2> pts = s.points;
  if (s.spline == PrismSpline::Linear) {
    // POV-Ray closes an unclosed last polygon too, but warns: write it closed.
    const PrismOutline o = prismOutline(pts, s.spline);
    if (o.closedLast) {
      size_t n = 0;
      for (size_t c = 0; c + 1 < o.contours.size(); ++c) n += o.contours[c].size() + 1;
      pts.push_back(pts[n]);
    }
  }
  out.line(fmt::format("{} {}", s.conic ? "conic_sweep" : "linear_sweep",
                       spline[static_cast<int>(s.spline)]));
  out.line(fmt::format("{}, {}, {}", out.number(s.height1), out.number(s.height2), pts.size()));
  std::string line;
  for (size_t i = 0; i < pts.size(); ++i) {
    line += fmt::format("<{}, {}>{}", out.number(pts[i].x), out.number(pts[i].y),
                        i + 1 < pts.size() ? ", " : "");
    if (line.size() > 80 || i + 1 == pts.size()) {
      out.line(line);
      line.clear();
    }
  }
  if (s.open) out.line("open");
}

std::vector<Vec2> pairs(std::initializer_list<double> v) {
  std::vector<Vec2> out;
  for (auto it = v.begin(); it != v.end(); it += 2) out.emplace_back(*it, *(it + 1));
  return out;
}

}  // namespace

template <>
ShapeEntry<PrismSpec> shapeEntry<PrismSpec>() {
  ShapeEntry<PrismSpec> e("prism", "prisms", buildPrism, writePrism);
  e.doc =
      "POV-Ray's prism: closed outlines of x z points (several make holes) swept along y from "
      "height1 to height2, linearly or towards the origin (solid unless open).";
  e.fields = {
      readByEntry<PrismSpec>("points", AttrType::NumberList, "", {}, 2)
          .doc("The outline's x z pairs, read as POV-Ray's prism reads them for the spline: each "
               "polygon or curve closed by repeating its first point; several make holes "
               "(even-odd)."),
      numberField("height1", &PrismSpec::height1).doc("One end of the sweep along y."),
      numberField("height2", &PrismSpec::height2)
          .doc("The other end (in either order; not equal to height1)."),
      readByEntry<PrismSpec>("spline", AttrType::Choice, "linear",
                             {"linear", "quadratic", "cubic", "bezier"})
          .doc("linear (polygons) | quadratic | cubic (each with a control point before, cubic "
               "also one after) | bezier (four points per segment)."),
      readByEntry<PrismSpec>("sweep", AttrType::Choice, "linear", {"linear", "conic"})
          .doc("linear (an extrusion) | conic (the outline is the section at y = 1, scaled by y "
               "towards the apex at the origin)."),
      booleanField("open", &PrismSpec::open).doc("Without the two caps (then not a solid).")};
  e.finish = readPrism;
  e.notSolid = [](const PrismSpec& s) {
    return s.open ? std::string("it is open") : std::string();
  };
  e.samples = [] {
    PrismSpec square;
    square.points = pairs({-1, -1, 1, -1, 1, 1, -1, 1, -1, -1});
    PrismSpec holed;
    holed.points = pairs({-1,   -1,   1,   -1,   1,   1,   -1,   1,   -1,   -1,
                          -0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, 0.5, -0.5, -0.5});
    holed.height1 = -0.5;
    holed.height2 = 0.5;
    PrismSpec cubic;
    cubic.spline = PrismSpline::Cubic;
    cubic.points = pairs({0, -1, 1, 0, 0, 1, -1, 0, 0, -1, 1, 0, 0, 1});
    PrismSpec bezier;
    bezier.spline = PrismSpline::Bezier;
    bezier.points = pairs({1,  0, 1,  0.55,  0.55,  1,  0, 1,  0, 1,  -0.55, 1,  -1, 0.55,  -1, 0,
                           -1, 0, -1, -0.55, -0.55, -1, 0, -1, 0, -1, 0.55,  -1, 1,  -0.55, 1,  0});
    PrismSpec quadratic;
    quadratic.spline = PrismSpline::Quadratic;
    quadratic.points = pairs({-1, 0, 0, -1, 1, 0, 0, 1, -1, 0, 0, -1});
    PrismSpec conic = square;
    conic.conic = true;
    conic.height1 = 0.25;
    PrismSpec open = square;
    open.open = true;
    return std::vector<std::pair<std::string, PrismSpec>>{{"square prism", square},
                                                          {"square prism with a hole", holed},
                                                          {"cubic spline prism", cubic},
                                                          {"bezier circle prism", bezier},
                                                          {"quadratic spline prism", quadratic},
                                                          {"conic square prism", conic},
                                                          {"open square prism", open}};
  };
  return e;
}

}  // namespace lucent
