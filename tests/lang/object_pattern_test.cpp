// <pattern|normal type="object" object="id"> and <material-map> of it: the node found and its
// solid built when the scene is read, written back by lucent convert, exported as POV-Ray's
// object pattern (the object declared without textures, its list the map's first and last
// entries), and read from POV-Ray's `object { OBJECT transforms LIST }` in pigments, normals
// and textures by the importer (the object a <defs> group in POV-Ray's pattern space).
#include "../sdl/scene_read_support.h"
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"
#include "render/patterns/pattern_value.h"
#include "scenegraph/object_pattern.h"

#include <catch2/catch.hpp>

#include <string>
#include <variant>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kBody =
    "<defs><difference id=\"cut\"><box min=\"-1 -1 -1\" max=\"1 1 1\"/>"
    "<sphere center=\"1 1 1\" radius=\"1.2\"/></difference></defs>"
    "<sphere><material><pattern type=\"object\" object=\"cut\" transform=\"scale(0.5)\">"
    "<color-map><entry at=\"0\" color=\"1 0 0\"/><entry at=\"1\" color=\"0 0 1\"/></color-map>"
    "</pattern><normal type=\"object\" object=\"cut\"><normal-map>"
    "<entry at=\"0\"><normal type=\"bumps\" depth=\"0.3\"/></entry>"
    "<entry at=\"1\"><normal type=\"waves\" depth=\"0.5\"/></entry></normal-map></normal>"
    "</material></sphere>"
    "<sphere center=\"3 0 0\"><material><material-map>"
    "<pattern type=\"object\" object=\"cut\"/>"
    "<entry at=\"0\"><material diffuse=\"1 1 0\"/></entry>"
    "<entry at=\"1\"><material diffuse=\"0 1 1\" specular=\"0.5\"/></entry>"
    "</material-map></material></sphere>";

}  // namespace

TEST_CASE("object pattern: the id names the node and its solid is built once",
          "[lang][pattern][object]") {
  auto scene = parseClean(kBody);
  const PatternSpec& p = nodePigmentPattern(*scene, 0);
  CHECK(p.type == PatternType::object);
  CHECK(p.frequency == 0.0);  // POV-Ray's: the value is used as it is
  REQUIRE(p.object);
  CHECK(p.object->id == "cut");
  REQUIRE(p.object->node);
  CHECK(p.object->node == scene->defs.front().get());
  REQUIRE(p.object->solid);
  const Material& m = scene->materials.at(*scene->root->children[0]->material);
  REQUIRE(m.normal);
  CHECK(m.normal->pattern.object->solid);
  CHECK(m.normal->map.size() == 2);
  // scale(0.5) on the pattern: the object half as large on the shape.
  CHECK(patternValue(p, Vec3(-0.4, -0.4, -0.4)) == 1.0);
  CHECK(patternValue(p, Vec3(-0.6, -0.6, -0.6)) == 0.0);
  CHECK(patternValue(p, Vec3(0.45, 0.45, 0.45)) == 0.0);  // in the ball cut out
}

