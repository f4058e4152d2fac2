// <light type="cylindrical">: POV-Ray's cylinder light. Its attributes and defaults, its
// axis from direction or look-at (placed by transforms, radius and falloff not), and a
// located message for every bad attribute.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

const Light& onlyLight(const Scene& s) {
  REQUIRE(s.lights.size() == 1);
  return s.lights[0];
}

// The messages of a body with one <light> on line 2 of cylinder.xml, indented by 2.
std::string errors(const std::string& light) {
  return messages(parseBody("\n  " + light + "\n", "cylinder.xml"));
}

}  // namespace

TEST_CASE("lang: a cylindrical light's defaults are POV-Ray's cylinder's", "[lang][lights]") {
  auto s = parseClean("<light type=\"cylindrical\"/>", "cylinder.xml");
  const Light& l = onlyLight(*s);
  CHECK(l.type == LightType::Cylindrical);
  CHECK(l.position == Vec3(0.0));
  CHECK(l.direction == Vec3(0, -1, 0));
  CHECK(l.radius == 0.75);
  CHECK(l.falloff == 1.0);
  CHECK(l.tightness == 0.0);
  CHECK(l.attenuation == Vec3(1, 0, 0));
  CHECK(l.color == Color(1.0f));
  CHECK(l.intensity == 1.0);
  CHECK(l.shadows);
}

TEST_CASE("lang: a cylindrical light reads its beam, its axis and the shared attributes",
          "[lang][lights]") {
  auto s = parseClean(
      "<light type=\"cylindrical\" position=\"1 4 2\" direction=\"0 0 -2\" radius=\"0.5\" "
      "falloff=\"2\" tightness=\"3\" color=\"1 0.5 0.25\" intensity=\"2\" attenuation=\"1 0 "
      "0.5\" shadows=\"false\"/>",
      "cylinder.xml");
  const Light& l = onlyLight(*s);
  CHECK(l.position == Vec3(1, 4, 2));
  CHECK(l.direction == Vec3(0, 0, -1));  // normalised
  CHECK(l.radius == 0.5);
  CHECK(l.falloff == 2.0);
  CHECK(l.tightness == 3.0);
  CHECK(l.color == Color(1.0f, 0.5f, 0.25f));
  CHECK(l.intensity == 2.0);
  CHECK(l.attenuation == Vec3(1, 0, 0.5));
  CHECK_FALSE(l.shadows);

  // look-at aims the axis from the position; radius may equal falloff (a hard edge).
  s = parseClean(
      "<light type=\"cylindrical\" position=\"0 3 0\" look-at=\"3 3 4\" radius=\"1\" "
      "falloff=\"1\"/>",
      "cylinder.xml");
  CHECK(onlyLight(*s).direction == Vec3(0.6, 0, 0.8));
  CHECK(onlyLight(*s).radius == 1.0);
  // radius 0: no smoothstep, the beam is (1 - rho/falloff)^tightness alone.
  CHECK(
      onlyLight(*parseClean("<light type=\"cylindrical\" radius=\"0\"/>", "cylinder.xml")).radius ==
      0.0);
}

TEST_CASE("lang: transforms move a cylindrical light's axis but not its radius and falloff",
          "[lang][lights]") {
  auto s = parseClean(
      "<group transform=\"scale(2) rotate-z(90) translate(10 0 0)\">"
      "<light type=\"cylindrical\" position=\"1 0 0\" direction=\"1 0 0\" radius=\"0.5\" "
      "falloff=\"0.8\"/></group>",
      "cylinder.xml");
  const Light& l = onlyLight(*s);
  CHECK(glm::length(l.position - Vec3(10, 2, 0)) <= 1e-12);
  CHECK(glm::length(l.direction - Vec3(0, 1, 0)) <= 1e-12);
  CHECK(l.radius == 0.5);  // as POV-Ray: distances, never scaled
  CHECK(l.falloff == 0.8);
}

