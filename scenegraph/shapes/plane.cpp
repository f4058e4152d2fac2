// <plane normal="0 1 0" offset="0"/>: the points with N·x = offset, the half-space
// N·x < offset inside (primitives/plane.h); the normal is normalised on load.
#include "scenegraph/shape_type.h"

#include "primitives/plane.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<PlaneSpec> shapeEntry<PlaneSpec>() {
  ShapeEntry<PlaneSpec> e(
      "plane", "planes",
      [](const PlaneSpec& s) { return std::make_shared<Plane>(s.normal, s.offset); },
      [](const PlaneSpec& s, PovShapeOut& out) {
        out.open("plane");  // the same convention: n·x = d, inside n·x < d
        out.line(fmt::format("{}, {}", out.vector(s.normal), out.number(s.offset)));
      });
  e.doc = "An infinite plane N·x = offset; the half-space N·x < offset is inside (solid).";
  e.fields = {directionField("normal", &PlaneSpec::normal)
                  .doc("Normal N (normalised on load; outward: N·x < offset is inside)."),
              numberField("offset", &PlaneSpec::offset)
                  .doc("The plane is N·x = offset (distance from the origin along N).")};
  // (u, v) = (p·t1, p·t2) (primitives/plane.cpp): a planar image_map.
  e.povImageMapping = [](const PlaneSpec& s) {
    Vec3 t1, t2;
    planeTangents(s.normal, t1, t2);
    ImageMapping m;
    m.kind = ImageMapping::Planar;
    m.uvFromObject = rowsMatrix(Vec4(t1, 0.0), Vec4(t2, 0.0), Vec4(s.normal, 0.0));
    return m;
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, PlaneSpec>>{
        {"plane", {glm::normalize(Vec3(1, 2, -0.5)), 0.3}}};
  };
  return e;
}

}  // namespace lucent