TEST_CASE("object pattern: convert writes object=\"id\" and reads back the same",
          "[lang][scene-writer][object]") {
  const std::string first = writeSceneXml(*parseClean(kBody), WriteOptions{});
  CHECK_THAT(first, Catch::Contains("type=\"object\""));
  CHECK_THAT(first, Catch::Contains("object=\"cut\""));
  auto reread = parseSceneString(first, "writer.xml");
  INFO(first);
  REQUIRE(reread.scene);
  CHECK(nodePigmentPattern(*reread.scene, 0).object->id == "cut");
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("object pattern: export-pov declares the object and writes its lists of two",
          "[povray][pattern][object]") {
  PovExport e = exportPov(*parseClean(kBody), {});
  REQUIRE(e.ok());
  INFO(e.text);
  CHECK_THAT(e.text, Catch::Contains("#declare LucentObject_cut = object {\n  difference {"));
  // The declaration comes before the materials that name it.
  CHECK(e.text.find("#declare LucentObject_cut") < e.text.find("object {\n      LucentObject_cut"));
  CHECK_THAT(e.text, Catch::Contains("object {\n      LucentObject_cut\n      rgbft <1, 0, 0, "
                                     "0, 0>,\n      rgbft <0, 0, 1, 0, 0>\n    }"));
  CHECK_THAT(e.text, Catch::Contains("LucentObject_cut\n      normal {"));
  CHECK_THAT(e.text, Catch::Contains("LucentObject_cut\n    texture {"));
}

TEST_CASE("object pattern: a map with a frequency and entries between its ends is not exported",
          "[povray][pattern][object]") {
  PovExport e = exportPov(
      *parseClean("<defs><sphere id=\"s\"/></defs><sphere><material><pattern type=\"object\" "
                  "object=\"s\" frequency=\"2\"><color-map><entry at=\"0\" color=\"0\"/><entry "
                  "at=\"0.5\" color=\"1\"/><entry at=\"1\" color=\"0\"/></color-map></pattern>"
                  "</material></sphere>"),
      {});
  CHECK_FALSE(e.ok());
  REQUIRE_FALSE(e.issues.empty());
  CHECK_THAT(e.issues.front().message, Catch::Contains("POV-Ray's list of two cannot write"));
}

TEST_CASE("object pattern: the importer reads it in pigments, normals and textures",
          "[sdl][pattern][object]") {
  auto r = sdltest::readScene(R"(
#declare Ball = sphere { <0, 0, 1>, 0.5 }
sphere { 0, 1 pigment { object { Ball rgb <1, 0, 0>, rgb <0, 0, 1> } } }
sphere { 0, 1 pigment { object { sphere { 0, 1 } translate z*2 } } }
sphere { 0, 1 pigment { object { Ball pigment { rgb 1 } pigment { checker } } scale 2 } }
sphere { 0, 1 normal { object { Ball normal { bumps 0.3 } normal { waves 0.5 } } } }
sphere { 0, 1 texture { object { Ball texture { pigment { rgb 1 } }
                                      texture { pigment { rgb 0 } } } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(s.defs.size() == 5);  // one group per object pattern
  const PatternSpec& p0 = nodePigmentPattern(s, 0);
  CHECK(p0.type == PatternType::object);
  // POV-Ray's <0, 0, 1> is Lucent's (0, 0, -1).
  CHECK(patternValue(p0, Vec3(0, 0, -1)) == 1.0);
  CHECK(patternValue(p0, Vec3(0, 0, 1)) == 0.0);
  const auto& t0 = std::get<PatternTexture>(sdltest::materialOf(s, 0).texture);
  REQUIRE(t0.map.entries.size() == 2);
  CHECK(t0.map.entries[0].color == Color(1, 0, 0));  // outside
  CHECK(t0.map.entries[1].color == Color(0, 0, 1));  // inside
  // Without colours POV-Ray's checker colours; the transform after the object moves it.
  const auto& t1 = std::get<PatternTexture>(sdltest::materialOf(s, 1).texture);
  CHECK(t1.map.entries[0].color == Color(0, 0, 1));
  CHECK(t1.map.entries[1].color == Color(0, 1, 0));
  CHECK(patternValue(t1.pattern, Vec3(0, 0, -2)) == 1.0);
  CHECK(patternValue(t1.pattern, Vec3(0, 0, 0)) == 0.0);
  const auto& t2 = std::get<PatternTexture>(sdltest::materialOf(s, 2).texture);
  REQUIRE(t2.pigments.size() == 2);
  CHECK(t2.pigments[0].at == 0.0);
  CHECK(t2.pigments[1].at == 1.0);
  CHECK(patternValue(t2.pattern, Vec3(0, 0, -2)) == 1.0);  // scale 2
  const Material& n = sdltest::materialOf(s, 3);
  REQUIRE(n.normal);
  CHECK(n.normal->pattern.type == PatternType::object);
  CHECK(n.normal->map.size() == 2);
  const Material& t = sdltest::materialOf(s, 4);
  REQUIRE(t.mapped());
  CHECK(std::get<PatternTexture>(t.mapPattern).pattern.type == PatternType::object);
  CHECK(t.mapEntries.size() == 2);
}

TEST_CASE("object pattern: POV-Ray's refusals of a colour map and of two objects",
          "[sdl][pattern][object]") {
  const auto colourMap = sdltest::errorsOf(
      "sphere { 0, 1 pigment { object { sphere { 0, 1 } } color_map { [0 rgb 0] [1 rgb 1] } } }");
  REQUIRE(colourMap.size() >= 1);
  CHECK_THAT(colourMap[0], Catch::Contains("a color_map cannot be used with an object pattern"));
  const auto two =
      sdltest::errorsOf("sphere { 0, 1 pigment { object { sphere { 0, 1 } box { 0, 1 } } } }");
  REQUIRE(two.size() >= 1);
  CHECK_THAT(two[0], Catch::Contains("object or object identifier expected"));
}
