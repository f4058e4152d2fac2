// mapping="uv" exported as POV-Ray's uv_mapping, first in the pigment, normal or texture
// block; only meshes with uvs have POV-Ray's (u,v) (an export error elsewhere).
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

namespace {

const char* const kQuad =
    R"XML(<mesh positions="0 0 0  1 0 0  1 1 0  0 1 0" uvs="0 0  1 0  1 1  0 1" indices="0 1 2  0 2 3">)XML";

}  // namespace

TEST_CASE("a uv-mapped pattern, normal and map write uv_mapping first in their block",
          "[povray][materials][uv-mapping]") {
  Exported e = exportScene(std::string(kQuad) +
                           R"XML(<material><checker mapping="uv" transform="scale(0.5)"/>
      <normal type="bumps" depth="0.3" mapping="uv"/></material></mesh>)XML");
  INFO(e.messages() << e.pov.text);
  REQUIRE(e.pov.ok());
  CHECK(e.has("pigment {\n      uv_mapping\n      checker"));
  CHECK(e.has("normal {\n      uv_mapping\n      bumps 0.3"));

  Exported m = exportScene(std::string(kQuad) + R"XML(<material><material-map>
      <pattern type="gradient" mapping="uv"/>
      <entry at="0"><material diffuse="1 0 0"/></entry>
      <entry at="1"><material><pattern type="bozo" mapping="uv" transform="scale(0.5)"/></material></entry>
      </material-map></material></mesh>)XML");
  INFO(m.messages() << m.pov.text);
  REQUIRE(m.pov.ok());
  CHECK(m.has("uv_mapping\n    gradient <0, 1, 0>"));
  // The entry is written in the map's (u, v) space: its own uv_mapping is the map's.
  CHECK(m.pov.text.find("uv_mapping") == m.pov.text.rfind("uv_mapping"));
}

TEST_CASE("uv mapping on a shape whose (u,v) POV-Ray does not share is an export error",
          "[povray][materials][uv-mapping]") {
  Exported e =
      exportScene(R"XML(<sphere><material><checker mapping="uv"/></material></sphere>)XML");
  CHECK_FALSE(e.pov.ok());
  CHECK(e.messages() ==
        "test.xml:3:1: error: <sphere> with the inline material mapped at (u,v): POV-Ray's "
        "uv_mapping gives this shape other (u,v) than Lucent's (meshes with uvs can be "
        "exported)\n");

  Exported mixed = exportScene(std::string(kQuad) + R"XML(<material><material-map>
      <pattern type="gradient" mapping="uv"/>
      <entry at="0"><material diffuse="1 0 0"/></entry>
      <entry at="1"><material><pattern type="bozo"/></material></entry>
      </material-map></material></mesh>)XML");
  CHECK_FALSE(mixed.pov.ok());
  CHECK(mixed.messages().find("the map is mapped at (u,v) and an entry is not") !=
        std::string::npos);
}
