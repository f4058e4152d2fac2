// Layered materials (render/surface_slots.h, Tracer::shadeLayers): each layer's own light
// seen through the layers above, mirror rays undimmed, the light from behind and shadow
// rays through every layer; checked pixel by pixel against POV-Ray 3.7's formula.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "layers.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

void checkColor(const Color& got, const Color& want) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-5));
}

}  // namespace

TEST_CASE("a layer's own light is dimmed by what the layers above let through",
          "[render][layers]") {
  // Ambient light only (1), background green. Bottom: ambient (1, 0.5, 0.25). Middle: blue
  // (0, 0, 1) with filter 0.5 and transmit 0.25 (ambient 1, a single number: times the
  // colour and the opacity 0.25). Top: grey 0.5 with transmit 0.5 (opacity 0.5).
  // Seen: top 0.5·0.5 + through(top) = 0.5 over the middle: blue·0.25 +
  // (blue·0.5 + 0.25) over the bottom; no light comes from behind the opaque bottom.
  auto scene = parse(R"XML(<render ambient="1" background="0 1 0"/>
    <plane normal="0 1 0" offset="0"><material ambient="1 0.5 0.25">
      <layer ambient="1"><pattern type="gradient"><color-map>
        <entry at="0" color="0 0 1" filter="0.5" transmit="0.25"/></color-map></pattern></layer>
      <layer ambient="1"><pattern type="gradient"><color-map>
        <entry at="0" color="0.5 0.5 0.5" transmit="0.5"/></color-map></pattern></layer>
    </material></plane>)XML");
  World world(*scene);
  const Color got = traceOne(world, Ray(Vec3(0.3, 1, 0.3), Vec3(0, -1, 0)));
  const Color bottom(1.0f, 0.5f, 0.25f), blue(0.0f, 0.0f, 1.0f);
  const Color middle = blue * 0.25f + (blue * 0.5f + Color(0.25f)) * bottom;
  checkColor(got, Color(0.25f) + Color(0.5f) * middle);
}

TEST_CASE("light from behind crosses every layer, and an opaque layer hides the ones below",
          "[render][layers]") {
  // A thin sheet (a disc) over a green background. Bottom: k_t 0.8 (no local light).
  // Layer: red (1, 0, 0) with filter 1 (opacity 0): lets red·1 through.
  auto sheet = parse(R"XML(<render ambient="1" background="0.5 1 0.25"/>
    <disc center="0 0 0" normal="0 1 0" radius="10"><material transmissive="0.8">
      <layer><pattern type="gradient"><color-map>
        <entry at="0" color="1 0 0" filter="1"/></color-map></pattern></layer>
    </material></disc>)XML");
  World world(*sheet);
  checkColor(traceOne(world, Ray(Vec3(0.3, 1, 0.3), Vec3(0, -1, 0))),
             Color(0.5f * 0.8f, 0.0f, 0.0f));

  // An opaque top layer: only its own light, whatever lies below.
  auto opaque = parse(R"XML(<render ambient="1" background="0 1 0"/>
    <disc center="0 0 0" normal="0 1 0" radius="10"><material emissive="5" transmissive="1">
      <layer ambient="0.25"/>
    </material></disc>)XML");
  World world2(*opaque);
  checkColor(traceOne(world2, Ray(Vec3(0.3, 1, 0.3), Vec3(0, -1, 0))), Color(0.25f));
}

TEST_CASE("a lower layer's mirror ray is added undimmed, as POV-Ray adds it", "[render][layers]") {
  // Bottom: reflective 0.5, nothing else; top: transmit 0.5 white (ambient 1·0.5).
  // Looking straight down at the plane, the mirror ray goes up into the background 0.8.
  auto scene = parse(R"XML(<render ambient="1" background="0.8 0.8 0.8"/>
    <plane normal="0 1 0" offset="0"><material reflective="0.5">
      <layer ambient="1"><pattern type="gradient"><color-map>
        <entry at="0" color="1 1 1" transmit="0.5"/></color-map></pattern></layer>
    </material></plane>)XML");
  World world(*scene);
  checkColor(traceOne(world, Ray(Vec3(0.3, 1, 0.3), Vec3(0, -1, 0))), Color(0.5f + 0.5f * 0.8f));
}

TEST_CASE("a shadow ray keeps the product of what the layers let through", "[render][layers]") {
  // A sheet over a white floor lit from straight above: bottom k_t 0.5, layer filter 0.5
  // over (1, 0.5, 0) plus transmit 0.25: the floor gets 0.5·((1, 0.5, 0)·0.5 + 0.25).
  auto scene = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <disc center="0 1 0" normal="0 1 0" radius="100"><material transmissive="0.5">
      <layer diffuse="0"><pattern type="gradient"><color-map>
        <entry at="0" color="1 0.5 0" filter="0.5" transmit="0.25"/></color-map></pattern></layer>
    </material></disc>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world(*scene);
  checkColor(traceOne(world, Ray(Vec3(0.3, 0.5, 0.3), Vec3(0, -1, 0))),
             Color(0.5f * 0.75f, 0.5f * 0.5f, 0.5f * 0.25f));
}
