// <fog> in POV-Ray: fog_type 1 or 2 with the colour's filter and transmit as rgbft, its
// turbulence, every fog of the scene; a hollow material's objects are hollow.
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("constant fog is POV-Ray's fog_type 1", "[povray][fog]") {
  Exported e = exportScene(R"XML(<fog color="0.7 0.75 0.8" distance="9" transmit="0.2"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  fog_type 1\n  distance 9\n  color rgbft <0.7, 0.75, 0.8, 0, 0.2>\n}\n"));
}

TEST_CASE("ground fog is POV-Ray's fog_type 2 with fog_offset, fog_alt and up", "[povray][fog]") {
  Exported e = exportScene(
      R"XML(<fog type="ground" color="1" distance="4" filter="0.5" offset="0.25" altitude="0.5"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("  fog_type 2\n  distance 4\n  color rgbft <1, 1, 1, 0.5, 0>\n  fog_offset 0.25\n  "
            "fog_alt 0.5\n"
            "  up <0, 1, 0>\n}\n"));
}

TEST_CASE("a scene without fog exports none", "[povray][fog]") {
  Exported e = exportScene(R"XML(<sphere/>)XML");
  REQUIRE(e.pov.ok());
  CHECK_FALSE(e.has("fog"));
}

TEST_CASE("every fog is exported, with its turbulence, and a mirroring transform folds into it",
          "[povray][fog]") {
  Exported e = exportScene(
      R"XML(<fog color="1" distance="3"/>
<fog type="ground" color="0 0 1" distance="2" turbulence="0.2 0.3 0.4" octaves="5" omega="0.35" lambda="1.25" turb-depth="0.6" transform="scale(1 1 -1)"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  fog_type 1\n  distance 3\n  color rgbft <1, 1, 1, 0, 0>\n}\n"));
  CHECK(
      e.has("  up <0, 1, 0>\n  turbulence <0.2, 0.3, -0.4>\n  octaves 5\n  omega 0.35\n  "
            "lambda 1.25\n  turb_depth 0.6\n}\n"));
}

TEST_CASE("an object of a hollow material is hollow in POV-Ray", "[povray][fog]") {
  Exported e = exportScene(R"XML(<sphere><material diffuse="1" hollow="true"/></sphere>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("hollow"));
  CHECK_FALSE(exportScene(R"XML(<sphere><material diffuse="1"/></sphere>)XML").has("hollow"));
}

TEST_CASE("a light with media-attenuation has media_attenuation on", "[povray][fog]") {
  CHECK(exportScene(R"XML(<light position="0 5 0" media-attenuation="true"/>)XML")
            .has("  media_attenuation on\n"));
  CHECK_FALSE(exportScene(R"XML(<light position="0 5 0"/>)XML").has("media_attenuation"));
}
