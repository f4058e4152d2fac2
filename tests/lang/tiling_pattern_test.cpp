// <pattern type="tiling" tiling="N">: parsed into the spec, written back by lucent convert,
// exported as POV-Ray's `tiling N`, and read from POV-Ray's `tiling N` by the importer
// (N as POV-Ray keeps it, a byte, then 1 to 27 or its error).
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
    "<sphere><material><pattern type=\"tiling\" tiling=\"24\" transform=\"scale(0.5)\"/>"
    "<normal type=\"tiling\" tiling=\"3\" depth=\"0.4\"/></material></sphere>"
    "<sphere center=\"3 0 0\"><material><pattern type=\"tiling\" tiling=\"1\" "
    "frequency=\"2\" wave=\"sine\"/></material></sphere>";

}  // namespace

TEST_CASE("tiling: the XML's tiling number reaches the pattern and the normal",
          "[lang][pattern][tiling]") {
  auto scene = parseClean(kBody);
  const PatternSpec& p = nodePigmentPattern(*scene, 0);
  CHECK(p.type == PatternType::tiling);
  CHECK(p.tiling == 24);
  const Material& m = scene->materials.at(*scene->root->children[0]->material);
  REQUIRE(m.normal);
  CHECK(m.normal->pattern.type == PatternType::tiling);
  CHECK(m.normal->pattern.tiling == 3);
  CHECK(nodePigmentPattern(*scene, 1).tiling == 1);
}

TEST_CASE("tiling: convert writes the number and reads back to the same text",
          "[lang][scene-writer][tiling]") {
  const std::string first = writeSceneXml(*parseClean(kBody), WriteOptions{});
  CHECK(first.find("type=\"tiling\"") != std::string::npos);
  CHECK(first.find("tiling=\"24\"") != std::string::npos);
  CHECK(first.find("tiling=\"3\" depth=\"0.4\"") != std::string::npos);
  CHECK(first.find("tiling=\"1\"") != std::string::npos);  // written even at its default
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("tiling: export-pov writes POV-Ray's tiling N as pigment and normal",
          "[povray][pattern][tiling]") {
  PovExport e = exportPov(*parseClean(kBody), {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("tiling 24\n"));
  CHECK_THAT(e.text, Catch::Contains("tiling 3 0.4"));
  CHECK_THAT(e.text, Catch::Contains("tiling 1\n"));
}

TEST_CASE("tiling: the importer reads tiling N as a pigment, a normal and a map's pattern",
          "[sdl][pattern][tiling]") {
  auto r = sdltest::readScene(R"(
sphere { 0, 1 pigment { tiling 27 scale 2 } }
sphere { 0, 1 normal { tiling 5 0.3 } }
sphere { 0, 1 pigment { tiling 258.9 color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 texture { tiling 9 texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(nodePigmentPattern(s, 0).type == PatternType::tiling);
  CHECK(nodePigmentPattern(s, 0).tiling == 27);
  const Material& normal = s.materials.at(*s.root->children[1]->material);
  REQUIRE(normal.normal);
  CHECK(normal.normal->pattern.type == PatternType::tiling);
  CHECK(normal.normal->pattern.tiling == 5);
  CHECK(normal.normal->depth == Approx(0.3));
  CHECK(nodePigmentPattern(s, 2).tiling == 2);  // 258 as POV-Ray's byte
  const Material& mapped = s.materials.at(*s.root->children[3]->material);
  REQUIRE(mapped.mapped());
  const auto& map = std::get<PatternTexture>(mapped.mapPattern);
  CHECK(map.pattern.type == PatternType::tiling);
  CHECK(map.pattern.tiling == 9);
}

TEST_CASE("tiling: POV-Ray's errors for a number outside 1 to 27 and for no number",
          "[sdl][pattern][tiling]") {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 pigment { tiling 0 } }",
       "test.pov:1:25: error: Tiling number must be between 1 and 27 (POV-Ray's error), got 0"},
      {"sphere { 0, 1 pigment { tiling 28 } }",
       "test.pov:1:25: error: Tiling number must be between 1 and 27 (POV-Ray's error), got 28"},
      {"sphere { 0, 1 pigment { tiling 256 } }",
       "test.pov:1:25: error: Tiling number must be between 1 and 27 (POV-Ray's error), got 256"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = sdltest::errorsOf(text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
  CHECK(sdltest::errorsOf("sphere { 0, 1 pigment { tiling } }").size() == 1);
}
