// Spline functions (`#declare S = function { spline { ... } }`) called as S(t).y inside
// isosurfaces and function patterns: the importer writes each call's component as the
// spline's piecewise polynomial (sdl/spline_text.cpp). Its text, evaluated by Lucent's
// expressions, against Spline::at (held to POV-Ray by the differential test) at every kind's
// segments, entries and ends; and a scene against POV-Ray's image.
#include "pov_meaning_support.h"
#include "scene_read_support.h"

#include "lang/expression.h"
#include "sdl/spline.h"

#include <catch2/catch.hpp>

using namespace lucent;

namespace {

// The one name `t`.
class ParameterNames : public ExpressionNames {
 public:
  double t = 0.0;
  std::optional<double> number(std::string_view name, std::string&, bool& known) override {
    known = name == "t";
    if (!known) return std::nullopt;
    return t;
  }
  std::vector<std::string> visibleNames() override { return {"t"}; }
};

sdl::Spline makeSpline(sdl::SplineKind kind) {
  sdl::SplineEntries entries;
  // Uneven parameters, given out of order; three components vary.
  entries.insert(0.25, {0.25, 0.5, -1, 0, 0});
  entries.insert(-0.5, {0, 0, 0, 0, 0});
  entries.insert(0.5, {0.5, 0.1, 2, 0, 0});
  entries.insert(1.75, {0.75, 0.9, 0.5, 0, 0});
  entries.insert(2, {1, -3, 0, 0, 0});
  entries.insert(3.5, {1.5, 2, 1, 0, 0});
  return entries.make(kind, 3);
}

}  // namespace

TEST_CASE("a spline function's text gives the spline's value for every kind",
          "[sdl][function][spline]") {
  ExpressionEvaluator evaluator;
  ParameterNames names;
  for (sdl::SplineKind kind : {sdl::SplineKind::Linear, sdl::SplineKind::Quadratic,
                               sdl::SplineKind::Cubic, sdl::SplineKind::Natural}) {
    const sdl::Spline s = makeSpline(kind);
    for (int member : {0, 1, 2, 5}) {
      const std::string text = sdl::splineText(s, "t", member);
      std::vector<double> ts = {-2, -0.5, 0.25, 0.5, 1.75, 2, 3.5, 9};  // ends and entries
      for (int i = 0; i <= 200; ++i) ts.push_back(-1 + i * 0.0251);     // every segment
      for (double t : ts) {
        INFO("kind " << static_cast<int>(kind) << ", member " << member << ", t " << t);
        names.t = t;
        ExpressionError error;
        const std::optional<double> got = evaluator.evaluate(text, names, error);
        REQUIRE(got);
        const std::array<double, 5> v = s.at(t);
        const double want = member == 5 ? 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2] : v[member];
        // The same formula up to the order of its roundings.
        CHECK(*got == Approx(want).margin(1e-12));
      }
    }
  }
}

TEST_CASE("splines of one and two entries are written as Spline::at holds them",
          "[sdl][function][spline]") {
  ExpressionEvaluator evaluator;
  ParameterNames names;
  sdl::SplineEntries one;
  one.insert(1, {3, 4, 0, 0, 0});
  sdl::SplineEntries two = one;
  two.insert(2, {5, 0, 0, 0, 0});
  for (sdl::SplineKind kind : {sdl::SplineKind::Linear, sdl::SplineKind::Quadratic,
                               sdl::SplineKind::Cubic, sdl::SplineKind::Natural})
    for (const sdl::SplineEntries* entries : {&one, &two}) {
      const sdl::Spline s = entries->make(kind, 2);
      for (double t : {0.0, 1.0, 1.5, 2.0, 3.0}) {
        names.t = t;
        ExpressionError error;
        INFO("kind " << static_cast<int>(kind) << ", t " << t << ", entries " << s.entries.size());
        CHECK(*evaluator.evaluate(sdl::splineText(s, "t", 0), names, error) == s.at(t)[0]);
      }
    }
  // Worked out by hand: cubic_spline with two entries is their mean everywhere.
  names.t = 7;
  ExpressionError error;
  CHECK(*evaluator.evaluate(sdl::splineText(two.make(sdl::SplineKind::Cubic, 2), "t", 0), names,
                            error) == 4.0);
}

TEST_CASE("a function pattern and an isosurface of a spline function match POV-Ray's image",
          "[sdl][function][spline][povray]") {
  // splinefunction.pov's box (a function pattern of the spline's y, through a pigment
  // function's gray) beside an isosurface whose surface follows another component.
  const std::string pov =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 0, -3.2> look_at 0 angle 40 }\n"
      "light_source { <-5, 8, -10> color rgb 1 }\n"
      "#declare S = function { spline { cubic_spline -0.001, <0, 0, 0> 0.25, <0.25, 0.5, 0>\n"
      "  0.5, <0.5, 0.1, 0.3> 0.75, <0.75, 0.9, -0.2> 1.001, <1, 0, 0> } }\n"
      "#declare N = function { spline { natural_spline -1, <0.3, 0> 0, <0.5, 0> 0.4, <0.2, 0>\n"
      "  1, <0.45, 0> } }\n"
      "#declare P = function { pigment { function { S(x).y } } }\n"
      "box { 0, 1 pigment { function { P(x, y, z).gray } } finish { ambient 1 diffuse 0 }\n"
      "  translate <-1.1, -0.5, 0> }\n"
      "isosurface { function { sqrt(x * x + z * z) - N(y).x + S(y + 0.5).z * 0.3 }\n"
      "  contained_by { box { <-1, -1, -1>, <1, 1, 1> } } max_gradient 4\n"
      "  pigment { rgb <0.9, 0.6, 0.3> } translate <0.6, 0, 0.5> }\n";
  auto r = sdltest::readScene(pov);
  REQUIRE(r->load.scene);
  test::requireSameImage(*r->load.scene, pov);
}
