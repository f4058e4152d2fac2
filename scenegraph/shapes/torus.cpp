// <torus major="1" minor="0.25"/>: in the xz-plane around the y axis (primitives/torus.h).
// A minor radius at or above the major one (a horn or spindle torus) is accepted, as
// POV-Ray accepts it: the surface is still the points at distance `minor` from the circle.
#include "scenegraph/shape_type.h"

#include "primitives/torus.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<TorusSpec> shapeEntry<TorusSpec>() {
  ShapeEntry<TorusSpec> e(
      "torus", "tori", [](const TorusSpec& s) { return std::make_shared<Torus>(s.major, s.minor); },
      [](const TorusSpec& s, PovShapeOut& out) {
        out.open("torus");  // POV-Ray's lies in the xz-plane around the y axis too
        out.line(fmt::format("{}, {}", out.number(s.major), out.number(s.minor)));
      });
  e.doc = "A torus in the xz-plane around the y axis (solid).";
  e.fields = {
      numberField("major", &TorusSpec::major, NumberRule::positive())
          .doc("Radius of the ring's centre line, around the y axis."),
      numberField("minor", &TorusSpec::minor, NumberRule::positive()).doc("Radius of the tube.")};
  // No image mapping; POV-Ray's uv_mapping reads u the other way (ImageMapping::uvMirrored).
  e.povImageMapping = [](const TorusSpec&) {
    ImageMapping m;
    m.uvMirrored = true;
    return m;
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, TorusSpec>>{{"torus", {1.0, 0.25}},
                                                          {"thin torus", {2.0, 0.01}},
                                                          {"fat torus", {1.0, 0.9}},
                                                          {"spindle torus", {1.0, 1.3}}};
  };
  return e;
}

}  // namespace lucent
