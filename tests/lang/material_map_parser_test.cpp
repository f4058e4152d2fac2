// <material-map> in <material>: its pattern, its entries (named, also defined later, or
// inline, layers included) and the messages for what a map cannot hold.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("material-map: the pattern and the entries, named or inline",
          "[lang][material][material-map]") {
  auto s = parseClean(R"XML(
    <material id="floor" ior="1.3">
      <material-map>
        <pattern type="bozo" transform="scale(0.5)"/>
        <entry at="0" material="later"/>
        <entry at="0.5"><material diffuse="0 1 0"><layer ambient="0.2"/></material></entry>
      </material-map>
    </material>
    <material id="later" diffuse="1 0 0"/>
    <material id="tiles"><material-map><checker scale="2"/>
      <entry at="0" material="later"/><entry at="1" material="floor"/></material-map></material>)XML");
  const Material& floor = materialNamed(*s, "floor");
  REQUIRE(floor.mapped());
  CHECK(floor.ior == 1.3);
  CHECK(std::get<PatternTexture>(floor.mapPattern).pattern.type == PatternType::bozo);
  REQUIRE(floor.mapEntries.size() == 2);
  CHECK(floor.mapEntries[0].at == 0.0);
  CHECK(floor.mapEntries[0].material.diffuse == Color(1, 0, 0));  // defined after its use
  CHECK(floor.mapEntries[1].material.layers.size() == 1);
  const Material& tiles = materialNamed(*s, "tiles");
  CHECK(std::get<CheckerTexture>(tiles.mapPattern).scale == 2.0);
  CHECK(tiles.mapEntries[1].material.mapped());  // a map as an entry
  CHECK(!materialNamed(*s, "later").mapped());
}

TEST_CASE("material-map: what a map cannot hold is an error at its place",
          "[lang][material][material-map]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><material-map><entry at=\"0\"/></material-map></material>"
      "\n<material id=\"b\"><material-map><checker/><entry at=\"1\"><material/></entry>"
      "<entry at=\"0\"><material/></entry></material-map></material>"
      "\n<material id=\"c\"><checker/><material-map><checker/><entry at=\"0\"><material/>"
      "</entry></material-map></material>"
      "\n<material id=\"d\"><material-map><pattern type=\"bozo\"><color-map><entry at=\"0\" "
      "color=\"1\"/></color-map></pattern><entry at=\"0\"/></material-map></material>"
      "\n<material id=\"e\"><material-map><pattern type=\"bozo\"/><entry at=\"0\" "
      "material=\"a\"><material/></entry></material-map></material>"
      "\n<material id=\"f\"><material-map><pattern type=\"bozo\"/><entry at=\"0\" "
      "material=\"f\"/></material-map></material>",
      "maps.xml");
  const std::string text = messages(r);
  INFO(text);
  CHECK(text.find("maps.xml:2:32: error: a <material-map> starts with its pattern") !=
        std::string::npos);
  CHECK(text.find("error: <entry> attribute 'at': the entries of a <material-map> must be in "
                  "ascending order of 'at'") != std::string::npos);
  CHECK(text.find("maps.xml:4:1: error: a <material> with a <material-map> has no texture, "
                  "normal or <layer> of its own") != std::string::npos);
  CHECK(text.find("error: a <material-map>'s <pattern> has no <color-map> or <pigment-map>") !=
        std::string::npos);
  CHECK(text.find("error: an <entry> needs a material: material=\"id\" or an inline "
                  "<material>") != std::string::npos);
  CHECK(text.find("error: an <entry> holds one inline <material>, or names one with "
                  "material=\"id\"") != std::string::npos);
  CHECK(text.find("materials are based on each other in a cycle: 'f' -> 'f'") != std::string::npos);
}
