// <polygon points="x y z, ..."/>: POV-Ray 3.7's polygon (primitives/polygon.h), its points
// read by POV-Ray's rules: outlines closed by repeating their first point, an unclosed last
// one closed with a warning (as POV-Ray does). Fewer than three points, points on one line
// and points not in one plane are errors (POV-Ray ignores the last two). Not a solid.
#include "scenegraph/shape_type.h"

#include "primitives/polygon.h"

#include <fmt/format.h>

namespace lucent {

namespace {

void readPolygon(PolygonSpec& s, AttributeInput& in) {
  if (!in.has("points")) {
    in.error("<polygon> needs 'points' (x y z of each corner)");
    return;
  }
  auto list = in.numbers("points");
  if (!list) return;
  if (list->size() % 3 != 0) {
    in.attrError("points", fmt::format("expected x y z for each point (a multiple of 3 numbers), "
                                       "got {}",
                                       list->size()));
    return;
  }
  s.points.clear();
  for (size_t i = 0; i < list->size(); i += 3)
    s.points.emplace_back((*list)[i], (*list)[i + 1], (*list)[i + 2]);
  if (s.points.size() < 3) {
    in.attrError("points",
                 fmt::format("a polygon needs at least three points, not {}", s.points.size()));
    return;
  }
  const PolygonOutline outline = polygonOutline(s.points);
  const std::string problem = polygonProblem(outline.points);
  if (!problem.empty()) {
    in.attrError("points", problem);
    return;
  }
  if (outline.closedLast)
    in.warning(
        "<polygon>: the last outline is not closed (its first point is not repeated); closed "
        "it");
}

std::shared_ptr<const Shape> buildPolygon(const PolygonSpec& s) {
  if (s.points.size() < 3)
    throw std::invalid_argument("makeShape: <polygon> needs at least three points");
  return std::make_shared<Polygon>(polygonOutline(s.points).points);
}

void writePolygon(const PolygonSpec& s, PovShapeOut& out) {
  // Written closed, as POV-Ray would close it, so that it reads without a warning.
  const std::vector<Vec3> pts = polygonOutline(s.points).points;
  out.open("polygon");
  out.line(fmt::format("{},", pts.size()));
  std::string line;
  for (size_t i = 0; i < pts.size(); ++i) {
    line += out.vector(pts[i]) + (i + 1 < pts.size() ? ", " : "");
    if (line.size() > 80 || i + 1 == pts.size()) {
      out.line(line);
      line.clear();
    }
  }
}

}  // namespace

template <>
ShapeEntry<PolygonSpec> shapeEntry<PolygonSpec>() {
  ShapeEntry<PolygonSpec> e("polygon", "polygons", buildPolygon, writePolygon);
  e.doc =
      "POV-Ray's polygon: closed outlines of points in one plane (several make holes, "
      "even-odd); not solid.";
  e.fields = {readByEntry<PolygonSpec>("points", AttrType::NumberList, "", {}, 3)
                  .doc("The corners, x y z each, read as POV-Ray's polygon reads them: each "
                       "outline closed by repeating its first point, the next one starting after "
                       "it; all in one plane.")};
  e.fields[0].info.required = true;
  e.finish = readPolygon;
  e.notSolid = [](const PolygonSpec&) { return std::string("a polygon encloses no volume"); };
  e.samples = [] {
    PolygonSpec square{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}}};
    PolygonSpec holed{{{-1, 0, -1},
                       {1, 0, -1},
                       {1, 0, 1},
                       {-1, 0, 1},
                       {-1, 0, -1},
                       {-0.5, 0, -0.5},
                       {0.5, 0, -0.5},
                       {0.5, 0, 0.5},
                       {-0.5, 0, 0.5},
                       {-0.5, 0, -0.5}}};
    // In the plane z = x / 2 + y / 4, not closed (closed when built).
    PolygonSpec tilted{{{0, 0, 0}, {1, 0.2, 0.55}, {0.8, 1, 0.65}, {0.1, 0.9, 0.275}}};
    return std::vector<std::pair<std::string, PolygonSpec>>{
        {"square polygon", square}, {"polygon with a hole", holed}, {"tilted quad", tilted}};
  };
  return e;
}

}  // namespace lucent
