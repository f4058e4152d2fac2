// <pigment-map>, <pigment-list>, <average> and <normal type="average">: read field by
// field, written by the scene writer and read back to the same text, and their errors.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kMaps = R"XML(
<material id="m">
  <pattern type="gradient" axis="1 0 0" transform="scale(2)">
    <pigment-map>
      <entry at="0" color="1 0 0" transmit="0.5"/>
      <entry at="0.5"><checker color1="0 0 1" color2="0 1 0" transform="scale(0.25)"/></entry>
      <entry at="1">
        <average>
          <entry weight="1" color="1 1 1"/>
          <entry weight="3"><hexagon><pigment-list><entry color="1 0 0"/><entry color="0 1 0"/>
            <entry><brick mortar="0.2"><pigment-list><entry color="0.5"/><entry color="0.1"/></pigment-list></brick></entry>
          </pigment-list></hexagon></entry>
        </average>
      </entry>
    </pigment-map>
  </pattern>
  <normal type="average" transform="scale(3)" keep-facing-away="true">
    <entry weight="2"><normal type="bumps" depth="0.6" transform="scale(0.125)"/></entry>
    <entry weight="1"><normal type="average"><entry weight="1"><normal type="ripples"/></entry></normal></entry>
  </normal>
</material>
<sphere material="m"/>)XML";

const Material& material(const Scene& s) {
  for (const Material& m : s.materials)
    if (m.id == "m") return m;
  FAIL("no material m");
  return s.materials[0];
}

}  // namespace

TEST_CASE("pigment maps: entries, nested textures and their placements are read",
          "[lang][texture][pigment-map]") {
  auto s = parseClean(kMaps);
  const Material& m = material(*s);
  const auto& t = std::get<PatternTexture>(m.texture);
  CHECK(t.map.entries.empty());
  REQUIRE(t.pigments.size() == 3);
  CHECK(t.pigments[0].at == 0.0);
  CHECK(std::holds_alternative<std::monostate>(t.pigments[0].texture));
  CHECK(t.pigments[0].color.rgb == Color(1, 0, 0));
  CHECK(t.pigments[0].color.ft.transmit == 0.5f);
  const auto& c = std::get<CheckerTexture>(t.pigments[1].texture);
  CHECK(c.color1 == Color(0, 0, 1));
  CHECK(c.placement.patternFromObject[0][0] == 4.0);  // its own scale, relative to the map's
  const auto& a = std::get<AverageTexture>(t.pigments[2].texture);
  REQUIRE(a.entries.size() == 2);
  CHECK(a.entries[1].at == 3.0);
  const auto& h = std::get<HexagonTexture>(a.entries[1].texture);
  REQUIRE(h.pigments.size() == 3);
  const auto& b = std::get<BrickTexture>(h.pigments[2].texture);
  CHECK(b.spec.mortar == 0.2);
  REQUIRE(b.pigments.size() == 2);
  CHECK(b.pigments[1].color.rgb == Color(0.1f));
  CHECK(textureSeeThrough(m.texture));
  CHECK(m.isTransmissive());

  REQUIRE(m.normal);
  CHECK(m.normal->keepFacingAway);
  CHECK(m.normal->pattern.placement.patternFromObject[1][1] == Approx(1.0 / 3.0));
  REQUIRE(m.normal->average.size() == 2);
  CHECK(m.normal->average[0].weight == 2.0);
  CHECK(m.normal->average[0].normal.pattern.type == PatternType::bumps);
  CHECK(m.normal->average[0].normal.depth == 0.6);
  REQUIRE(m.normal->average[1].normal.average.size() == 1);
  CHECK(m.normal->average[1].normal.average[0].normal.pattern.type == PatternType::ripples);
}

TEST_CASE("pigment maps: the scene writer writes them and they read back to the same text",
          "[lang][scene-writer][pigment-map]") {
  const std::string first = writeSceneXml(*parseClean(kMaps, "writer.xml"), WriteOptions{});
  CHECK(first.find("<pigment-map>") != std::string::npos);
  CHECK(first.find("<pigment-list>") != std::string::npos);
  CHECK(first.find("<normal type=\"average\"") != std::string::npos);
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("pigment maps: bad entries are errors at the element or attribute",
          "[lang][texture][pigment-map]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><pattern type=\"bozo\"><pigment-map><entry at=\"0\" "
      "color=\"1\"><checker/></entry></pigment-map></pattern></material>"
      "\n<material id=\"b\"><checker><pigment-list><entry color=\"1\"/></pigment-list>"
      "</checker></material>"
      "\n<material id=\"c\"><average><entry color=\"1\"/></average></material>"
      "\n<material id=\"d\"><pattern type=\"bozo\"><pigment-map><entry at=\"0\"><image "
      "src=\"x.png\"/></entry></pigment-map></pattern></material>",
      "maps.xml");
  CHECK(messages(r) ==
        "maps.xml:2:76: error: an <entry> with a texture takes no color, filter or transmit (the "
        "texture's own colours have them)\n"
        "maps.xml:3:27: error: <pigment-list> of <checker> needs 2 entries, got 1\n"
        "maps.xml:4:27: error: <entry> needs a 'weight' (a positive number)\n"
        "maps.xml:5:78: error: <image> attribute 'src': file 'x.png' not found (looked for '" +
            (std::filesystem::current_path() / "x.png").string() + "')\n");
}
