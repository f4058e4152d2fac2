// mapping="uv" exported as POV-Ray's uv_mapping, first in the pigment, normal or texture
// block; POV-Ray's (u,v) taken in its left-handed space: mirrored in u on spheres, tori,
// lathes and sors, and a box written mirrored in z.
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

TEST_CASE("uv mapping on a sphere, torus, lathe, sor or ovus is written mirrored in u, a box in z",
          "[povray][materials][uv-mapping]") {
  // u -> 1 - u first: POV-Ray's placement takes (u, v) to 4·(1 - u, v), the inverse of
  // x -> 1 - x/4, y -> y/4.
  for (const char* shape : {"sphere", "torus", "sor points=\"1 0  1 1  1 2  1 3\"",
                            "lathe points=\"1 0  1 1\"", "ovus"}) {
    Exported e = exportScene("<" + std::string(shape) +
                             R"XML(><material><checker mapping="uv" transform="scale(0.25)"/>
        </material></)XML" + std::string(shape).substr(0, std::string(shape).find(' ')) +
                             ">");
    INFO(shape << "\n" << e.messages() << e.pov.text);
    REQUIRE(e.pov.ok());
    CHECK(e.has("uv_mapping\n      checker"));
    CHECK(e.has("matrix <-0.25, 0, 0,  0, 0.25, 0,  0, 0, 0.25,  1, 0, 0>"));
  }
  Exported box =
      exportScene(R"XML(<box min="0 1 2" max="3 4 5"><material><checker mapping="uv"/></material>
      </box>)XML");
  INFO(box.messages() << box.pov.text);
  REQUIRE(box.pov.ok());
  CHECK(
      box.has("  <0, 1, -5>, <3, 4, -2>\n  matrix <1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0, 0>\n"
              "  texture"));
  // A cylinder's (u,v) are the world's x and y in both: written as they are.
  Exported cylinder =
      exportScene(R"XML(<cylinder><material><checker mapping="uv"/></material></cylinder>)XML");
  REQUIRE(cylinder.pov.ok());
  CHECK_FALSE(cylinder.has("matrix"));

  Exported mixed = exportScene(std::string(kQuad) + R"XML(<material><material-map>
      <pattern type="gradient" mapping="uv"/>
      <entry at="0"><material diffuse="1 0 0"/></entry>
      <entry at="1"><material><pattern type="bozo"/></material></entry>
      </material-map></material></mesh>)XML");
  CHECK_FALSE(mixed.pov.ok());
  CHECK(mixed.messages().find("the map is mapped at (u,v) and an entry is not") !=
        std::string::npos);
}
