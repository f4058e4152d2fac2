// <ovus bottom-radius="1" top-radius="0.5"/>: POV-Ray 3.7's ovus (primitives/ovus.h). Radii
// >= 0, not both 0; a top radius at or above twice the bottom one is the top sphere, as
// POV-Ray substitutes it (export-pov writes that sphere, so POV-Ray gives no warning).
#include "scenegraph/shape_type.h"

#include "primitives/ovus.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<OvusSpec> shapeEntry<OvusSpec>() {
  ShapeEntry<OvusSpec> e(
      "ovus", "ovuses",
      [](const OvusSpec& s) { return std::make_shared<Ovus>(s.bottomRadius, s.topRadius); },
      [](const OvusSpec& s, PovShapeOut& out) {
        if (s.topRadius >= 2.0 * s.bottomRadius) {
          out.open("sphere");
          out.line(fmt::format("{}, {}", out.vector(Vec3(0.0, s.bottomRadius, 0.0)),
                               out.number(s.topRadius)));
          return;
        }
        out.open("ovus");  // about the y axis in both spaces
        out.line(fmt::format("{}, {}", out.number(s.bottomRadius), out.number(s.topRadius)));
      });
  e.doc =
      "POV-Ray's ovus: a sphere at the origin and one on its top point joined smoothly by a "
      "surface of revolution, an egg about the y axis (solid).";
  e.fields = {
      numberField("bottom-radius", &OvusSpec::bottomRadius, NumberRule::nonNegative())
          .doc("Radius of the sphere centred at the origin, >= 0."),
      numberField("top-radius", &OvusSpec::topRadius, NumberRule::nonNegative())
          .doc("Radius of the sphere centred at (0, bottom-radius, 0), >= 0; at or above twice "
               "bottom-radius the ovus is that sphere.")};
  // No image mapping; POV-Ray's uv_mapping reads u the other way (ImageMapping::uvMirrored).
  e.povImageMapping = [](const OvusSpec&) {
    ImageMapping m;
    m.uvMirrored = true;
    return m;
  };
  e.finish = [](OvusSpec& s, AttributeInput& in) {
    if (!in.failed() && s.bottomRadius == 0.0 && s.topRadius == 0.0)
      in.error("<ovus> needs a radius above 0: both are 0");
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, OvusSpec>>{{"ovus", {1.0, 0.5}},
                                                         {"ovus wider at the top", {1.0, 1.6}},
                                                         {"ovus of equal radii", {0.8, 0.8}},
                                                         {"ovus of top radius 0", {1.0, 0.0}},
                                                         {"ovus as its top sphere", {0.5, 1.2}}};
  };
  return e;
}

}  // namespace lucent
