// Averaged material maps exported as POV-Ray's `average texture_map`, and a map's entries
// written in its warped space (both hand the entries the point after the map's warps).
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("an averaged material map is written as average texture_map with its weights",
          "[povray][materials][material-map]") {
  // The entry's bozo (scale 0.5, then the average's translate) is written in the
  // average's space: its scale alone; the average keeps its translate.
  Exported e = exportScene(R"XML(<sphere><material><material-map>
      <average transform="translate(1 0 0)"/>
      <entry weight="3"><material diffuse="1 0 0"/></entry>
      <entry weight="0.5"><material><pattern type="bozo" transform="scale(0.5) translate(1 0 0)"/></material></entry>
      </material-map></material></sphere>)XML");
  INFO(e.messages() << e.pov.text);
  REQUIRE(e.pov.ok());
  CHECK(e.messages().empty());
  CHECK(e.has("  average\n  texture_map {\n    [3\n    pigment { rgbft <1, 0, 0, 0, 0> }"));
  CHECK(e.has("    [0.5\n    pigment {\n      bozo"));
  CHECK(e.has("      matrix <0.5, 0, 0,  0, 0.5, 0,  0, 0, 0.5,  0, 0, 0>\n    }"));
  CHECK(e.has("  }\n  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  1, 0, 0>\n}"));
}

TEST_CASE("a warped material map's entries are written in its warped space, unwarned",
          "[povray][materials][material-map][warp]") {
  // The entry's placement is the map's whole linear placement (the scale step and the
  // translate): in POV-Ray's map space it has no transform of its own.
  Exported e = exportScene(R"XML(<box min="0 0 0" max="1 1 1"><material><material-map>
      <pattern type="gradient" axis="1 0 0" transform="translate(0 2 0)" turbulence="0.2">
        <warp type="transform" transform="scale(2)"/>
        <warp type="repeat" direction="1 0 0"/>
      </pattern>
      <entry at="0"><material><pattern type="bozo" transform="scale(2) translate(0 2 0)"/></material></entry>
      </material-map></material></box>)XML");
  INFO(e.messages() << e.pov.text);
  REQUIRE(e.pov.ok());
  CHECK(e.messages().empty());
  CHECK(
      e.has("    pigment {\n      bozo\n      color_map {\n        [0 rgbft <0, 0, 0, 0, 0>]\n"
            "        [1 rgbft <1, 1, 1, 0, 0>]\n      }\n    }"));
  CHECK(e.has("warp { repeat <1, 0, 0> offset <0, 0, 0> flip <0, 0, 0> }"));
}
