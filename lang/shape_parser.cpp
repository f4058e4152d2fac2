// The parameters of the contract's simple shapes (contract, "Geometry nodes"):
//   <sphere center="0 0 0" radius="1"/>           <box min="-1 -1 -1" max="1 1 1"/>
//   <cylinder base="0 0 0" cap="0 1 0" radius="1" open="false"/>
//   <cone base="0 0 0" base-radius="1" cap="0 1 0" cap-radius="0" open="false"/>
//   <torus major="1" minor="0.25"/>   (in the xz-plane around the y axis)
//   <plane normal="0 1 0" offset="0"/>   <disc center="0 0 0" normal="0 1 0" radius="1" inner-radius="0"/>
//   <triangle a b c [na nb nc]/>       (a, b and c are required)
// Normals are normalised on load; a zero normal is an error.
//
// A torus whose minor radius reaches or exceeds its major radius (a horn or spindle torus)
// is accepted, as POV-Ray accepts it: the surface is still the points at distance `minor`
// from the circle of radius `major`.
#include "element_parsers.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace lucent {

namespace {

using ShapeParser = std::function<ShapeSpec(ElementReader&)>;

struct ShapeEntry {
  std::string_view element;
  std::vector<std::string_view> attributes;
  ShapeParser parse;
};

ShapeSpec parseSphere(ElementReader& r) {
  SphereSpec s;
  s.center = r.vector("center", s.center);
  s.radius = r.number("radius", s.radius, NumberRule::positive());
  return s;
}

ShapeSpec parseBox(ElementReader& r) {
  BoxSpec b;
  b.min = r.vector("min", b.min);
  b.max = r.vector("max", b.max);
  for (int k = 0; k < 3; ++k)
    if (!(b.min[k] < b.max[k])) {
      r.attrError(r.has("max") ? "max" : "min",
                  fmt::format("'min' must be below 'max' in every coordinate, but {} {} >= {}",
                              "xyz"[k], b.min[k], b.max[k]));
      break;
    }
  return b;
}

void requireDistinct(ElementReader& r, const Vec3& base, const Vec3& cap) {
  if (base == cap) r.attrError(r.has("cap") ? "cap" : "base", "'base' and 'cap' must differ (the axis would have no length)");
}

ShapeSpec parseCylinder(ElementReader& r) {
  CylinderSpec c;
  c.base = r.vector("base", c.base);
  c.cap = r.vector("cap", c.cap);
  c.radius = r.number("radius", c.radius, NumberRule::positive());
  c.open = r.boolean("open", c.open);
  requireDistinct(r, c.base, c.cap);
  return c;
}

ShapeSpec parseCone(ElementReader& r) {
  ConeSpec c;
  c.base = r.vector("base", c.base);
  c.baseRadius = r.number("base-radius", c.baseRadius, NumberRule::nonNegative());
  c.cap = r.vector("cap", c.cap);
  c.capRadius = r.number("cap-radius", c.capRadius, NumberRule::nonNegative());
  c.open = r.boolean("open", c.open);
  requireDistinct(r, c.base, c.cap);
  if (c.baseRadius == 0.0 && c.capRadius == 0.0)
    r.error("<cone>: 'base-radius' and 'cap-radius' are both 0, so the cone has no surface");
  return c;
}

ShapeSpec parseTorus(ElementReader& r) {
  TorusSpec t;
  t.major = r.number("major", t.major, NumberRule::positive());
  t.minor = r.number("minor", t.minor, NumberRule::positive());
  return t;
}

ShapeSpec parsePlane(ElementReader& r) {
  PlaneSpec p;
  p.normal = r.direction("normal", p.normal);
  p.offset = r.number("offset", p.offset);
  return p;
}

ShapeSpec parseDisc(ElementReader& r) {
  DiscSpec d;
  d.center = r.vector("center", d.center);
  d.normal = r.direction("normal", d.normal);
  d.radius = r.number("radius", d.radius, NumberRule::positive());
  d.innerRadius = r.number("inner-radius", d.innerRadius, NumberRule::nonNegative());
  if (d.innerRadius >= d.radius)
    r.attrError("inner-radius", fmt::format("'inner-radius' ({}) must be smaller than 'radius' ({})",
                                            d.innerRadius, d.radius));
  return d;
}

ShapeSpec parseTriangle(ElementReader& r) {
  TriangleSpec t;
  bool complete = true;
  for (const char* corner : {"a", "b", "c"})
    if (!r.has(corner)) {
      r.error(std::string("<triangle> needs the attribute '") + corner + "' (its corners a, b and c)");
      complete = false;
    }
  t.a = r.vector("a", t.a);
  t.b = r.vector("b", t.b);
  t.c = r.vector("c", t.c);
  Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
  if (complete && !r.failed() &&
      !(glm::length(glm::cross(e1, e2)) > 1e-12 * glm::length(e1) * glm::length(e2)))
    r.error("<triangle>: the corners a, b and c lie on one line, so the triangle has no area");

  int given = r.has("na") + r.has("nb") + r.has("nc");
  if (given == 3) {
    t.normals = std::array<Vec3, 3>{r.direction("na", Vec3(0.0)), r.direction("nb", Vec3(0.0)),
                                     r.direction("nc", Vec3(0.0))};
  } else if (given > 0) {
    r.error("<triangle>: give all three vertex normals na, nb and nc, or none");
  }
  return t;
}

const std::vector<ShapeEntry>& shapeTable() {
  // One explicit table maps element names to their parsers (no self-registration).
  static const std::vector<ShapeEntry> table{
      {"sphere", {"center", "radius"}, parseSphere},
      {"box", {"min", "max"}, parseBox},
      {"cylinder", {"base", "cap", "radius", "open"}, parseCylinder},
      {"cone", {"base", "base-radius", "cap", "cap-radius", "open"}, parseCone},
      {"torus", {"major", "minor"}, parseTorus},
      {"plane", {"normal", "offset"}, parsePlane},
      {"disc", {"center", "normal", "radius", "inner-radius"}, parseDisc},
      {"triangle", {"a", "b", "c", "na", "nb", "nc"}, parseTriangle},
      {"mesh", {"src", "positions", "indices", "normals", "uvs", "smooth"}, parseMesh},
  };
  return table;
}

const ShapeEntry* findShape(std::string_view name) {
  for (const ShapeEntry& e : shapeTable())
    if (e.element == name) return &e;
  return nullptr;
}

}  // namespace

bool isShapeElement(std::string_view name) { return findShape(name) != nullptr; }

const std::vector<std::string_view>& shapeAttributes(std::string_view element) {
  static const std::vector<std::string_view> none;
  const ShapeEntry* e = findShape(element);
  return e ? e->attributes : none;
}

std::optional<ShapeSpec> parseShape(ElementReader& r) {
  const ShapeEntry* e = findShape(r.element().name());
  if (!e) return std::nullopt;
  return e->parse(r);
}

}  // namespace lucent
