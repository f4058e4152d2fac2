// <cone base="0 0 0" base-radius="1" cap="0 1 0" cap-radius="0" open="false"/>: solid
// unless open (primitives/cone.h).
#include "scenegraph/shape_type.h"

#include "primitives/cone.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<ConeSpec> shapeEntry<ConeSpec>() {
  ShapeEntry<ConeSpec> e(
      "cone", "cones",
      [](const ConeSpec& s) {
        return std::make_shared<Cone>(s.base, s.baseRadius, s.cap, s.capRadius, s.open);
      },
      [](const ConeSpec& s, PovShapeOut& out) {
        out.open("cone");
        out.line(fmt::format("{}, {}, {}, {}", out.vector(s.base), out.number(s.baseRadius),
                             out.vector(s.cap), out.number(s.capRadius)));
        if (s.open) out.line("open");
      });
  e.doc = "A cone or truncated cone from base to cap (solid unless open).";
  e.fields = {vectorField("base", &ConeSpec::base).doc("Centre of the base."),
              numberField("base-radius", &ConeSpec::baseRadius, NumberRule::nonNegative())
                  .doc("Radius at base."),
              vectorField("cap", &ConeSpec::cap).doc("Centre of the other end."),
              numberField("cap-radius", &ConeSpec::capRadius, NumberRule::nonNegative())
                  .doc("Radius at cap; 0 gives a pointed cone."),
              booleanField("open", &ConeSpec::open).doc("true: no end caps (then not solid).")};
  e.finish = [](ConeSpec& c, AttributeInput& in) {
    if (c.base == c.cap)
      in.attrError(in.has("cap") ? "cap" : "base",
                   "'base' and 'cap' must differ (the axis would have no length)");
    if (c.baseRadius == 0.0 && c.capRadius == 0.0)
      in.error("<cone>: 'base-radius' and 'cap-radius' are both 0, so the cone has no surface");
  };
  e.notSolid = [](const ConeSpec& c) { return c.open ? std::string("it is open") : std::string(); };
  e.samples = [] {
    return std::vector<std::pair<std::string, ConeSpec>>{
        {"cone", {Vec3(0, 0, 0), 1.0, Vec3(0.3, 2, 0.1), 0.0, false}},
        {"truncated cone", {Vec3(0, 1, 0), 0.3, Vec3(0, -1, 0.5), 0.9, false}},
        {"apex-at-base cone", {Vec3(0, 0, 0), 0.0, Vec3(0, 0, 2), 1.0, false}},
        {"open cone", {Vec3(0, 0, 0), 1.0, Vec3(0, 1, 0), 0.5, true}}};
  };
  return e;
}

}  // namespace lucent
