// Material maps (Tracer::shadeMap, scenegraph/map_blend.h): the entries a pattern's value
// falls between, each shaded whole and blended by weight as POV-Ray's texture_map blends
// them; a block pattern's cells; shadow rays and straight rays through an entry.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"
#include "scenegraph/map_blend.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "material_map.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

void checkColor(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-5));
}

std::vector<MaterialMapEntry> entriesAt(std::initializer_list<double> ats) {
  std::vector<MaterialMapEntry> out;
  for (double at : ats) out.push_back({at, Material{}});
  return out;
}

}  // namespace

TEST_CASE("map blend: POV-Ray's search over ascending entries", "[render][material-map]") {
  const auto e = entriesAt({0.2, 0.5, 0.5, 0.9});
  auto check = [&](double v, uint32_t a, uint32_t b, float wa) {
    INFO("v = " << v);
    const MapBlend m = mapBlend(e, v);
    CHECK(m.a == a);
    CHECK(m.b == b);
    CHECK(m.wa == Approx(wa));
    CHECK(m.wa + m.wb == Approx(1.0f));
  };
  check(0.0, 0, 0, 1.0f);  // below the first: the first alone
  check(0.2, 0, 0, 1.0f);
  check(0.35, 0, 1, 0.5f);  // halfway between 0.2 and 0.5
  check(0.5, 1, 1, 1.0f);   // exactly at a value: the first entry with it
  check(0.6, 2, 3, 0.75f);  // past the sharp edge: between the second 0.5 and 0.9
  check(0.9, 3, 3, 1.0f);   // at or above the last: the last alone
  check(2.0, 3, 3, 1.0f);
}

TEST_CASE("a material map blends the shaded colours of its entries by the pattern's value",
          "[render][material-map]") {
  // Ambient light only. Gradient along x (the value is x's fraction): red at 0.25, blue at
  // 0.75, each its own ambient; between them the blend, outside them the nearer one alone.
  auto scene = parse(R"XML(<render ambient="1" background="0 1 0"/>
    <material id="red" ambient="1 0 0"/>
    <plane normal="0 1 0" offset="0"><material><material-map>
      <pattern type="gradient" axis="1 0 0"/>
      <entry at="0.25" material="red"/>
      <entry at="0.75"><material ambient="0 0 1"/></entry>
    </material-map></material></plane>)XML");
  World world(*scene);
  auto at = [&](double x) { return traceOne(world, Ray(Vec3(x, 1, 0.3), Vec3(0, -1, 0))); };
  checkColor(at(0.1), Color(1, 0, 0));
  checkColor(at(0.5), Color(0.5f, 0, 0.5f));
  checkColor(at(0.6), Color(0.3f, 0, 0.7f));
  checkColor(at(0.9), Color(0, 0, 1));
}

TEST_CASE("a checker map's cells show its entries at 0 and 1, mirrors and all",
          "[render][material-map]") {
  // Cell 0 a mirror (the background above it, 0.8 grey), cell 1 a matte ambient green.
  auto scene = parse(R"XML(<render ambient="1" background="0.8 0.8 0.8"/>
    <plane normal="0 1 0" offset="0"><material><material-map><checker/>
      <entry at="0"><material reflective="1"/></entry>
      <entry at="1"><material ambient="0 0.5 0"/></entry>
    </material-map></material></plane>)XML");
  World world(*scene);
  checkColor(traceOne(world, Ray(Vec3(0.5, 1, 0.5), Vec3(0, -1, 0))), Color(0.8f));
  checkColor(traceOne(world, Ray(Vec3(1.5, 1, 0.5), Vec3(0, -1, 0))), Color(0, 0.5f, 0));
}

TEST_CASE("light through a map: an entry's own transmitted ray, and a shadow ray's blend",
          "[render][material-map]") {
  // A sheet halfway between a clear entry (k_t 1) and an opaque one: the background is
  // seen at half weight, and the floor under it gets half the light.
  auto sheet = parse(R"XML(<render ambient="1" background="0.4 0.6 0.8"/>
    <disc center="0 0 0" normal="0 1 0" radius="10"><material><material-map>
      <pattern type="gradient" axis="1 0 0"/>
      <entry at="0"><material transmissive="1"/></entry>
      <entry at="1"><material ambient="0.2"/></entry>
    </material-map></material></disc>)XML");
  World world(*sheet);
  checkColor(traceOne(world, Ray(Vec3(0.5, 1, 0.3), Vec3(0, -1, 0))),
             Color(0.4f, 0.6f, 0.8f) * 0.5f + Color(0.1f));

  auto shadow = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <disc center="0 1 0" normal="0 1 0" radius="100"><material><material-map>
      <pattern type="gradient" axis="1 0 0"/>
      <entry at="0"><material transmissive="1"/></entry>
      <entry at="1"><material/></entry>
    </material-map></material></disc>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world2(*shadow);
  checkColor(traceOne(world2, Ray(Vec3(0.25, 0.5, 0.3), Vec3(0, -1, 0))), Color(0.75f));
}
