// <sphere center="0 0 0" radius="1"/>: a solid ball (primitives/sphere.h).
#include "scenegraph/shape_type.h"

#include "primitives/sphere.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<SphereSpec> shapeEntry<SphereSpec>() {
  ShapeEntry<SphereSpec> e(
      "sphere", "spheres",
      [](const SphereSpec& s) { return std::make_shared<Sphere>(s.center, s.radius); },
      [](const SphereSpec& s, PovShapeOut& out) {
        out.open("sphere");
        out.line(fmt::format("{}, {}", out.vector(s.center), out.number(s.radius)));
      });
  e.doc = "A sphere (solid).";
  e.fields = {vectorField("center", &SphereSpec::center).doc("Centre."),
              numberField("radius", &SphereSpec::radius, NumberRule::positive()).doc("Radius.")};
  // POV-Ray's map_type 1 (spherical), turned to Lucent's longitude and latitude.
  e.povImageMapping = [](const SphereSpec& s) {
    ImageMapping m;
    m.kind = ImageMapping::Spherical;
    m.center = s.center;
    m.uvMirrored = true;
    return m;
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, SphereSpec>>{{"sphere", {Vec3(0.5, -0.25, 1.0), 1.5}},
                                                           {"small sphere", {Vec3(0.0), 1e-3}}};
  };
  return e;
}

}  // namespace lucent
