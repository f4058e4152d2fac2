// <light-group> as POV-Ray's light_group: its own lights inside it (placed in the world as
// every exported light), its objects, global_lights; its lights not again among the
// global ones; refused inside a merge, intersection or difference.
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("a light group is written as light_group with its own lights", "[povray][light-group]") {
  Exported e = exportScene(R"XML(
    <light position="0 9 0"/>
    <light-group global-lights="true" transform="translate(1 0 0)">
      <light position="0 5 0" color="1 0 0"/>
      <sphere/>
      <group><light position="3 3 3" color="0 1 0"/><box/></group>
    </light-group>
    <light-group><light position="0 4 0"/><sphere center="5 0 0"/></light-group>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "light_group {") == 2);
  CHECK(occurrences(e.pov.text, "light_source {") == 4);
  CHECK(occurrences(e.pov.text, "global_lights on") == 1);
  CHECK(occurrences(e.pov.text, "global_lights off") == 1);
  // The group's red light inside its block, moved by the group; the one deeper in it is
  // global, written with the top-level lights before every object.
  const size_t group = e.pov.text.find("light_group {");
  const size_t red = e.pov.text.find("rgb <1, 0, 0>");
  const size_t green = e.pov.text.find("rgb <0, 1, 0>");
  REQUIRE(red != std::string::npos);
  CHECK(red > group);
  CHECK(green < group);
  CHECK(e.has("<1, 5, 0>"));
}

TEST_CASE("a light group inside a merge cannot be written", "[povray][light-group]") {
  Exported e = exportScene(R"XML(
    <merge><sphere/><light-group><light position="0 4 0"/><box/></light-group></merge>)XML");
  CHECK_FALSE(e.pov.ok());
  CHECK(e.messages().find("a <light-group> inside a merge, intersection or difference cannot be "
                          "written") != std::string::npos);
}
