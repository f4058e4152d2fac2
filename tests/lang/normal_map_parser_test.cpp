// <normal-map>, <normal-list> (checker, hexagon, brick normals) and <slope-map>: read field
// by field, written by the scene writer and read back to the same text, exported to
// POV-Ray's syntax, and their errors.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kNormals = R"XML(
<material id="m">
  <normal type="gradient" axis="1 0 0" transform="scale(2)" keep-facing-away="true">
    <normal-map>
      <entry at="0.3"><normal type="marble" depth="1.2" turbulence="0.5"/></entry>
      <entry at="0.7">
        <normal type="checker" transform="scale(0.5)">
          <normal-list><entry><normal type="bumps" depth="0.8"/></entry><entry/></normal-list>
        </normal>
      </entry>
    </normal-map>
  </normal>
</material>
<material id="b">
  <normal type="brick" mortar="0.1" size="1 0.4 0.6">
    <normal-list><entry/><entry><normal type="granite" depth="0.3"/></entry></normal-list>
  </normal>
</material>
<material id="h">
  <normal type="hexagon">
    <normal-list><entry><normal type="ripples"/></entry><entry/><entry><normal type="bumps"/></entry></normal-list>
  </normal>
</material>
<material id="s">
  <normal type="onion" depth="0.8">
    <slope-map>
      <entry at="0" height="0" slope="1"/><entry at="0.5" height="1" slope="1"/>
      <entry at="0.5" height="1" slope="-1"/><entry at="1" height="0" slope="-1"/>
    </slope-map>
  </normal>
</material>
<material id="k"><normal type="checker" depth="0.75" transform="scale(0.5)"/></material>
<sphere material="m"/><sphere material="b"/><sphere material="h"/><sphere material="s"/>
<sphere material="k"/>)XML";

}  // namespace

TEST_CASE("normal maps: entries, block lists and slope maps are read field by field",
          "[lang][texture][normal-map]") {
  auto scene = parseClean(kNormals, "normals.xml");
  const NormalSpec& m = *materialNamed(*scene, "m").normal;
  CHECK(m.keepFacingAway);
  CHECK(m.pattern.type == PatternType::gradient);
  CHECK(m.pattern.placement.patternFromObject[0][0] == Approx(0.5));
  REQUIRE(m.map.size() == 2);
  CHECK(m.map[0].at == 0.3);
  CHECK_FALSE(m.map[0].flat);
  CHECK(m.map[0].normal.pattern.type == PatternType::marble);
  CHECK(m.map[0].normal.depth == 1.2);
  CHECK(m.map[0].normal.pattern.placement.turbulence == Vec3(0.5));
  const NormalSpec& checker = m.map[1].normal;
  CHECK(checker.block == NormalBlock::checker);
  CHECK(checker.pattern.placement.patternFromObject[0][0] == Approx(2.0));
  REQUIRE(checker.map.size() == 2);
  CHECK(checker.map[0].at == 0.0);
  CHECK(checker.map[0].normal.pattern.type == PatternType::bumps);
  CHECK(checker.map[1].at == 1.0);
  CHECK(checker.map[1].flat);

  const NormalSpec& b = *materialNamed(*scene, "b").normal;
  CHECK(b.block == NormalBlock::brick);
  CHECK(b.brick.mortar == 0.1);
  CHECK(b.brick.size == Vec3(1, 0.4, 0.6));
  REQUIRE(b.map.size() == 2);
  CHECK(b.map[0].flat);
  CHECK(b.map[1].normal.pattern.type == PatternType::granite);

  const NormalSpec& h = *materialNamed(*scene, "h").normal;
  CHECK(h.block == NormalBlock::hexagon);
  REQUIRE(h.map.size() == 3);
  CHECK(h.map[2].at == 2.0);

  const NormalSpec& s = *materialNamed(*scene, "s").normal;
  REQUIRE(s.slopeMap.size() == 4);
  CHECK(s.slopeMap[1].at == 0.5);
  CHECK(s.slopeMap[1].height == 1.0);
  CHECK(s.slopeMap[2].slope == -1.0);
  CHECK(s.map.empty());

  // A block pattern without a list: the slope of its cell index, bent by depth.
  const NormalSpec& k = *materialNamed(*scene, "k").normal;
  CHECK(k.block == NormalBlock::checker);
  CHECK(k.map.empty());
  CHECK(k.depth == 0.75);
}

