// <superellipsoid e="1" n="1"/>: the solid filling [-1, 1]³ with POV-Ray's exponents and
// axes (primitives/superellipsoid.h). POV-Ray takes any exponent (0 divides by zero, a
// negative one breaks the shape); Lucent keeps to [0.01, 10], from nearly a box to a
// sharply pinched star, where its root isolation is tested.
#include "scenegraph/shape_type.h"

#include "primitives/superellipsoid.h"

#include <fmt/format.h>

namespace lucent {

template <>
ShapeEntry<SuperellipsoidSpec> shapeEntry<SuperellipsoidSpec>() {
  ShapeEntry<SuperellipsoidSpec> e(
      "superellipsoid", "superellipsoids",
      [](const SuperellipsoidSpec& s) { return std::make_shared<Superellipsoid>(s.e, s.n); },
      [](const SuperellipsoidSpec& s, PovShapeOut& out) {
        out.open("superellipsoid");  // the same axes: the poles on z in both
        out.line(fmt::format("<{}, {}>", out.number(s.e), out.number(s.n)));
      });
  e.doc = "A superellipsoid filling the cube from -1 to 1, its poles on the z axis (solid).";
  const NumberRule exponent = NumberRule::between(
      Superellipsoid::kMinExponent, Superellipsoid::kMaxExponent, "a number from 0.01 to 10");
  e.fields = {
      numberField("e", &SuperellipsoidSpec::e, exponent)
          .doc("East-west exponent: the cross-sections parallel to the xy-plane; 1 round, small "
               "values square, 2 a diamond, above 2 pinched."),
      numberField("n", &SuperellipsoidSpec::n, exponent)
          .doc("North-south exponent: the profile along the z axis, with the same meaning.")};
  e.samples = [] {
    return std::vector<std::pair<std::string, SuperellipsoidSpec>>{
        {"round superellipsoid", {1.0, 1.0}},       {"boxy superellipsoid", {0.1, 0.1}},
        {"rounded box superellipsoid", {0.3, 0.6}}, {"octahedral superellipsoid", {2.0, 2.0}},
        {"pinched superellipsoid", {3.0, 2.5}},     {"mixed superellipsoid", {0.5, 3.0}}};
  };
  return e;
}

}  // namespace lucent
