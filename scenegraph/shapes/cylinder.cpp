// <cylinder base="0 0 0" cap="0 1 0" radius="1" open="false"/>: solid unless open
// (primitives/cylinder.h).
#include "scenegraph/shape_type.h"

#include "primitives/cylinder.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<CylinderSpec> shapeEntry<CylinderSpec>() {
  ShapeEntry<CylinderSpec> e(
      "cylinder", "cylinders",
      [](const CylinderSpec& s) {
        return std::make_shared<Cylinder>(s.base, s.cap, s.radius, s.open);
      },
      [](const CylinderSpec& s, PovShapeOut& out) {
        out.open("cylinder");
        out.line(
            fmt::format("{}, {}, {}", out.vector(s.base), out.vector(s.cap), out.number(s.radius)));
        if (s.open) out.line("open");
      });
  e.doc = "A cylinder from base to cap (solid unless open).";
  e.fields = {vectorField("base", &CylinderSpec::base).doc("Centre of the base cap."),
              vectorField("cap", &CylinderSpec::cap).doc("Centre of the top cap."),
              numberField("radius", &CylinderSpec::radius, NumberRule::positive()).doc("Radius."),
              booleanField("open", &CylinderSpec::open).doc("true: no end caps (then not solid).")};
  e.finish = [](CylinderSpec& c, AttributeInput& in) {
    if (c.base == c.cap)
      in.attrError(in.has("cap") ? "cap" : "base",
                   "'base' and 'cap' must differ (the axis would have no length)");
  };
  e.notSolid = [](const CylinderSpec& c) {
    return c.open ? std::string("it is open") : std::string();
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, CylinderSpec>>{
        {"cylinder", {Vec3(0.1, 0.2, 0.3), Vec3(1, 2, -1), 0.6, false}},
        {"open cylinder", {Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, true}}};
  };
  return e;
}

}  // namespace lucent
