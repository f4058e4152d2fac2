// <pattern type="pavement" sides tiles pavement exterior-corners interior-corners
// pavement-form>: parsed into the spec, written back by lucent convert, exported as POV-Ray's
// pavement with its modifiers, and read from POV-Ray's pavement by the importer (its numbers
// as POV-Ray keeps them, bytes, the corners modulo 3 and the form modulo 4 or 3, then its
// limits or its errors).
#include "../sdl/scene_read_support.h"
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

#include <string>
#include <variant>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kBody =
    "<sphere><material><pattern type=\"pavement\" sides=\"4\" tiles=\"6\" pavement=\"35\" "
    "exterior-corners=\"1\" interior-corners=\"2\" pavement-form=\"3\" transform=\"scale(0.5)\"/>"
    "<normal type=\"pavement\" sides=\"6\" tiles=\"3\" pavement=\"2\" depth=\"0.4\"/>"
    "</material></sphere>"
    "<sphere center=\"3 0 0\"><material><pattern type=\"pavement\"/></material></sphere>";

bool same(const PavementParams& a, const PavementParams& b) {
  return a.sides == b.sides && a.tiles == b.tiles && a.number == b.number &&
         a.exterior == b.exterior && a.interior == b.interior && a.form == b.form;
}

}  // namespace

TEST_CASE("pavement: the XML's attributes reach the pattern and the normal",
          "[lang][pattern][pavement]") {
  auto scene = parseClean(kBody);
  const PatternSpec& p = nodePigmentPattern(*scene, 0);
  CHECK(p.type == PatternType::pavement);
  CHECK(same(p.pavement, {4, 6, 35, 1, 2, 3}));
  const Material& m = scene->materials.at(*scene->root->children[0]->material);
  REQUIRE(m.normal);
  CHECK(m.normal->pattern.type == PatternType::pavement);
  CHECK(same(m.normal->pattern.pavement, {6, 3, 2, 0, 0, 0}));
  CHECK(same(nodePigmentPattern(*scene, 1).pavement, {3, 1, 1, 0, 0, 0}));  // POV-Ray's defaults
}

TEST_CASE("pavement: convert writes what differs from the defaults and reads back the same",
          "[lang][scene-writer][pavement]") {
  const std::string first = writeSceneXml(*parseClean(kBody), WriteOptions{});
  CHECK(first.find("sides=\"4\" tiles=\"6\" pavement=\"35\" "
                   "exterior-corners=\"1\" interior-corners=\"2\" pavement-form=\"3\"") !=
        std::string::npos);
  CHECK(first.find("type=\"pavement\" sides=\"6\" tiles=\"3\" pavement=\"2\" depth=\"0.4\"") !=
        std::string::npos);
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(same(nodePigmentPattern(*reread.scene, 0).pavement, {4, 6, 35, 1, 2, 3}));
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("pavement: export-pov writes POV-Ray's pavement with all its modifiers",
          "[povray][pattern][pavement]") {
  PovExport e = exportPov(*parseClean(kBody), {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("pavement\n"));
  CHECK_THAT(e.text, Catch::Contains("number_of_sides 4 number_of_tiles 6 pattern 35\n"));
  CHECK_THAT(e.text, Catch::Contains("exterior 1 interior 2 form 3\n"));
  CHECK_THAT(e.text, Catch::Contains("pavement 0.4\n"));
  CHECK_THAT(e.text, Catch::Contains("number_of_sides 6 number_of_tiles 3 pattern 2\n"));
}

TEST_CASE("pavement: the importer reads it as a pigment, a normal and a map's pattern",
          "[sdl][pattern][pavement]") {
  auto r = sdltest::readScene(R"(
sphere { 0, 1 pigment { pavement pattern 3 number_of_tiles 6 number_of_sides 4
                        exterior 1 interior 5 form 2 scale 2 } }
sphere { 0, 1 normal { pavement 0.3 number_of_sides 6 number_of_tiles 5 pattern 22 form 3 } }
sphere { 0, 1 pigment { pavement number_of_sides 260 number_of_tiles 4 pattern 258.5 form 7
                        color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 texture { pavement number_of_tiles 5 pattern 4
                        texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(nodePigmentPattern(s, 0).type == PatternType::pavement);
  // The arrangement is checked once the block is read; interior 5 is 2 (modulo 3).
  CHECK(same(nodePigmentPattern(s, 0).pavement, {4, 6, 3, 1, 2, 2}));
  const Material& normal = s.materials.at(*s.root->children[1]->material);
  REQUIRE(normal.normal);
  CHECK(normal.normal->pattern.type == PatternType::pavement);
  CHECK(same(normal.normal->pattern.pavement, {6, 5, 22, 0, 0, 0}));  // form 3 is 0 for hexagons
  CHECK(normal.normal->depth == Approx(0.3));
  // Bytes: 260 sides are 4, pattern 258 is 2; form 7 is 3 for squares.
  CHECK(same(nodePigmentPattern(s, 2).pavement, {4, 4, 2, 0, 0, 3}));
  const Material& mapped = s.materials.at(*s.root->children[3]->material);
  REQUIRE(mapped.mapped());
  const auto& map = std::get<PatternTexture>(mapped.mapPattern);
  CHECK(map.pattern.type == PatternType::pavement);
  CHECK(same(map.pattern.pavement, {3, 5, 4, 0, 0, 0}));
}

TEST_CASE("pavement: POV-Ray's errors for sides, tiles and arrangements out of range",
          "[sdl][pattern][pavement]") {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 pigment { pavement number_of_sides 5 } }",
       "test.pov:1:52: error: number_of_sides of pavement must be 3, 4 or 6 (POV-Ray's error), "
       "got 5"},
      {"sphere { 0, 1 pigment { pavement number_of_sides 6 number_of_tiles 6 } }",
       "test.pov:1:70: error: number_of_tiles of pavement must be between 1 and 5 (POV-Ray's "
       "error), got 6"},
      {"sphere { 0, 1 pigment { pavement number_of_tiles 0 } }",
       "test.pov:1:52: error: number_of_tiles of pavement must be between 1 and 6"},
      {"sphere { 0, 1 pigment { pavement number_of_tiles 4 pattern 4 } }",
       "test.pov:1:62: error: pattern value for pavement is out of range (POV-Ray's error): 4 "
       "tiles of 3 sides have patterns 1 to 3, got 4"},
      {"sphere { 0, 1 normal { pavement pattern 0 } }",
       "test.pov:1:43: error: pattern value for pavement is out of range"},
      {"sphere { 0, 1 pigment { bozo number_of_sides 4 } }", "test.pov:1:"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = sdltest::errorsOf(text);
    REQUIRE(errors.size() >= 1);
    INFO(errors[0]);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}
