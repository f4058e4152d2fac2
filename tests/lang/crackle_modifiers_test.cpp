// crackle's form, metric, offset and solid in the XML: parsed into CrackleParams, written
// back by lucent convert, exported with POV-Ray's syntax, read from POV-Ray's by the
// importer (and refused on other patterns, as POV-Ray refuses them); their values are held
// to POV-Ray by tests/patterns (crackle_metric1, crackle_metric3, crackle_offset, crackle_solid).
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

using sdltest::materialOf;

const char* kBody =
    "<sphere><material><pattern type=\"crackle\" form=\"1 0 0\" metric=\"1\" offset=\"0.2\"/>"
    "<normal type=\"crackle\" solid=\"true\" depth=\"0.4\"/></material></sphere>"
    "<sphere center=\"3 0 0\"><material><pattern type=\"crackle\" metric=\"3\" "
    "form=\"-0.5 1.2 0.3\"/></material></sphere>"
    "<sphere center=\"6 0 0\"><material><pattern type=\"magnet\" form=\"julia\" c=\"0.4 0.1\" "
    "iterations=\"5\"/></material></sphere>";

}  // namespace

TEST_CASE("crackle: form, metric, offset and solid reach the pattern and the normal",
          "[lang][pattern][crackle]") {
  auto scene = parseClean(kBody);
  const CrackleParams& a = nodePigmentPattern(*scene, 0).crackle;
  CHECK(a.form == Vec3(1, 0, 0));
  CHECK(a.metric == 1.0);
  CHECK(a.offset == 0.2);
  CHECK_FALSE(a.solid);
  REQUIRE(materialOf(*scene, 0).normal);
  const CrackleParams& n = materialOf(*scene, 0).normal->pattern.crackle;
  CHECK(n.solid);
  CHECK(n.form == Vec3(-1, 1, 0));  // POV-Ray's defaults
  CHECK(n.metric == 2.0);
  CHECK(n.offset == 0.0);
  const CrackleParams& b = nodePigmentPattern(*scene, 1).crackle;
  CHECK(b.metric == 3.0);
  CHECK(b.form == Vec3(-0.5, 1.2, 0.3));
  CHECK(nodePigmentPattern(*scene, 2).fractal.juliaForm);  // magnet's form is still its word
}

TEST_CASE("crackle: convert writes its modifiers and reads back to the same text",
          "[lang][scene-writer][crackle]") {
  const std::string first = writeSceneXml(*parseClean(kBody), WriteOptions{});
  CHECK(first.find("metric=\"1\" form=\"1 0 0\" offset=\"0.2\"") != std::string::npos);
  CHECK(first.find("<normal type=\"crackle\" solid=\"true\" depth=\"0.4\"/>") != std::string::npos);
  CHECK(first.find("metric=\"3\" form=\"-0.5 1.2 0.3\"") != std::string::npos);
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("crackle: export-pov writes every modifier with POV-Ray's syntax",
          "[povray][pattern][crackle]") {
  PovExport e = exportPov(*parseClean(kBody), {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("metric 1 form <1, 0, 0> offset 0.2\n"));
  CHECK_THAT(e.text, Catch::Contains("metric 2 form <-1, 1, 0> offset 0 solid\n"));
  CHECK_THAT(e.text, Catch::Contains("metric 3 form <-0.5, 1.2, 0.3> offset 0\n"));
}

TEST_CASE("crackle: the importer's modifiers survive convert, and other patterns refuse them",
          "[sdl][pattern][crackle]") {
  auto r = sdltest::readScene(
      "sphere { 0, 1 pigment { crackle form <0, 1, 0> metric <1, 5, 5> offset 0.3 solid } }\n");
  REQUIRE(r->load.scene);
  const CrackleParams& c = nodePigmentPattern(*r->load.scene, 0).crackle;
  CHECK(c.form == Vec3(0, 1, 0));
  CHECK(c.metric == 1.0);  // a vector's x, as POV-Ray's
  CHECK(c.offset == 0.3);
  CHECK(c.solid);
  const std::string xml = writeSceneXml(*r->load.scene, WriteOptions{});
  CHECK(xml.find("metric=\"1\" form=\"0 1 0\" offset=\"0.3\" solid=\"true\"") != std::string::npos);

  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 pigment { bozo form <1, 0, 0> } }",
       "test.pov:1:30: error: 'form' is for crackle"},
      {"sphere { 0, 1 pigment { granite metric 1 } }",
       "test.pov:1:33: error: 'metric' is for crackle"},
      {"sphere { 0, 1 pigment { onion offset 0.5 } }",
       "test.pov:1:31: error: 'offset' is for crackle"},
      {"sphere { 0, 1 pigment { cells solid } }", "test.pov:1:31: error: 'solid' is for crackle"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = sdltest::errorsOf(text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}
