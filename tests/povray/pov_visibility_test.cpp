// image="false", reflection="false", double-illuminate and interior-material as POV-Ray's
// no_image, no_reflection (as no_shadow: on each leaf, or on a whole merge, intersection or
// difference), double_illuminate and interior_texture (on every leaf under the node).
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("image and reflection flags are no_image and no_reflection on each leaf",
          "[povray][visibility]") {
  Exported e = exportScene(R"XML(
    <sphere image="false"/>
    <group reflection="false"><box/><union><sphere radius="0.5"/><sphere center="1 0 0" radius="0.5" image="false"/></union></group>
    <difference image="false"><box/><sphere radius="0.5" reflection="false"/></difference>
    <cone/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "no_image") == 3);       // sphere, union sphere, difference
  CHECK(occurrences(e.pov.text, "no_reflection") == 3);  // box, both union spheres
  CHECK(e.has("  no_image\n}\n"));
}

TEST_CASE("double-illuminate and interior-material go on every leaf", "[povray][visibility]") {
  Exported e = exportScene(R"XML(
    <material id="shell" diffuse="0 1 0"/>
    <material id="lining" diffuse="1 1 0"/>
    <disc double-illuminate="true"/>
    <difference material="shell" interior-material="lining"><sphere/><box/></difference>
    <sphere material="lining" interior-material="lining"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(occurrences(e.pov.text, "double_illuminate") == 1);
  // The difference's two leaves; the sphere whose interior material is its own writes none.
  CHECK(occurrences(e.pov.text, "interior_texture {") == 2);
}
