// <sor points="x y ..." open="false"/>: POV-Ray's surface of revolution (primitives/sor.h),
// its points checked by POV-Ray's rules: at least 4, x >= 0, the heights of the second to
// the next-to-last point increasing, each control point's height apart from its
// neighbour's neighbour's (the slopes divide by those differences).
#include "profile_points.h"
#include "scenegraph/shape_type.h"

#include "primitives/sor.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

// POV-Ray's EPSILON, below which it calls a height difference "Incorrect point".
constexpr double kPovEpsilon = 1e-10;

void readSor(SorSpec& s, AttributeInput& in) {
  auto v = readProfilePairs(in, "sor");
  if (!v) return;
  const size_t n = v->size();
  if (n < 4) {
    in.attrError(
        "points",
        fmt::format("a sor needs at least 4 points (the first and last steer), not {}", n));
    return;
  }
  s.points.clear();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = (*v)[i];
    if (!profilePointValid(in, p, i)) return;
    s.points.push_back(p);
  }
  const auto& P = s.points;
  for (size_t i = 2; i + 1 < n; ++i)
    if (!(P[i].y > P[i - 1].y)) {
      in.attrError("points", fmt::format("point {} has y = {}, not above point {}'s {}: the "
                                         "heights of points 2 to {} must increase",
                                         i + 1, P[i].y, i, P[i - 1].y, n - 1));
      return;
    }
  if (std::abs(P[2].y - P[0].y) < kPovEpsilon) {
    in.attrError("points",
                 "point 1 is at the height of point 3: the slope at point 2 is undefined");
    return;
  }
  if (std::abs(P[n - 1].y - P[n - 3].y) < kPovEpsilon) {
    in.attrError(
        "points",
        fmt::format("point {} is at the height of point {}: the slope at point {} is undefined", n,
                    n - 2, n - 1));
    return;
  }
  for (size_t i = 1; i + 2 < n; ++i)
    if (P[i + 1].y - P[i].y < kPovEpsilon) {
      in.attrError("points",
                   fmt::format("points {} and {} are closer in height than POV-Ray accepts (1e-10)",
                               i + 1, i + 2));
      return;
    }
  bool offAxis = false;
  for (size_t i = 1; i + 1 < n; ++i) offAxis |= P[i].x > 0.0;
  if (!offAxis)
    in.attrError("points",
                 fmt::format("points 2 to {} all have x = 0: there is no surface", n - 1));
}

void writeSor(const SorSpec& s, PovShapeOut& out) {
  out.open("sor");
  std::string line = fmt::format("{}", s.points.size());
  for (const Vec2& p : s.points) {
    line += fmt::format(", <{}, {}>", out.number(p.x), out.number(p.y));
    if (line.size() > 80) {
      out.line(line);
      line.clear();
    }
  }
  if (!line.empty()) out.line(line);
  if (s.open) out.line("open");
  // No sturm: POV-Ray's closed-form cubic is the better of its two solvers here. With
  // sturm it misses a shadow ray's second crossing of the wall it starts on (the inside of
  // an open sor near its rim, lit through the opening, shows light there).
}

}  // namespace

template <>
ShapeEntry<SorSpec> shapeEntry<SorSpec>() {
  ShapeEntry<SorSpec> e(
      "sor", "sors", [](const SorSpec& s) { return std::make_shared<Sor>(s.points, s.open); },
      writeSor);
  e.doc =
      "POV-Ray's surface of revolution: x y points (x >= 0, y increasing), r² a cubic in y between "
      "consecutive points, turned about the y axis (solid unless open).";
  Field<SorSpec> points = readByEntry<SorSpec>("points", AttrType::NumberList, "", {}, 2)
                              .doc(
                                  "The curve's x y pairs, 4 or more: x >= 0 the radius, y the "
                                  "height, increasing from the second to the next-to-last point; "
                                  "the first and last only steer the slopes at the ends.");
  points.info.required = true;
  e.fields = {std::move(points),
              booleanField("open", &SorSpec::open)
                  .doc("Without the discs at the bottom and the top (then not a solid).")};
  e.finish = readSor;
  e.notSolid = [](const SorSpec& s) { return s.open ? std::string("it is open") : std::string(); };
  // No image mapping; POV-Ray's uv_mapping reads u the other way (ImageMapping::uvMirrored).
  e.povImageMapping = [](const SorSpec&) {
    ImageMapping m;
    m.uvMirrored = true;
    return m;
  };
  e.samples = [] {
    using V = std::vector<Vec2>;
    return std::vector<std::pair<std::string, SorSpec>>{
        {"sor cylinder", {V{{1, -1}, {1, 0}, {1, 1}, {1, 2}}, false}},
        {"sor vase",
         {V{{0, -0.5}, {0.6, 0}, {0.9, 0.4}, {0.4, 1}, {0.5, 1.4}, {0.7, 1.6}, {0.8, 1.8}}, false}},
        {"sor bulb closing at the axis",
         {V{{0.5, -0.5}, {0, 0}, {0.8, 0.5}, {0, 1}, {0.5, 1.5}}, false}},
        {"open sor vase",
         {V{{0, -0.5}, {0.6, 0}, {0.9, 0.4}, {0.4, 1}, {0.5, 1.4}, {0.7, 1.6}}, true}}};
  };
  return e;
}

}  // namespace lucent
