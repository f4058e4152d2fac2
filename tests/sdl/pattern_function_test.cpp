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

// The numbers of every line that starts with "V ".
std::vector<double> printedRows(const std::string& messages) {
  std::vector<double> all;
  std::istringstream lines(messages);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("V ", 0) != 0) continue;
    std::istringstream row(line.substr(2));
    for (double v; row >> v;) all.push_back(v);
  }
  return all;
}

std::vector<double> lucentValues(const std::string& script) {
  auto r = sdltest::readScene(script + "camera { location -5 look_at 0 }\n");
  REQUIRE(r->load.scene);
  return printed(r->out.debugText);
}

// Block patterns as functions (checker 0 or 1, brick 0 in the mortar, hexagon 0, 1 or 2) and
// functions.inc's f_hexagon pigment, at a row of points and at cell edges: integer points
// (checker's floors), hexagon's negative z (mapped by 5.196152424), brick's mortar edges.
const char* kBlockScript =
    "#version 3.7;\n"
    "#include \"functions.inc\"\n"
    "#declare H = function { pattern { hexagon scale 0.7 } }\n"
    "#declare B = function { pattern { brick brick_size <1, 0.5, 0.7> mortar 0.1 } }\n"
    "#declare C = function { pattern { checker turbulence 0.4 scale 0.5 rotate y * 30 } }\n"
    "#declare Pts = array[12] { <0, 0, 0>, <1, 0, 0>, <-1, 2, -3>, <0.5, -0.5, 0.5>,\n"
    "  <-0.25, 0, -5.196152424>, <8, 3, 4.5>, <7.5, 2.999, 4.49>, <-7.75, -0.26, 0.2>,\n"
    "  <1.7320508, 0, 1>, <3, 0, 1.5>, <-4.5, 1, -2.598>, <100.3, -20.7, 55.1> }\n"
    "#macro Row(P)\n"
    "  #debug concat(\"V \", str(f_checker(P.x, P.y, P.z), 0, 7), \" \",\n"
    "    str(f_brick(P.x * 3, P.y * 3, P.z * 3), 0, 7), \" \", str(H(P.x, P.y, P.z), 0, 7), \" "
    "\",\n"
    "    str(f_hexagon(P.x, P.y, P.z).gray, 0, 7), \" \", str(B(P.x, P.y, P.z), 0, 7), \" \",\n"
    "    str(C(P.x, P.y, P.z), 0, 7), \"\\n\")\n"
    "#end\n"
    "#for (I, 0, 11) Row(Pts[I]) #end\n"
    "#for (I, 0, 39)\n"
    "  Row(<-3.7 + I * 0.613, -2.1 + mod(I * 7, 13) * 0.37, -4.2 + mod(I * 5, 11) * 0.81>)\n"
    "#end\n";

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

TEST_CASE("block pattern functions give POV-Ray's cell indices while the scene is read",
          "[sdl][function][pattern]") {
  const std::vector<double> lucent = printedRows(
      sdltest::readScene(std::string(kBlockScript) + "camera { location -5 look_at 0 }\n")
          ->out.debugText);
  const std::vector<double> povray = printedRows(test::povrayMessages(kBlockScript));
  REQUIRE(povray.size() == 52 * 6);
  REQUIRE(lucent.size() == povray.size());
  int hexagonTwos = 0, bricks = 0;
  for (size_t i = 0; i < povray.size(); ++i) {
    INFO("point " << i / 6 << ", function " << i % 6);
    CHECK(lucent[i] == povray[i]);
    hexagonTwos += i % 6 == 2 && povray[i] == 2.0;
    bricks += i % 6 == 4 && povray[i] == 1.0;
  }
  // The points reach every cell kind (hexagon's third, brick's bricks and mortar).
  CHECK(hexagonTwos > 5);
  CHECK(bricks > 5);
  CHECK(bricks < 47);
}

TEST_CASE("an isosurface of block pattern functions holds them as pigment calls",
          "[sdl][function][pattern][isosurface]") {
  auto r = sdltest::readScene(
      "#version 3.7;\n#include \"functions.inc\"\n"
      "camera { location -5 look_at 0 }\n"
      "isosurface { function { f_sphere(x, y, z, 1) - f_checker(x, y, z) * 0.1 - f_brick(x, y, "
      "z) * 0.1 - f_hexagon(x, y, z).gray * 0.2 } contained_by { box { -2, 2 } } }\n");
  REQUIRE(r->load.scene);
  const Node& n = *r->load.scene->root->children.at(0);
  REQUIRE(n.shape);
  const auto& iso = std::get<IsosurfaceSpec>(*n.shape);
  REQUIRE(iso.pigments.size() == 3);
  int kinds = 0;
  for (const auto& p : iso.pigments) {
    INFO(p->name);
    if (const auto* c = std::get_if<CheckerTexture>(&p->pigment)) {
      kinds += 1;
      CHECK(c->color1 == Color(0.0f));
      CHECK(c->color2 == Color(1.0f));
      CHECK(p->component == PigmentComponent::red);
    } else if (const auto* b = std::get_if<BrickTexture>(&p->pigment)) {
      kinds += 10;
      CHECK(b->spec.color1 == Color(0.0f));  // the mortar
      CHECK(b->spec.color2 == Color(1.0f));
    } else if (const auto* h = std::get_if<HexagonTexture>(&p->pigment)) {
      kinds += 100;
      CHECK(h->spec.colors[1] == Color(0.5f));  // f_hexagon is a pigment of its own colours
      CHECK(p->component == PigmentComponent::gray);
    }
  }
  CHECK(kinds == 111);
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

TEST_CASE("a pigment function called while the scene is read gives its colour",
          "[sdl][function][pigment]") {
  const char* script =
      "#version 3.7;\n"
      "#declare P = function { pigment { checker color rgbft <0.2, 0.3, 0.4, 0.5, 0.6>, "
      "color rgb 1 } }\n"
      "#declare V = P(0.5, 0.5, 0.5);\n"
      "#debug concat(\"V \", vstr(5, V, \" \", 0, 7), \" \", str(P(0.5, 0.5, 0.5).gray, 0, 7), "
      "\" \", str(P(1.5, 0.5, 0.5).blue, 0, 7), \"\\n\")\n";
  const std::vector<double> lucent = test::printedNumbers(
      sdltest::readScene(std::string(script) + "camera { location -5 look_at 0 }\n")->out.debugText,
      "V ");
  const std::vector<double> povray = test::printedNumbers(test::povrayMessages(script), "V ");
  REQUIRE(povray.size() == 7);
  CHECK(lucent == povray);
  // The grey by POV-Ray's weights, worked out here.
  CHECK(lucent[5] == Approx(0.297 * 0.2 + 0.589 * 0.3 + 0.114 * 0.4).margin(1e-7));
}

TEST_CASE("a function pattern of block pattern functions matches POV-Ray's image",
          "[sdl][function][pattern][povray]") {
  // The three indices weighted so that every combination is a colour of its own.
  const std::string pov =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n#include \"functions.inc\"\n"
      "#declare H = function { pattern { hexagon scale 0.3 } }\n"
      "camera { location <0, 3, -3> look_at 0 angle 40 }\n"
      "light_source { <-5, 8, -10> color rgb 1 }\n"
      "box { -1, 1 pigment { function { H(x, y, z) * 0.4 + f_checker(x * 2, y * 2, z * 2) * 0.2 "
      "+ f_brick(x * 8, y * 8, z * 8) * 0.1 } color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } "
      "} }\n";
  auto r = sdltest::readScene(pov);
  REQUIRE(r->load.scene);
  test::requireSameImage(*r->load.scene, pov);
}
