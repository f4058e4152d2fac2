// <box min="-1 -1 -1" max="1 1 1"/>: a solid axis-aligned box (primitives/box.h).
#include "scenegraph/shape_type.h"

#include "primitives/box.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<BoxSpec> shapeEntry<BoxSpec>() {
  ShapeEntry<BoxSpec> e(
      "box", "boxes", [](const BoxSpec& s) { return std::make_shared<Box>(s.min, s.max); },
      [](const BoxSpec& s, PovShapeOut& out) {
        out.open("box");
        out.line(fmt::format("{}, {}", out.vector(s.min), out.vector(s.max)));
      });
  e.doc = "An axis-aligned box from min to max (solid).";
  e.fields = {vectorField("min", &BoxSpec::min).doc("Minimum corner."), vectorField("max", &BoxSpec::max).doc("Maximum corner: each coordinate must be above min's.")};
  e.finish = [](BoxSpec& b, AttributeInput& in) {
    for (int k = 0; k < 3; ++k)
      if (!(b.min[k] < b.max[k])) {
        in.attrError(in.has("max") ? "max" : "min",
                     fmt::format("'min' must be below 'max' in every coordinate, but {} {} >= {}",
                                 "xyz"[k], b.min[k], b.max[k]));
        break;
      }
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, BoxSpec>>{{"box", {Vec3(-1, -0.5, 0), Vec3(1, 2, 3)}},
                                                        {"thin box", {Vec3(-1, -1e-3, -1), Vec3(1, 1e-3, 1)}}};
  };
  return e;
}

}  // namespace lucent
