// <quadric a="1 1 1" b="0 0 0" c="0 0 0" d="-1"/>: the solid Q(p) < 0 of a second-degree
// polynomial (primitives/quadric.h), POV-Ray's quadric with the same coefficients.
#include "scenegraph/shape_type.h"

#include "primitives/quadric.h"

#include <fmt/format.h>

namespace lucent {

namespace {

QuadricCoefficients coefficients(const QuadricSpec& s) { return {s.a, s.b, s.c, s.d}; }

}  // namespace

template <>
ShapeEntry<QuadricSpec> shapeEntry<QuadricSpec>() {
  ShapeEntry<QuadricSpec> e(
      "quadric", "quadrics",
      [](const QuadricSpec& s) { return std::make_shared<Quadric>(coefficients(s)); },
      [](const QuadricSpec& s, PovShapeOut& out) {
        out.open("quadric");  // A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J
        out.line(fmt::format("{}, {}, {}, {}", out.vector(s.a), out.vector(s.b), out.vector(s.c),
                             out.number(s.d)));
      });
  e.doc =
      "The solid where a second-degree polynomial of x, y and z is below 0 (solid; unbounded "
      "unless an ellipsoid).";
  e.fields = {vectorField("a", &QuadricSpec::a).doc("Coefficients of x², y² and z²."),
              vectorField("b", &QuadricSpec::b).doc("Coefficients of xy, xz and yz."),
              vectorField("c", &QuadricSpec::c).doc("Coefficients of x, y and z."),
              numberField("d", &QuadricSpec::d).doc("The constant term.")};
  e.finish = [](QuadricSpec& q, AttributeInput& in) {
    if (q.a == Vec3(0.0) && q.b == Vec3(0.0) && q.c == Vec3(0.0))
      in.attrError(in.has("a") ? "a" : (in.has("b") ? "b" : (in.has("c") ? "c" : "a")),
                   "a quadric needs a non-zero coefficient in 'a', 'b' or 'c' (with only 'd' it "
                   "has no surface)");
  };
  e.samples = [] {
    return std::vector<std::pair<std::string, QuadricSpec>>{
        {"unit sphere", {}},
        {"ellipsoid off the origin", {Vec3(1, 4, 0.25), Vec3(0.5, 0, 0), Vec3(-2, 0, 1), -2}},
        {"cylinder along y", {Vec3(1, 0, 1), Vec3(0), Vec3(0), -1}},
        {"cone along y", {Vec3(1, -1, 1), Vec3(0), Vec3(0), 0}},
        {"hyperboloid of one sheet", {Vec3(1, -1, 1), Vec3(0), Vec3(0), -0.5}},
        {"paraboloid", {Vec3(1, 0, 1), Vec3(0), Vec3(0, -1, 0), 0}},
        {"plane as a quadric", {Vec3(0), Vec3(0), Vec3(0, 1, 0), -0.5}},
        {"saddle", {Vec3(0), Vec3(1, 0, 0), Vec3(0, -1, 0), 0}}};
  };
  return e;
}

}  // namespace lucent
