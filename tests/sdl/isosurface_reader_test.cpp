// POV-Ray's isosurface read into Lucent's (sdl/read_isosurface.cpp): the function as Lucent
// expression text in Lucent's space (z negated), the container, POV-Ray's parameters and
// its corrections, and the functions Lucent cannot write refused where they are.
#include <catch2/catch.hpp>

#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

SceneLoad load(const std::string& text, CollectedOutput& out) {
  Options options;
  options.imageWidth = 160;
  options.imageHeight = 120;
  options.output = &out;
  SceneLoad l = loadSceneText("test.pov", text, sdltest::dataFolder(), options);
  for (const Diagnostic& d : l.diagnostics.all()) UNSCOPED_INFO(d.str());
  return l;
}

const IsosurfaceSpec& isoOf(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const Node& n = *scene.root->children[i];
  REQUIRE(n.shape);
  REQUIRE(std::holds_alternative<IsosurfaceSpec>(*n.shape));
  return std::get<IsosurfaceSpec>(*n.shape);
}

}  // namespace

TEST_CASE("isosurface: the function in Lucent's space, and POV-Ray's parameters",
          "[sdl][scene][isosurface]") {
  CollectedOutput out;
  SceneLoad l = load(
      "#declare R = 0.5;\n"
      "#declare F = function(a, b, c) { a + 2*c - R }\n"
      "isosurface { function { F(x, y, z) } contained_by { box { <-1, -2, -3>, <4, 5, 6> } }\n"
      "  threshold 0.25 accuracy 0.01 max_gradient 3 open }\n"
      "isosurface { function { x*y } contained_by { sphere { <1, 2, 3>, 4 } } }\n"
      "isosurface { function { z } }\n",
      out);
  REQUIRE(l.scene);
  const IsosurfaceSpec& a = isoOf(*l.scene, 0);
  CHECK(a.function == "(((x + (2 * (-z))) - 0.5))");
  CHECK(a.container.kind == IsosurfaceContainer::Box);
  CHECK(a.container.min == Vec3(-1, -2, -6));
  CHECK(a.container.max == Vec3(4, 5, 3));
  CHECK(a.threshold == 0.25);
  CHECK(a.accuracy == 0.01);
  CHECK(a.maxGradient == 3.0);
  CHECK(a.open);
  // The field is F at (x, y, -z): POV-Ray's point of the Lucent point.
  CHECK(a.field->value(Vec3(1, 0, 2)) == 1.0 + 2.0 * -2.0 - 0.5);
  const IsosurfaceSpec& b = isoOf(*l.scene, 1);
  CHECK(b.function == "(x * y)");
  CHECK(b.container.kind == IsosurfaceContainer::Sphere);
  CHECK(b.container.center == Vec3(1, 2, -3));
  CHECK(b.container.radius == 4.0);
  // POV-Ray's defaults.
  const IsosurfaceSpec& c = isoOf(*l.scene, 2);
  CHECK(c.function == "(-z)");
  CHECK(c.container.kind == IsosurfaceContainer::Box);
  CHECK(c.container.min == Vec3(-1));
  CHECK(c.container.max == Vec3(1));
  CHECK(c.maxGradient == 1.1);
  CHECK(c.accuracy == 0.001);
  CHECK(!c.open);
}

TEST_CASE("isosurface: what cannot be written as a Lucent expression is refused where it is",
          "[sdl][scene][isosurface]") {
  CollectedOutput out;
  SceneLoad l = load(
      "#include \"functions.inc\"\n"
      "#declare F = function { f_sphere(x, y, z, 1) + 0.1*f_ridged_mf(x, y, z, 1, 2, 6, 1, 1, 0) "
      "}\n"
      "isosurface { function { F(x, y, z) } }\n"
      "isosurface { function { f_helix2(x, y, z, 1, 2, 3, 4, 5, 6, 7) } }\n"
      "isosurface { function { sum(i, 1, 3, x) } }\n",
      out);
  CHECK(!l.scene);
  std::vector<std::string> errors;
  for (const Diagnostic& d : l.diagnostics.all()) errors.push_back(d.str());
  REQUIRE(errors.size() == 3);
  CHECK(errors[0].rfind("test.pov:3:14: error: this isosurface's function cannot be imported: "
                        "'f_ridged_mf' (internal(59)) is a noise function Lucent does not evaluate",
                        0) == 0);
  CHECK(errors[0].find("test.pov:2:52: note: the cause, in the function's text") !=
        std::string::npos);
  CHECK(errors[1].rfind("test.pov:4:14: error: this isosurface's function cannot be imported: "
                        "'f_helix2' (internal(26)) is not evaluated",
                        0) == 0);
  CHECK(errors[2].rfind("test.pov:5:14: error: this isosurface's function cannot be imported: "
                        "sum() and prod() cannot be written",
                        0) == 0);
}
