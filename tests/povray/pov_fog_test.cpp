// <fog> in POV-Ray: fog_type 1 or 2 with the colour's filter and transmit as rgbft.
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
