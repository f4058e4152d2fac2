// The interior of a solid CSG operation is written once, on the CSG object, so POV-Ray's
// operands share it: a ray entering a lens through one sphere leaves through the other
// into the air (with one interior per leaf POV-Ray takes that exit for an entry into a
// second glass and does not bend; examples/gallery/csg-lens.xml fell to 17 dB that way).
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("a glass intersection holds one interior shared by its leaves", "[povray][geometry]") {
  Exported e = exportScene(R"XML(<material id="glass" transmissive="0.9" ior="1.5"/>
<material id="amber" transmissive="0.5" ior="1.3"/>
<intersection material="glass">
  <sphere center="0 0 -1.6" radius="2"/>
  <sphere center="0 0 1.6" radius="2"/>
  <box min="-3 -3 -3" max="3 0.5 3" material="amber"/>
</intersection>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("intersection {  // <intersection> test.xml:5:1\n"
            "  sphere {  // <sphere> test.xml:6:3\n"
            "    <0, 0, -1.6>, 2\n"
            "    texture { M1_glass }\n"
            "  }\n"
            "  sphere {  // <sphere> test.xml:7:3\n"
            "    <0, 0, 1.6>, 2\n"
            "    texture { M1_glass }\n"
            "  }\n"
            "  box {  // <box> test.xml:8:3\n"
            "    <-3, -3, -3>, <3, 0.5, 3>\n"
            "    texture { M2_amber }\n"
            "    interior { IM2_amber }\n"
            "  }\n"
            "  interior { IM1_glass }\n"
            "}\n"));
}

TEST_CASE("a glass union keeps one interior per leaf, as it keeps every surface",
          "[povray][geometry]") {
  Exported e = exportScene(R"XML(<material id="glass" transmissive="0.9" ior="1.5"/>
<union material="glass">
  <sphere center="-0.5 0 0"/>
  <merge>
    <sphere center="0.5 0 0"/>
    <sphere center="0.5 1 0"/>
  </merge>
</union>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("  sphere {  // <sphere> test.xml:5:3\n"
            "    <-0.5, 0, 0>, 1\n"
            "    texture { M1_glass }\n"
            "    interior { IM1_glass }\n"
            "  }\n"));
  // The merge inside the union is a solid operation: its own leaves share its interior.
  CHECK(
      e.has("    sphere {  // <sphere> test.xml:8:5\n"
            "      <0.5, 1, 0>, 1\n"
            "      texture { M1_glass }\n"
            "    }\n"
            "    interior { IM1_glass }\n"
            "  }\n"));
}
