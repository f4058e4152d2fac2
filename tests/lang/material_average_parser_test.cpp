// <material-map> with an <average>: POV-Ray's average of textures. The average's placement,
// the entries' weights, the scene writer's round trip and the messages for what it cannot
// hold.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "scenegraph/map_blend.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* const kAverage = R"XML(
    <material id="red" ambient="1 0 0"/>
    <material id="mixed" ior="1.2">
      <material-map>
        <average transform="translate(0 0 0.5)" turbulence="0.2">
          <warp type="repeat" direction="2 0 0" offset="0 1 0"/>
        </average>
        <entry weight="3" material="red"/>
        <entry weight="0.5"><material reflective="1"><layer ambient="0.2"/></material></entry>
        <entry weight="1"><material><material-map><checker/>
          <entry at="0" material="red"/><entry at="1"><material/></entry></material-map></material></entry>
      </material-map>
    </material>
    <sphere material="mixed"/>)XML";

}  // namespace

TEST_CASE("material-map average: the placement and the weighted entries, in any order",
          "[lang][material][material-map]") {
  auto s = parseClean(kAverage);
  const Material& m = materialNamed(*s, "mixed");
  REQUIRE(m.mapped());
  REQUIRE(mapAverages(m));
  CHECK(m.ior == 1.2);
  const auto& a = std::get<AverageTexture>(m.mapPattern);
  CHECK(a.entries.empty());  // the map's entries are what it averages
  CHECK(a.placement.patternFromObject[3][2] == -0.5);
  CHECK(a.placement.turbulence == Vec3(0.2));
  REQUIRE(a.placement.warps.size() == 1);
  CHECK(std::holds_alternative<RepeatWarp>(a.placement.warps[0]));
  REQUIRE(m.mapEntries.size() == 3);
  CHECK(m.mapEntries[0].at == 3.0);  // weights, not in ascending order
  CHECK(m.mapEntries[1].at == 0.5);
  CHECK(m.mapEntries[0].material.ambient == Color(1, 0, 0));
  CHECK(m.mapEntries[1].material.layers.size() == 1);
  CHECK(m.mapEntries[2].material.mapped());
  CHECK(!mapAverages(m.mapEntries[2].material));
}

TEST_CASE("material-map average: the scene writer writes it and it reads back to the same text",
          "[lang][scene-writer][material-map]") {
  const std::string first = writeSceneXml(*parseClean(kAverage, "writer.xml"), WriteOptions{});
  CHECK(first.find("<average transform=") != std::string::npos);
  CHECK(first.find("<entry weight=\"3\">") != std::string::npos);
  CHECK(first.find("<entry weight=\"0.5\">") != std::string::npos);
  CHECK(first.find("<entry at=\"1\">") != std::string::npos);  // the inner checker map
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("material-map average: weights, entries and children it cannot take are errors",
          "[lang][material][material-map]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><material-map><average/><entry at=\"0\"><material/></entry>"
      "</material-map></material>"
      "\n<material id=\"b\"><material-map><average/><entry weight=\"0\"><material/></entry>"
      "</material-map></material>"
      "\n<material id=\"c\"><material-map><average><entry weight=\"1\" color=\"1\"/></average>"
      "<entry weight=\"1\"><material/></entry></material-map></material>"
      "\n<material id=\"d\"><material-map><pattern type=\"bozo\"/><entry weight=\"1\">"
      "<material/></entry></material-map></material>"
      "\n<material id=\"e\"><material-map><average/></material-map></material>",
      "averages.xml");
  const std::string text = messages(r);
  INFO(text);
  CHECK(text.find("averages.xml:2:42: error: an <entry> of an averaged <material-map> needs a "
                  "'weight' (a positive number)") != std::string::npos);
  CHECK(text.find("averages.xml:2:49: error: <entry>: unknown attribute 'at'") !=
        std::string::npos);
  CHECK(text.find("averages.xml:3:57: error: <entry> attribute 'weight': expected a positive "
                  "number, got '0'") != std::string::npos);
  CHECK(text.find("averages.xml:4:41: error: the <average> of a <material-map> holds only "
                  "<warp>s: the map's <entry weight>s are what it averages") != std::string::npos);
  CHECK(text.find("averages.xml:5:61: error: <entry>: unknown attribute 'weight'") !=
        std::string::npos);
  CHECK(text.find("averages.xml:6:18: error: a <material-map> needs at least one <entry>") !=
        std::string::npos);
}
