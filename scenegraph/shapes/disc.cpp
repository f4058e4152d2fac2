// <disc center="0 0 0" normal="0 1 0" radius="1" inner-radius="0"/>: a flat disc,
// optionally with a hole; not a solid (primitives/disc.h).
#include "scenegraph/shape_type.h"

#include "primitives/disc.h"
#include "primitives/plane.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<DiscSpec> shapeEntry<DiscSpec>() {
  ShapeEntry<DiscSpec> e(
      "disc", "discs",
      [](const DiscSpec& s) {
        return std::make_shared<Disc>(s.center, s.normal, s.radius, s.innerRadius);
      },
      [](const DiscSpec& s, PovShapeOut& out) {
        out.open("disc");
        std::string hole = s.innerRadius > 0.0 ? ", " + out.number(s.innerRadius) : "";
        out.line(fmt::format("{}, {}, {}{}", out.vector(s.center), out.vector(s.normal),
                             out.number(s.radius), hole));
      });
  e.doc = "A flat disc or annulus (not solid).";
  e.fields = {vectorField("center", &DiscSpec::center).doc("Centre."),
              directionField("normal", &DiscSpec::normal).doc("Normal (normalised on load)."),
              numberField("radius", &DiscSpec::radius, NumberRule::positive()).doc("Outer radius."),
              numberField("inner-radius", &DiscSpec::innerRadius, NumberRule::nonNegative())
                  .doc("Radius of the hole (below radius).")};
  e.finish = [](DiscSpec& d, AttributeInput& in) {
    if (d.innerRadius >= d.radius)
      in.attrError("inner-radius",
                   fmt::format("'inner-radius' ({}) must be smaller than 'radius' ({})",
                               d.innerRadius, d.radius));
  };
  e.notSolid = [](const DiscSpec&) { return std::string("a disc encloses no volume"); };
  // (u, v) = ((p − c)·t1, (p − c)·t2) (primitives/disc.cpp): a planar image_map.
  e.povImageMapping = [](const DiscSpec& s) {
    Vec3 t1, t2;
    planeTangents(s.normal, t1, t2);
    ImageMapping m;
    m.kind = ImageMapping::Planar;
    Mat4 toCentre(1.0);
    toCentre[3] = Vec4(-s.center, 1.0);
    m.uvFromObject = rowsMatrix(Vec4(t1, 0.0), Vec4(t2, 0.0), Vec4(s.normal, 0.0)) * toCentre;
    return m;
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, DiscSpec>>{
        {"disc", {Vec3(0.2, 0.1, 0), glm::normalize(Vec3(0, 1, 1)), 1.0, 0.3}}};
  };
  return e;
}

}  // namespace lucent
