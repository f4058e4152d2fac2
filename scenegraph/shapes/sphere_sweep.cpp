// <sphere-sweep spline="linear" spheres="x y z r, ..." tolerance="1e-6"/>: POV-Ray 3.7's
// sphere_sweep (primitives/sphere_sweep.h), with POV-Ray's counts (linear 2 spheres or
// more, cubic and b-spline 4 or more). POV-Ray accepts negative radii; Lucent asks for
// radii >= 0, not all 0.
#include "scenegraph/shape_type.h"

#include "primitives/sphere_sweep.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent {

namespace {

const std::vector<std::string_view> kSplines = {"linear", "cubic", "b-spline"};
const char* const kPovSpline[] = {"linear_spline", "cubic_spline", "b_spline"};

void readSweep(SphereSweepSpec& s, AttributeInput& in) {
  s.spline = static_cast<SweepSpline>(in.choice("spline", 0, kSplines));
  if (in.failed()) return;
  if (!in.has("spheres")) {
    in.error("<sphere-sweep> needs 'spheres' (x y z radius of each control sphere)");
    return;
  }
  auto list = in.numbers("spheres");
  if (!list) return;
  if (list->size() % 4 != 0) {
    in.attrError(
        "spheres",
        fmt::format("needs x y z radius groups of 4 numbers, but has {} numbers", list->size()));
    return;
  }
  const size_t n = list->size() / 4;
  const size_t want = static_cast<size_t>(SphereSweep::minSpheres(s.spline));
  if (n < want) {
    in.attrError("spheres", fmt::format("a {} sphere sweep needs at least {} spheres, not {}",
                                        kSplines[static_cast<size_t>(s.spline)], want, n));
    return;
  }
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    const double* v = list->data() + 4 * i;
    SweepSphere sphere{Vec3(v[0], v[1], v[2]), v[3]};
    if (!isFinite(sphere.center) || !std::isfinite(sphere.radius)) {
      in.attrError("spheres", "must be finite numbers");
      return;
    }
    if (sphere.radius < 0.0) {
      in.attrError("spheres", fmt::format("sphere {} has radius {}: a radius must be >= 0", i + 1,
                                          sphere.radius));
      return;
    }
    any |= sphere.radius > 0.0;
    s.spheres.push_back(sphere);
  }
  if (!any) in.attrError("spheres", "every radius is 0: nothing is swept");
}

void writeSweep(const SphereSweepSpec& s, PovShapeOut& out) {
  out.open("sphere_sweep");
  out.line(kPovSpline[static_cast<size_t>(s.spline)]);
  out.line(fmt::format("{},", s.spheres.size()));
  for (size_t i = 0; i < s.spheres.size(); ++i)
    out.line(fmt::format("{}, {}{}", out.vector(s.spheres[i].center),
                         out.number(s.spheres[i].radius), i + 1 < s.spheres.size() ? "," : ""));
  out.line("tolerance " + out.number(s.tolerance));
}

SphereSweepSpec sample(SweepSpline spline, std::vector<SweepSphere> spheres) {
  SphereSweepSpec s;
  s.spline = spline;
  s.spheres = std::move(spheres);
  return s;
}

}  // namespace

template <>
ShapeEntry<SphereSweepSpec> shapeEntry<SphereSweepSpec>() {
  ShapeEntry<SphereSweepSpec> e(
      "sphere-sweep", "sphere sweeps",
      [](const SphereSweepSpec& s) { return std::make_shared<SphereSweep>(s.spline, s.spheres); },
      writeSweep);
  e.doc =
      "POV-Ray's sphere_sweep: the solid a sphere sweeps along a linear, Catmull-Rom (cubic) "
      "or B-spline path through control spheres (solid).";
  Field<SphereSweepSpec> spheres =
      readByEntry<SphereSweepSpec>("spheres", AttrType::NumberList, "", {}, 4)
          .doc(
              "The control spheres as x y z radius groups (radius >= 0): linear 2 or more, cubic "
              "and b-spline 4 or more.");
  spheres.info.required = true;
  e.fields = {
      std::move(spheres),
      readByEntry<SphereSweepSpec>("spline", AttrType::Choice, "linear", kSplines)
          .doc("linear (spheres joined by tangent cones) | cubic (Catmull-Rom, through the "
               "second to the last but one sphere) | b-spline (uniform cubic B-spline), as "
               "POV-Ray's."),
      numberField<SphereSweepSpec>("tolerance", &SphereSweepSpec::tolerance,
                                   NumberRule::between(0.0, kInf, "a number >= 0"))
          .doc("POV-Ray's depth tolerance, kept for export-pov; Lucent's own offsets make it "
               "unneeded, so it does not change Lucent's render.")};
  e.finish = readSweep;
  e.samples = [] {
    using S = SweepSpline;
    return std::vector<std::pair<std::string, SphereSweepSpec>>{
        {"linear sphere sweep capsule",
         sample(S::Linear, {{Vec3(-0.6, 0, 0), 0.4}, {Vec3(0.6, 0, 0), 0.4}})},
        {"linear sphere sweep of cones", sample(S::Linear, {{Vec3(-0.8, -0.5, 0), 0.5},
                                                            {Vec3(0, 0.3, 0.2), 0.2},
                                                            {Vec3(0.7, -0.2, -0.3), 0.35},
                                                            {Vec3(0.9, 0.6, 0), 0.0}})},
        {"cubic sphere sweep", sample(S::Cubic, {{Vec3(-1, -0.6, 0), 0.1},
                                                 {Vec3(-0.6, 0, 0), 0.3},
                                                 {Vec3(0, 0.4, 0.2), 0.2},
                                                 {Vec3(0.6, -0.1, 0), 0.35},
                                                 {Vec3(1, 0.5, -0.3), 0.1}})},
        {"b-spline sphere sweep", sample(S::BSpline, {{Vec3(-1, -0.6, 0), 0.3},
                                                      {Vec3(-0.6, 0.5, 0), 0.4},
                                                      {Vec3(0.2, 0.6, 0.3), 0.1},
                                                      {Vec3(0.6, -0.5, 0), 0.4},
                                                      {Vec3(1, 0.5, -0.3), 0.2}})}};
  };
  return e;
}

}  // namespace lucent
