// shadows="false" as POV-Ray's no_shadow: on leaves (inherited from groups, unions and
// uses), on a whole merge, intersection or difference and never on its parts.
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("shadows=false is no_shadow on each leaf under the node", "[povray][no-shadow]") {
  Exported e = exportScene(R"XML(
    <sphere shadows="false"/>
    <group shadows="false"><box/><union><sphere radius="0.5"/><sphere center="1 0 0" radius="0.5"/></union></group>
    <defs><sphere id="s" radius="0.2"/></defs>
    <use ref="s" shadows="false"/>
    <use ref="s"/>
    <cone/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "no_shadow") == 5);  // sphere, box, two union spheres, one use
}

TEST_CASE("no_shadow goes on a whole difference, not on its parts", "[povray][no-shadow]") {
  Exported e = exportScene(R"XML(
    <difference shadows="false"><box/><sphere radius="0.5" shadows="false"/></difference>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "no_shadow") == 1);
  CHECK(e.has("  no_shadow\n}\n"));  // the last line of the difference
}

TEST_CASE("a one-operand difference written as its operand carries the difference's no_shadow",
          "[povray][no-shadow]") {
  Exported e = exportScene(
      R"XML(<difference shadows="false"><sphere/></difference><intersection><box shadows="false"/></intersection>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "no_shadow") == 1);
}
