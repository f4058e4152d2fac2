// <isosurface function="..." threshold container min max center radius max-gradient
// accuracy open/>: POV-Ray's isosurface (primitives/isosurface.h). The function is an
// expression of the scene language in x, y, z, compiled where it is read (its other names
// are parameters, taken as numbers then); POV-Ray gets it as a function { } body
// (PovShapeOut::function, written by povray/pov_function.h).
#include "container_fields.h"

#include "scenegraph/pigment_function.h"
#include "scenegraph/shape_type.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace lucent {

namespace {

// The samples' functions, written in C++ (the registry knows no expression compiler).
class SampleField final : public ScalarField {
 public:
  explicit SampleField(double (*f)(const Vec3&)) : f_(f) {}
  double value(const Vec3& p) const override { return f_(p); }

 private:
  double (*f_)(const Vec3&);
};

IsosurfaceSpec sample(const char* text, double (*f)(const Vec3&), IsosurfaceContainer c,
                      bool open = false) {
  IsosurfaceSpec s;
  s.function = text;
  s.field = std::make_shared<SampleField>(f);
  s.container = c;
  s.open = open;
  return s;
}

}  // namespace

ChildElementInfo pigmentFunctionChild() {
  AttributeInfo name;
  name.name = "name";
  name.type = AttrType::Text;
  name.required = true;
  name.doc = "How the function calls it: name(x, y, z).";
  AttributeInfo component;
  component.name = "component";
  component.type = AttrType::Choice;
  component.required = true;
  component.doc = "The component of the colour the call gives.";
  component.choices.assign(std::begin(kPigmentComponentNames), std::end(kPigmentComponentNames));
  return {"pigment-function",
          "A texture the function calls by name with a point (POV-Ray's pigment "
          "function): the component of its colour there.",
          {name, component},
          false,
          "    <xs:group ref=\"nestedTexture\"/>\n"};
}

template <>
ShapeEntry<IsosurfaceSpec> shapeEntry<IsosurfaceSpec>() {
  ShapeEntry<IsosurfaceSpec> e(
      "isosurface", "isosurfaces",
      [](const IsosurfaceSpec& s) {
        Isosurface::Params p;
        p.field = s.field;
        p.threshold = s.threshold;
        p.container = s.container;
        p.maxGradient = s.maxGradient;
        p.accuracy = s.accuracy;
        p.open = s.open;
        p.record = s.record;
        return std::make_shared<Isosurface>(std::move(p));
      },
      [](const IsosurfaceSpec& s, PovShapeOut& out) {
        std::string problem;
        std::optional<std::string> body =
            out.function(s.function, s.constants, s.pigments, problem);
        if (!body) {
          out.error("<isosurface> function: " + problem);
          return;
        }
        out.open("isosurface");
        out.line("function { " + *body + " }");
        out.line(povContainer(s.container, out));
        out.line("threshold " + out.number(s.threshold));
        out.line("max_gradient " + out.number(s.maxGradient));
        out.line("accuracy " + out.number(s.accuracy));
        // Every crossing, as Lucent's CSG uses them (POV-Ray's default finds the first only).
        // Written for lone isosurfaces too: without it POV-Ray's image of the gallery scene
        // departs more from Lucent's (67 dB against 73), at twice POV-Ray's render time.
        out.line("all_intersections");
        if (s.open) out.line("open");
      });
  e.doc =
      "POV-Ray's isosurface: the solid where a function of x, y, z is below the threshold, within "
      "a "
      "box or sphere container (solid unless open).";
  // Its <pigment-function> children are read with the function (the language reads them).
  e.children = {pigmentFunctionChild()};
  Field<IsosurfaceSpec> function = readByEntry<IsosurfaceSpec>("function", AttrType::Text);
  function.info.required = true;
  e.fields = {
      std::move(function).doc(
          "An expression in x, y and z (the syntax of ${...} expressions, without ${}); other "
          "names are parameters, taken as numbers where the element is read."),
      numberField("threshold", &IsosurfaceSpec::threshold)
          .doc("The function's value on the surface; below it is inside."),
      numberField("max-gradient", &IsosurfaceSpec::maxGradient, NumberRule::positive())
          .doc("A bound on the function's gradient length, which the root search steps by; a "
               "render that sees a "
               "larger one warns with the largest it saw."),
      numberField("accuracy", &IsosurfaceSpec::accuracy, NumberRule::positive())
          .doc("How finely the ray is divided (object-space length) when crossings are sought."),
      booleanField("open", &IsosurfaceSpec::open)
          .doc("true: no surface where the container cuts the solid (then not solid).")};
  // The container's after the threshold, as the schema has always listed them.
  auto container = containerFields<IsosurfaceSpec>();
  e.fields.insert(e.fields.begin() + 2, container.begin(), container.end());
  e.finish = [](IsosurfaceSpec& s, AttributeInput& in) {
    if (auto f = in.function("function", {"x", "y", "z"})) {
      s.function = f->text;
      s.constants = f->constants;
      s.field = f->field;
      s.pigments = f->pigments;
    } else if (!in.has("function")) {
      in.error("<isosurface> needs a 'function' (an expression in x, y and z)");
    }
    s.container = readContainer(in);
  };
  e.notSolid = [](const IsosurfaceSpec& s) {
    return s.open ? std::string("it is open") : std::string();
  };
  e.samples = [] {
    IsosurfaceContainer box, ball;
    ball.kind = IsosurfaceContainer::Sphere;
    ball.radius = 1.5;
    return std::vector<std::pair<std::string, IsosurfaceSpec>>{
        {"sphere isosurface in a box",
         sample(
             "sqrt(x*x + y*y + z*z) - 0.8", [](const Vec3& p) { return glm::length(p) - 0.8; },
             box)},
        {"torus isosurface in a sphere",
         sample(
             "sqrt((sqrt(x*x + z*z) - 0.8)^2 + y*y) - 0.3",
             [](const Vec3& p) { return std::hypot(std::hypot(p.x, p.z) - 0.8, p.y) - 0.3; },
             ball)},
        {"plane isosurface cut by its box", sample(
                                                "y", [](const Vec3& p) { return p.y; }, box)},
        {"open sphere isosurface",
         sample(
             "sqrt(x*x + y*y + z*z) - 1.2", [](const Vec3& p) { return glm::length(p) - 1.2; }, box,
             true)}};
  };
  return e;
}

}  // namespace lucent
