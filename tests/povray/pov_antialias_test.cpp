// adaptive-mode="corners" is parsed into the render settings and exported as the POV-Ray
// command line of the same method (+AM2 without jitter, same threshold and depth).
#include "pov_test_support.h"

using namespace lucent;
using namespace lucent::test;

TEST_CASE("corner sampling is parsed and exported as POV-Ray's +AM2 -J", "[povray][corners]") {
  Exported e = exportScene(
      R"XML(<render width="320" height="240" adaptive="0.2" adaptive-mode="corners" adaptive-depth="4"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.scene->render.adaptiveMode == AdaptiveMode::Corners);
  CHECK(e.scene->render.adaptiveDepth == 4);
  CHECK(e.scene->render.adaptive == 0.2);
  CHECK(e.has("// Render: povray +I<this file> +W320 +H240 +AM2 +A0.2 -J +R4"));
  CHECK(e.pov.issues.empty());
}

TEST_CASE("corner sampling keeps POV-Ray's depth 3 by default and warns of a threshold above 1",
          "[povray][corners]") {
  Exported e = exportScene(R"XML(<render adaptive="1.5" adaptive-mode="corners"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.scene->render.adaptiveDepth == 3);
  CHECK(e.has("+AM2 +A1.5 -J +R3"));
  CHECK(e.messages().find("exceeds 1, where POV-Ray clips its antialiasing threshold") !=
        std::string::npos);
}

TEST_CASE("without adaptive-mode the export keeps its no-antialiasing hint", "[povray][corners]") {
  Exported e = exportScene(R"XML(<render adaptive="0.2" samples="4"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.scene->render.adaptiveMode == AdaptiveMode::Centres);
  CHECK(e.has("-A   (+FN writes sRGB"));
  CHECK_FALSE(e.has("+AM2"));
}