TEST_CASE("normal maps: the scene writer writes them and they read back to the same text",
          "[lang][scene-writer][normal-map]") {
  const std::string first = writeSceneXml(*parseClean(kNormals, "writer.xml"), WriteOptions{});
  CHECK(first.find("<normal-map>") != std::string::npos);
  CHECK(first.find("<normal-list>") != std::string::npos);
  CHECK(first.find("<slope-map>") != std::string::npos);
  CHECK(first.find("<entry/>") != std::string::npos);
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("normal maps: export-pov writes normal_map, full lists of normals and slope_map",
          "[lang][povray][normal-map]") {
  const std::string pov = exportPov(*parseClean(kNormals, "export.xml")).text;
  CHECK(pov.find("normal_map {") != std::string::npos);
  CHECK(pov.find("[0.3") != std::string::npos);
  CHECK(pov.find("slope_map {") != std::string::npos);
  CHECK(pov.find("[0.5 <1, -1>]") != std::string::npos);
  CHECK(pov.find("brick_size <1, 0.4, 0.6> mortar 0.1") != std::string::npos);
  // Every cell's normal is written, a flat one as bumps 0 (POV-Ray stops at a short list).
  CHECK(pov.find("bumps 0\n") != std::string::npos);
  CHECK(pov.find("checker 0.75\n") != std::string::npos);
}

TEST_CASE("normal maps: bad entries and misplaced maps are errors at the element or attribute",
          "[lang][texture][normal-map]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><normal type=\"bozo\"><normal-map><entry at=\"0.6\"><normal "
      "type=\"bumps\"/></entry><entry at=\"0.2\"><normal type=\"dents\"/></entry></normal-map>"
      "</normal></material>"
      "\n<material id=\"b\"><normal type=\"bumps\"><slope-map><entry at=\"0\" height=\"0\" "
      "slope=\"1\"/></slope-map></normal></material>"
      "\n<material id=\"c\"><normal type=\"checker\"><normal-list><entry/></normal-list>"
      "</normal></material>"
      "\n<material id=\"d\"><normal type=\"hexagon\" depth=\"0.3\"><normal-list><entry/><entry/>"
      "<entry/></normal-list></normal></material>"
      "\n<material id=\"e\"><normal type=\"onion\"><slope-map><entry at=\"0\" height=\"1\"/>"
      "</slope-map></normal></material>"
      "\n<material id=\"f\"><pattern type=\"onion\"><slope-map/></pattern></material>"
      "\n<material id=\"g\"><normal type=\"gradient\" depth=\"0.4\"><normal-map><entry at=\"0\">"
      "<normal type=\"bumps\"/></entry></normal-map></normal></material>"
      "\n<material id=\"h\"><normal type=\"checker\" frequency=\"2\"/></material>",
      "maps.xml");
  CHECK(messages(r) ==
        "maps.xml:2:107: error: <entry> attribute 'at': the entries of a <normal-map> go in "
        "increasing order of 'at'; this one is below the one before (0.6)\n"
        "maps.xml:3:39: error: a bumps <normal> bends by its own normal, not a slope, so a "
        "<slope-map> has nothing to shape (POV-Ray ignores it); give it a colour pattern's type\n"
        "maps.xml:4:41: error: <normal-list> of a <normal type=\"checker\"> needs 2 entries, "
        "got 1\n"
        "maps.xml:5:48: error: <normal> attribute 'depth': a hexagon <normal> with a "
        "<normal-list> takes no depth (each entry's <normal> has its own)\n"
        "maps.xml:6:50: error: <entry> of a <slope-map> needs 'height' and 'slope' (POV-Ray's "
        "[at <height, slope>])\n"
        "maps.xml:7:40: error: <pattern> may hold one <color-map> or <pigment-map>, not "
        "<slope-map>\n"
        "maps.xml:8:49: error: <normal> attribute 'depth': a <normal> with a <normal-map> takes "
        "no depth (each entry's <normal> has its own)\n"
        "maps.xml:9:41: error: <normal> attribute 'frequency': a checker <normal> takes only the "
        "placement attributes, depth and keep-facing-away (each entry's <normal> has its own "
        "frequency)\n");
}
