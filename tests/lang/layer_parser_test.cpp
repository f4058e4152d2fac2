// <layer> in <material>: its surface terms, texture and normal, diffuse 1 under a texture,
// the order of layers, base= (own layers replace the base's), and the messages for the
// interior terms and children a layer cannot take.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("layer: each <layer> is read in order, bottom first, with its own terms",
          "[lang][material][layers]") {
  auto s = parseClean(R"XML(
    <material id="wood" diffuse="0.7 0.4 0.2" ior="1.2" phong="0.3">
      <checker/>
      <layer ambient="0.2" specular="0.5" shininess="20"><pattern type="bozo"/>
        <normal type="bumps" depth="0.3"/></layer>
      <layer reflective="0.25" diffuse="0.1"/>
    </material>
    <material id="again" base="wood" phong="0.6"/>
    <material id="other" base="wood"><layer transmissive="0.5"/></material>)XML");
  const Material& wood = materialNamed(*s, "wood");
  CHECK(wood.ior == 1.2);
  REQUIRE(wood.layers.size() == 2);
  const Material& grain = wood.layers[0];
  CHECK(grain.ambient == Color(0.2f));
  CHECK(grain.specular == Color(0.5f));
  CHECK(grain.shininess == 20.0);
  CHECK(grain.diffuse == Color(1.0f));  // a texture without diffuse shows as it is
  CHECK(std::holds_alternative<PatternTexture>(grain.texture));
  REQUIRE(grain.normal);
  CHECK(grain.normal->depth == 0.3);
  CHECK(grain.ior == 1.0);  // the interior is the material's alone
  CHECK(wood.layers[1].reflective == Color(0.25f));
  CHECK(wood.layers[1].diffuse == Color(0.1f));
  // base= keeps the base's layers unless the material writes its own.
  const Material& again = materialNamed(*s, "again");
  CHECK(again.phong == Color(0.6f));
  CHECK(again.layers.size() == 2);
  const Material& other = materialNamed(*s, "other");
  REQUIRE(other.layers.size() == 1);
  CHECK(other.layers[0].transmissive == Color(0.5f));
  CHECK(other.layered());
  CHECK(!materialNamed(*s, "wood").isTransmissive());
}

TEST_CASE("layer: the interior terms, a second texture and a nested layer are errors",
          "[lang][material][layers]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><layer ior=\"1.5\" hollow=\"true\"/></material>"
      "\n<material id=\"b\"><layer><checker/><checker/></layer></material>"
      "\n<material id=\"c\"><layer><layer/></layer></material>"
      "\n<material id=\"d\"><layer diffuse=\"x\" roughness=\"0.1\"/></material>",
      "layers.xml");
  const std::string text = messages(r);
  CHECK(text.find("layers.xml:2:30: error: <layer> attribute 'ior': a term of the whole "
                  "material (its interior), not of one layer: write it on the <material>") !=
        std::string::npos);
  CHECK(text.find("layers.xml:2:43: error: <layer> attribute 'hollow': a term of the whole "
                  "material") != std::string::npos);
  CHECK(text.find("layers.xml:3:35: error: <layer> holds one texture at most; the first is at "
                  "layers.xml:3:25") != std::string::npos);
  CHECK(text.find(
            "layers.xml:4:25: error: <layer> may hold a texture (<checker>, <image>, "
            "<pattern>, <hexagon>, <brick> or <average>), a <normal> or <bump-map>, not <layer>") !=
        std::string::npos);
  CHECK(text.find("(POV-Ray's 'roughness' is 'shininess' (1/roughness) in Lucent)") !=
        std::string::npos);
}
