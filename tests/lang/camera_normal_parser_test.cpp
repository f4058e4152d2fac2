// <camera><normal/></camera> and a pattern's `sources`: read, written back by the scene
// writer, and exported to POV-Ray (the camera's normal block, global_settings'
// number_of_waves).
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kCamera = R"XML(<camera fov="50">
    <normal type="waves" depth="0.375" frequency="3" sources="1" transform="scale(0.5 1 1)"/>
  </camera>)XML";

}  // namespace

TEST_CASE("camera normal: read, written back and read again the same", "[lang][camera]") {
  auto scene = parseClean("<sphere/>", "test.xml", kCamera);
  const Camera& c = scene->cameras.front();
  REQUIRE(c.normal);
  CHECK(c.normal->pattern.type == PatternType::waves);
  CHECK(c.normal->depth == 0.375);
  CHECK(c.normal->pattern.frequency == 3.0);
  CHECK(c.normal->pattern.waveSources == 1);
  CHECK(c.normal->pattern.placement.patternFromObject[0][0] == Approx(2.0));
  const std::string text = writeSceneXml(*scene, WriteOptions{});
  INFO(text);
  CHECK(text.find("sources=\"1\"") != std::string::npos);
  ParseResult again = parseSceneString(text, "again.xml");
  REQUIRE(again.scene);
  const Camera& back = again.scene->cameras.front();
  REQUIRE(back.normal);
  CHECK(back.normal->depth == 0.375);
  CHECK(back.normal->pattern.waveSources == 1);
  CHECK(back.normal->pattern.placement.patternFromObject ==
        c.normal->pattern.placement.patternFromObject);
}

TEST_CASE("camera normal and wave sources exported to POV-Ray", "[lang][camera][povray]") {
  auto scene = parseClean("<sphere/>", "test.xml", kCamera);
  const PovExport exported = exportPov(*scene);
  REQUIRE(exported.ok());
  INFO(exported.text);
  const size_t camera = exported.text.find("camera {");
  const size_t normal = exported.text.find("normal {", camera);
  REQUIRE(camera != std::string::npos);
  REQUIRE(normal != std::string::npos);
  CHECK(exported.text.find("waves 0.375", normal) != std::string::npos);
  CHECK(exported.text.find("number_of_waves 1") != std::string::npos);
}

TEST_CASE("ripples and waves of different sources cannot be exported", "[lang][povray]") {
  auto scene =
      parseClean(R"(<sphere><material><pattern type="ripples" sources="3"/></material></sphere>
      <sphere center="3 0 0"><material><normal type="waves" sources="4"/></material></sphere>)");
  const PovExport exported = exportPov(*scene);
  CHECK(!exported.ok());
  bool said = false;
  for (const PovIssue& i : exported.issues)
    said = said ||
           i.message.find("POV-Ray's number_of_waves is one for the scene") != std::string::npos;
  CHECK(said);
}
