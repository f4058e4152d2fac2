// The light attributes that select POV-Ray's rules: a spot's tightness, POV-Ray's fade
// (fade-distance, fade-power) and highlights="false" (POV-Ray's shadowless light); their
// defaults keep Lucent's rules, and every bad value has a located message.
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

// The messages of a body with one <light> on line 2 of rules.xml, indented by 2.
std::string errors(const std::string& light) {
  return messages(parseBody("\n  " + light + "\n", "rules.xml"));
}

}  // namespace

TEST_CASE("lang: POV-Ray's light rules are off by default", "[lang][lights]") {
  const auto s = parseClean("<light type=\"spot\"/>", "rules.xml");
  const Light& l = onlyLight(*s);
  CHECK(l.tightness == 0.0);
  CHECK_FALSE(l.fades());
  CHECK(l.highlights);
  CHECK(l.shadows);
}

TEST_CASE("lang: tightness, fade and highlights are read", "[lang][lights]") {
  auto s = parseClean(
      "<light type=\"spot\" angle=\"40\" tightness=\"12.5\" fade-distance=\"3\" "
      "fade-power=\"0.5\" shadows=\"false\" highlights=\"false\"/>",
      "rules.xml");
  const Light& l = onlyLight(*s);
  CHECK(l.tightness == 12.5);
  CHECK(l.fadeDistance == 3.0);
  CHECK(l.fadePower == 0.5);
  CHECK_FALSE(l.shadows);
  CHECK_FALSE(l.highlights);
  // A tightness makes an area light spot-shaped, as its other spot attributes do.
  const auto areaScene = parseClean("<light type=\"area\" tightness=\"2\"/>", "rules.xml");
  const Light& area = onlyLight(*areaScene);
  CHECK(area.cone);
  CHECK(area.hasCone());
  CHECK(area.tightness == 2.0);
  // Either fade attribute alone fades the light, the other at its default (fd 1, fp 2).
  const auto distanceScene = parseClean("<light fade-distance=\"4\"/>", "rules.xml");
  const Light& distance = onlyLight(*distanceScene);
  CHECK(distance.fadeDistance == 4.0);
  CHECK(distance.fadePower == 2.0);
  const auto powerScene = parseClean("<light fade-power=\"3\"/>", "rules.xml");
  const Light& power = onlyLight(*powerScene);
  CHECK(power.fadeDistance == 1.0);
  CHECK(power.fadePower == 3.0);
  // highlights on every type, the fade on every positioned one.
  CHECK_FALSE(
      onlyLight(*parseClean("<light type=\"directional\" highlights=\"false\"/>", "rules.xml"))
          .highlights);
  CHECK(onlyLight(*parseClean("<light type=\"cylindrical\" fade-distance=\"2\" fade-power=\"1\"/>",
                              "rules.xml"))
            .fades());
}

TEST_CASE("lang: every bad light rule has a located message", "[lang][lights]") {
  CHECK(errors("<light type=\"spot\" tightness=\"-1\"/>") ==
        "rules.xml:2:33: error: <light> attribute 'tightness': expected a number >= 0, got "
        "'-1'\n");
  CHECK(errors("<light type=\"point\" tightness=\"3\"/>") ==
        "rules.xml:2:23: error: <light> attribute 'tightness': belongs to spot, area and "
        "cylindrical lights; this light is point (set type=\"spot\")\n");
  CHECK(errors("<light fade-distance=\"0\" fade-power=\"1\"/>") ==
        "rules.xml:2:25: error: <light> attribute 'fade-distance': expected a positive number, "
        "got '0'\n");
  CHECK(errors("<light fade-distance=\"2\" fade-power=\"-1\"/>") ==
        "rules.xml:2:40: error: <light> attribute 'fade-power': expected a positive number, "
        "got '-1'\n");
  CHECK(errors("<light attenuation=\"1 0 1\" fade-distance=\"2\" fade-power=\"2\"/>") ==
        "rules.xml:2:45: error: <light> attribute 'fade-distance': give either 'attenuation' or "
        "POV-Ray's fade ('fade-distance', 'fade-power'), not both\n");
  CHECK(errors("<light attenuation=\"1 0 1\" fade-power=\"2\"/>") ==
        "rules.xml:2:42: error: <light> attribute 'fade-power': give either 'attenuation' or "
        "POV-Ray's fade ('fade-distance', 'fade-power'), not both\n");
  CHECK(errors("<light type=\"directional\" fade-distance=\"2\" fade-power=\"2\"/>") ==
        "rules.xml:2:29: error: <light> attribute 'fade-distance': belongs to point, spot, area "
        "and cylindrical lights; this light is directional (set type=\"point\")\n"
        "rules.xml:2:47: error: <light> attribute 'fade-power': belongs to point, spot, area and "
        "cylindrical lights; this light is directional (set type=\"point\")\n");
  CHECK(errors("<light highlights=\"no\"/>") ==
        "rules.xml:2:22: error: <light> attribute 'highlights': expected true or false, got "
        "'no'\n");
}
