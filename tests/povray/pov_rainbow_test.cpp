// <rainbow> exported as POV-Ray's rainbow and rendered by POV-Ray to Lucent's image.
#include "pov_test_support.h"

#include "../sdl/pov_meaning_support.h"

using namespace lucent;
using namespace lucent::test;

namespace {

// Two rainbows over a sky and a wall: one partly transparent (filter, transmit), faded by
// distance, on an arc with a falloff; one whole and opaque.
const char* kScene = R"XML(
  <render width="160" height="120" background="0.3 0.5 0.8"/>
  <camera position="0 1 0" look-at="0 3 -10" fov="100"/>
  <box min="2 -1 -30" max="12 6 -29"><material emissive="0.8 0.7 0.6"/></box>
  <plane normal="0 1 0" offset="-1"><material diffuse="0.6" ambient="0.2"/></plane>
  <light position="0 20 10"/>
  <rainbow direction="0.1 -0.2 -1" up="0 1 0" angle="35" width="8" distance="40" arc-angle="160" falloff-angle="100">
    <color-map>
      <entry at="0" color="1 0.4 1" filter="1"/>
      <entry at="0.3" color="0.2 0.2 1" filter="0.7"/>
      <entry at="0.6" color="0.2 1 0.2" transmit="0.3"/>
      <entry at="1" color="1 0.2 0.2"/>
    </color-map>
  </rainbow>
  <rainbow direction="0.1 -0.2 -1" angle="48" width="4">
    <color-map><entry at="0" color="1 1 0"/><entry at="1" color="0 1 1"/></color-map>
  </rainbow>)XML";

}  // namespace

TEST_CASE("rainbows are written as POV-Ray's rainbow", "[povray][rainbow]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "rainbow {") == 2);
  CHECK(e.has("arc_angle 160"));
  CHECK(e.has("falloff_angle 100"));
  CHECK(e.has("[0 color rgbft <1, 0.4, 1, 1, 0>]"));
}

TEST_CASE("exported rainbows render in POV-Ray as in Lucent", "[povray][rainbow][image]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  requireSameImage(*e.scene, e.pov.text);
}