TEST_CASE("lang: every bad attribute of a cylindrical light has a located message",
          "[lang][lights]") {
  CHECK(errors("<light type=\"cylindrical\" radius=\"-1\"/>") ==
        "cylinder.xml:2:37: error: <light> attribute 'radius': expected a number >= 0, got "
        "'-1'\n");
  CHECK(errors("<light type=\"cylindrical\" falloff=\"0\"/>") ==
        "cylinder.xml:2:38: error: <light> attribute 'falloff': expected a positive number, "
        "got '0'\n");
  CHECK(errors("<light type=\"cylindrical\" tightness=\"-2\"/>") ==
        "cylinder.xml:2:40: error: <light> attribute 'tightness': expected a number >= 0, got "
        "'-2'\n");
  CHECK(errors("<light type=\"cylindrical\" tightness=\"a lot\"/>") ==
        "cylinder.xml:2:40: error: <light> attribute 'tightness': expected a number, got 'a "
        "lot'\n");
  // The beam's edges: radius within falloff, each default named when it is the other side.
  CHECK(errors("<light type=\"cylindrical\" radius=\"2\" falloff=\"1.5\"/>") ==
        "cylinder.xml:2:37: error: <light> attribute 'radius': 'radius' (2) must not exceed "
        "'falloff' (1.5)\n");
  CHECK(errors("<light type=\"cylindrical\" radius=\"2\"/>") ==
        "cylinder.xml:2:37: error: <light> attribute 'radius': 'radius' (2) must not exceed "
        "'falloff' (1, its default)\n");
  CHECK(errors("<light type=\"cylindrical\" falloff=\"0.5\"/>") ==
        "cylinder.xml:2:38: error: <light> attribute 'falloff': 'falloff' (0.5) must not be "
        "less than 'radius' (0.75, its default)\n");
  // A wrong value is not compared as its default.
  CHECK(errors("<light type=\"cylindrical\" radius=\"big\" falloff=\"0.5\"/>") ==
        "cylinder.xml:2:37: error: <light> attribute 'radius': expected a number, got 'big'\n");
  // The axis, as a spot's.
  CHECK(errors("<light type=\"cylindrical\" direction=\"0 1 0\" look-at=\"1 1 1\"/>") ==
        "cylinder.xml:2:56: error: <light> attribute 'look-at': give either 'direction' or "
        "'look-at', not both\n");
  CHECK(errors("<light type=\"cylindrical\" position=\"1 2 3\" look-at=\"1 2 3\"/>") ==
        "cylinder.xml:2:55: error: <light> attribute 'look-at': 'look-at' must differ from "
        "'position'\n");
  CHECK(errors("<light type=\"cylindrical\" direction=\"0 0 0\"/>") ==
        "cylinder.xml:2:40: error: <light> attribute 'direction': a direction must not be the "
        "zero vector, got '0 0 0'\n");
  CHECK(errors("<light type=\"cylindrical\" attenuation=\"0 0 0\"/>") ==
        "cylinder.xml:2:42: error: <light> attribute 'attenuation': expected 3 numbers a b c >= "
        "0, not all zero, got '0 0 0'\n");
  // Attributes of other types, and the beam's on other types.
  CHECK(errors("<light type=\"cylindrical\" angle=\"20\"/>") ==
        "cylinder.xml:2:29: error: <light> attribute 'angle': belongs to spot and area lights; "
        "this light is cylindrical (set type=\"spot\")\n");
  CHECK(errors("<light type=\"cylindrical\" samples=\"4 4\"/>") ==
        "cylinder.xml:2:29: error: <light> attribute 'samples': belongs to area lights; this "
        "light is cylindrical (set type=\"area\")\n");
  // A spot's radius is POV-Ray's spotlight word: the message says Lucent's too.
  CHECK(errors("<light type=\"spot\" radius=\"0.5\"/>") ==
        "cylinder.xml:2:22: error: <light> attribute 'radius': belongs to cylindrical lights; "
        "this light is spot (set type=\"cylindrical\") (POV-Ray's 'radius' is 'inner' for a "
        "spot light in Lucent)\n");
  CHECK(errors("<light type=\"directional\" falloff=\"2\"/>") ==
        "cylinder.xml:2:29: error: <light> attribute 'falloff': belongs to cylindrical lights; "
        "this light is directional (set type=\"cylindrical\") (POV-Ray's 'falloff' is 'angle' "
        "for a spot light in Lucent)\n");
  CHECK(errors("<light type=\"cylindrical\" look_at=\"0 0 0\"/>")
            .find("cylinder.xml:2:29: error: <light>: unknown attribute 'look_at'") == 0);
}
