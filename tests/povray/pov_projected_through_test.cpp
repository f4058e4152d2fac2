// <light><projected-through> exported as POV-Ray's projected_through: written inside the
// light_source where the light is placed, and rendered by POV-Ray to Lucent's image.
#include "pov_test_support.h"

#include "../sdl/pov_meaning_support.h"

using namespace lucent;
using namespace lucent::test;

namespace {

// A floor lit through a ring and a ball by a light moved with them (a <use> of a lamp), a
// ball between them and the light (no shadow) and one below (a shadow in the ring), and a
// shadowless light through a turned box.
const char* kScene = R"XML(
  <render width="160" height="120"/>
  <camera position="0 9 9" look-at="0 0 -0.5" fov="60"/>
  <material id="white" diffuse="0.8" ambient="0.02"/>
  <material id="red" diffuse="0.8 0.2 0.2"/>
  <plane normal="0 1 0" material="white"/>
  <defs>
    <group id="lamp">
      <light position="0 8 0" color="1 0.85 0.6">
        <projected-through>
          <union transform="scale(0.5) translate(0 4 0)">
            <torus major="1" minor="0.15"/>
            <sphere radius="0.35"/>
          </union>
        </projected-through>
      </light>
    </group>
  </defs>
  <use ref="lamp" transform="translate(-2.5 0 0)"/>
  <sphere center="-2.5 6 0" radius="0.3" material="red"/>
  <sphere center="-1.5 1 0" radius="0.3" material="red"/>
  <light position="2.5 8 -1" color="0.5 0.6 1" shadows="false" highlights="false">
    <projected-through>
      <box min="-0.5 -0.5 -0.5" max="0.5 0.5 0.5" transform="rotate-y(30) translate(2.5 5 -1)"/>
    </projected-through>
  </light>)XML";

}  // namespace

TEST_CASE("projected-through objects are written as projected_through in their light",
          "[povray][lights][projected-through]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "projected_through {") == 2);
  // Each inside its light_source, after the light's colour: the lamp's holds the ring.
  const size_t light = e.pov.text.find("rgb <1, 0.85, 0.6>");
  REQUIRE(light != std::string::npos);
  const size_t through = e.pov.text.find("projected_through {", light);
  REQUIRE(through != std::string::npos);
  CHECK(e.pov.text.rfind("light_source {", through) < light);
  CHECK(e.pov.text.find("torus {", through) != std::string::npos);
}

TEST_CASE("an exported projected-through light renders in POV-Ray as in Lucent",
          "[povray][lights][projected-through][image]") {
  Exported e = exportScene(kScene);
  REQUIRE(e.pov.ok());
  requireSameImage(*e.scene, e.pov.text);
}
