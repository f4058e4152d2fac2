// Forms of POV-Ray 3.0 and older that POV-Ray 3.7 still reads, found in scenes from outside
// the sample set: bare pigment, normal and finish identifiers in a texture, a finish's ior,
// `refraction`, and a block pattern's list shorter than its cells.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::materialOf;
using sdltest::readScene;

void checkColor(const Color& got, const Color& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-6));
}

}  // namespace

TEST_CASE("pov old forms: bare pigment, normal and finish identifiers in a texture",
          "[sdl][scene][texture]") {
  // POV-Ray's Parse_Texture replaces each part by an identifier written bare before the
  // blocks; the blocks after it continue that part.
  auto r = readScene(
      "#declare P = pigment { rgb <1, 0, 0> }\n"
      "#declare F = finish { ambient 0 diffuse 0.5 phong 1 }\n"
      "#declare N = normal { bumps 0.4 }\n"
      "#declare T = texture { pigment { rgb <0, 1, 0> } }\n"
      "sphere { 0, 1 texture { P F } }\n"
      "sphere { 0, 1 texture { T N finish { F diffuse 0.25 } } }\n"
      "sphere { 0, 1 texture { P pigment { transmit 0.5 } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& a = materialOf(s, 0);
  // diffuse 0.5 times the red pigment; phong from F; no ambient.
  checkColor(a.diffuse, Color(0.5f, 0, 0));
  checkColor(a.ambient, Color(0.0f));
  checkColor(a.phong, Color(1.0f));
  const Material& b = materialOf(s, 1);
  checkColor(b.diffuse, Color(0, 0.25f, 0));
  REQUIRE(b.normal);
  CHECK(b.normal->pattern.type == PatternType::bumps);
  CHECK(b.normal->depth == 0.4);
  const Material& c = materialOf(s, 2);
  checkColor(c.transmissive, Color(0.5f));  // transmit is untinted
  const auto& warnings = r->out.warnings;
  REQUIRE(warnings.size() == 4);
  CHECK(warnings[0] ==
        "test.pov:5:25: warning: found pigment identifier 'P' that should be in a 'pigment' "
        "statement (read as pigment { P }, as POV-Ray reads it)");
  CHECK(warnings[2] ==
        "test.pov:6:27: warning: found normal identifier 'N' that should be in a 'normal' "
        "statement (read as normal { N }, as POV-Ray reads it)");

  // After a block, an identifier is not POV-Ray's: still an error.
  const auto errors = errorsOf(
      "#declare P = pigment { rgb 1 }\n"
      "sphere { 0, 1 texture { finish { phong 1 } P } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == "test.pov:2:44: error: unexpected pigment identifier 'P' in this block");
}

TEST_CASE("pov old forms: a finish's ior becomes the object's interior's",
          "[sdl][scene][texture]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { rgbf 1 } finish { ior 1.5 } }\n"
      "sphere { 0, 1 pigment { rgbf 1 } finish { ior 1.5 } interior { ior 1.2 } }\n"
      "sphere { 0, 1 interior { ior 1.2 } texture { pigment { rgbf 1 } finish { ior 1.33 } } }\n"
      "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.2 } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(materialOf(s, 0).ior == 1.5);
  // POV-Ray's post-processing at the object's end: the finish's wins over the interior's.
  CHECK(materialOf(s, 1).ior == 1.5);
  CHECK(materialOf(s, 2).ior == Approx(1.33));
  CHECK(materialOf(s, 3).ior == Approx(1.2));
}

TEST_CASE("pov old forms: refraction 1 is read and ignored, any other is refused",
          "[sdl][scene][texture]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { rgbf 1 } finish { refraction 1 ior 1.5 } }\n"
      "sphere { 0, 1 pigment { rgbf 1 } interior { refraction on } }\n");
  REQUIRE(r->load.scene);
  const auto& warnings = r->out.warnings;
  REQUIRE(warnings.size() == 2);
  CHECK(warnings[0] ==
        "test.pov:1:43: warning: 'refraction 1' is not needed to turn refraction on (read and "
        "ignored, as POV-Ray reads it)");
  const auto errors = errorsOf("sphere { 0, 1 pigment { rgbf 1 } finish { refraction 0.9 } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        "test.pov:1:43: error: 'refraction 0.9' (a factor on the light seen through the object, "
        "not on its shadow) is not supported by Lucent; POV-Ray attenuates with interior { "
        "fade_distance fade_power }");
}

TEST_CASE("pov old forms: a block pattern's short list of pigments takes the #default's",
          "[sdl][scene][texture][block]") {
  auto r = readScene(
      "#default { pigment { rgb <0, 0, 1> } }\n"
      "sphere { 0, 1 pigment { checker pigment { rgb <1, 0, 0> } } }\n"
      "sphere { 0, 1 pigment { hexagon pigment { rgb <1, 0, 0> } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& checker = std::get<CheckerTexture>(materialOf(s, 0).texture);
  REQUIRE(checker.pigments.size() == 2);
  checkColor(checker.pigments[0].color.rgb, Color(1, 0, 0));
  checkColor(checker.pigments[1].color.rgb, Color(0, 0, 1));
  const auto& hexagon = std::get<HexagonTexture>(materialOf(s, 1).texture);
  REQUIRE(hexagon.pigments.size() == 3);
  checkColor(hexagon.pigments[2].color.rgb, Color(0, 0, 1));
}

TEST_CASE("pov old forms: a declared object written bare where an object is read",
          "[sdl][scene][csg]") {
  // POV-Ray's Parse_Object takes an object identifier alone: a CSG operand after the first,
  // a clip or bound, an object at the top level.
  auto r = readScene(
      "#declare A = sphere { 0, 1 }\n"
      "#declare B = box { -1, 1 }\n"
      "#declare L = light_source { <0, 5, -5> rgb 1 }\n"
      "union { sphere { 2 * x, 1 } A }\n"
      "A\n"
      "object { A clipped_by { B } }\n"
      "L\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.size() == 3);
  CHECK(s.root->children[0]->children.size() == 2);
  CHECK(s.lightRoot->children.size() == 1);

  // The first operand of a CSG is POV-Ray's `union { A modifiers }`: an object after it is
  // its error.
  const auto errors = errorsOf(
      "#declare A = sphere { 0, 1 }\n"
      "union { A sphere { x, 1 } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        "test.pov:2:11: error: an object where the modifiers of union are read (POV-Ray: \"No "
        "matching } in 'union'\"; in 'union { IDENTIFIER' the identifier is the copied object, "
        "modifiers follow: write object { IDENTIFIER } to make it an operand)");
  const auto light = errorsOf(
      "#declare A = sphere { 0, 1 }\n"
      "#declare L = light_source { 0 rgb 1 }\n"
      "object { A bounded_by { L } }\n");
  REQUIRE(light.size() == 1);
  CHECK(light[0] == "test.pov:3:25: error: a light source cannot bound an object");
}

TEST_CASE("pov old forms: a pigment function's .hf and .grey in a function", "[sdl][function]") {
  // POV-Ray 3.7 keeps MegaPOV's .hf: (red + green/255) times 0.996093. Its output for this
  // scene: 0.499023 0.295750.
  auto r = readScene(
      "#declare P = function { pigment { rgb <0.5, 0.25, 0> } }\n"
      "#declare V = function { P(x, y, z).hf }\n"
      "#declare G = function { P(x, y, z).grey }\n"
      "#debug concat(str(V(0, 0, 0), 0, 6), \" \", str(G(0, 0, 0), 0, 6), \"\\n\")\n"
      "isosurface { function { y - P(x, y, z).hf } contained_by { box { -1, 1 } } }\n");
  REQUIRE(r->load.scene);
  CHECK(r->out.debugText == "0.499023 0.295750\n");
}
