// Pattern functions (`function { pattern { PATTERN } }`, functions.inc's f_agate, f_granite,
// ... and f_noise3d): their values while the scene is read (#debug) against POV-Ray's own,
// printed by POV-Ray from the same script; and isosurfaces of them imported.
#include "pov_meaning_support.h"
#include "scene_read_support.h"

#include <catch2/catch.hpp>

#include <sstream>

using namespace lucent;

namespace {

// The values the script prints after "V", as POV-Ray and as Lucent's reader print them.
const char* kScript =
    "#version 3.7;\n"
    "#include \"functions.inc\"\n"
    "#declare G = function { pattern { granite scale 2 } }\n"
    "#declare W = function { pattern { wood turbulence 0.3 rotate x * 30 } }\n"
    "#declare Grad = function { pattern { gradient <1, 1, 0> } }\n"
    "#debug concat(\"V \", str(f_noise3d(0.3, 0.7, 1.1), 0, 7), \" \",\n"
    "  str(f_noise3d(-2.45, 10.5, 3.25), 0, 7), \" \", str(f_agate(0.2, 0.5, 0.9), 0, 7), "
    "\"\\n\")\n"
    "#debug concat(\"W \", str(f_bozo(1.2, -0.4, 0.6), 0, 7), \" \", str(G(1.5, -0.25, 0.75), 0, "
    "7),\n"
    "  \"\\n\")\n"
    "#debug concat(\"X \", str(W(0.4, 0.1, -0.3), 0, 7), \" \", str(Grad(0.3, 0.2, 5), 0, 7), \" "
    "\",\n"
    "  str(f_dents(0.7, 0.2, 0.1), 0, 7), \"\\n\")\n";

// The numbers printed after "V ", "W " and "X ", in that order.
std::vector<double> printed(const std::string& messages) {
  std::vector<double> all;
  for (const char* label : {"V ", "W ", "X "})
    for (double v : test::printedNumbers(messages, label)) all.push_back(v);
  return all;
}

std::vector<double> lucentValues(const std::string& script) {
  auto r = sdltest::readScene(script + "camera { location -5 look_at 0 }\n");
  REQUIRE(r->load.scene);
  return printed(r->out.debugText);
}

}  // namespace

TEST_CASE("pattern functions give POV-Ray's pattern values while the scene is read",
          "[sdl][function][pattern]") {
  const std::vector<double> lucent = lucentValues(kScript);
  const std::vector<double> povray = printed(test::povrayMessages(kScript));
  REQUIRE(lucent.size() == 8);
  REQUIRE(povray.size() == 8);
  for (size_t i = 0; i < povray.size(); ++i) {
    INFO("value " << i);
    // Lucent's pattern colour is single precision.
    CHECK(lucent[i] == Approx(povray[i]).margin(2e-6));
  }
}

TEST_CASE("an isosurface of pattern functions is imported with the patterns as pigment calls",
          "[sdl][function][pattern][isosurface]") {
  auto r = sdltest::readScene(
      "#version 3.7;\n#include \"functions.inc\"\n"
      "camera { location -5 look_at 0 }\n"
      "isosurface { function { f_sphere(x, y, z, 1) - f_agate(x, y, z) * 0.2 + "
      "f_noise3d(x * 3, y * 3, z * 3) * 0.1 } contained_by { box { -2, 2 } } max_gradient 4 }\n");
  REQUIRE(r->load.scene);
  const Node& n = *r->load.scene->root->children.at(0);
  REQUIRE(n.shape);
  const auto& iso = std::get<IsosurfaceSpec>(*n.shape);
  CHECK(iso.pigments.size() == 2);
}

TEST_CASE("pattern functions of block patterns are refused where they are called",
          "[sdl][function][pattern][bad]") {
  const std::vector<std::string> errors = sdltest::errorsOf(
      "#version 3.7;\n#include \"functions.inc\"\n"
      "camera { location -5 look_at 0 }\n"
      "isosurface { function { f_sphere(x, y, z, 1) - f_checker(x, y, z) } }\n");
  REQUIRE(!errors.empty());
  CHECK_THAT(errors.front(), Catch::Contains("'f_checker' is a pattern function"));
}

TEST_CASE("a hexagon pigment keeps its three colours (functions.inc's f_hexagon)",
          "[sdl][pattern]") {
  auto r = sdltest::readScene(
      "#version 3.7;\ncamera { location -5 look_at 0 }\n"
      "sphere { 0, 1 pigment { hexagon color rgb 0, color rgb 0.5, color rgb 1 } }\n");
  REQUIRE(r->load.scene);
  const Material& m = r->load.scene->materials.at(*r->load.scene->root->children.at(0)->material);
  const auto& h = std::get<HexagonTexture>(m.texture);
  CHECK(h.spec.colors[0] == Color(0.0f));
  CHECK(h.spec.colors[1] == Color(0.5f));
  CHECK(h.spec.colors[2] == Color(1.0f));
}
