// <image use-alpha> exported as POV-Ray's image_map, which reads the image's alpha as
// transmit itself, and rendered by POV-Ray to Lucent's image; without use-alpha the export
// says that POV-Ray would read it.
#include "../sdl/pov_meaning_support.h"
#include "../support/paths.h"

#include "lang/parser.h"
#include "povray/pov_export.h"

using namespace lucent;
using namespace lucent::test;

namespace {

// An RGBA image (tests/data/sdl/scenes/image_pattern_rgba8.png, 5 x 4, random alphas)
// projected onto the plane z = 0 in front of a checker wall; `alpha` is the image's
// use-alpha.
std::unique_ptr<Scene> alphaScene(const std::string& alpha) {
  const std::string xml = R"XML(<scene version="1">
  <render width="120" height="96" background="1 0.2 0.1"/>
  <camera type="orthographic" position="0.5 0.5 5" look-at="0.5 0.5 0" width="1.25"/>
  <plane normal="0 0 1" offset="-1"><material ambient="1" diffuse="0">
    <checker color1="0.1 0.3 0.9" color2="0.9 0.9 0.2" scale="0.125"/></material></plane>
  <plane normal="0 0 1"><material ambient="1" diffuse="0">
    <image src="image_pattern_rgba8.png" projection="planar" interpolate="none" )XML" +
                          alpha + R"XML(/></material></plane>
</scene>)XML";
  ParseResult parsed =
      parseSceneString(xml, std::string(lucentSourceDir()) + "/tests/data/sdl/scenes/alpha.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  return std::move(parsed.scene);
}

std::string messagesOf(const PovExport& e) {
  std::string all;
  for (const PovIssue& i : e.issues) all += i.message + "\n";
  return all;
}

}  // namespace

TEST_CASE("an image that reads its alpha renders in POV-Ray as in Lucent",
          "[povray][image-map][alpha][image]") {
  auto scene = alphaScene("use-alpha=\"true\"");
  const PovExport e = exportPov(*scene);
  INFO(messagesOf(e));
  REQUIRE(e.ok());
  CHECK(messagesOf(e).find("alpha channel") == std::string::npos);
  requireSameImage(*scene, e.text);
}

TEST_CASE("an image that does not read its alpha is exported with a warning",
          "[povray][image-map][alpha]") {
  auto scene = alphaScene("");
  const PovExport e = exportPov(*scene);
  REQUIRE(e.ok());
  CHECK(messagesOf(e).find("has an alpha channel, which POV-Ray uses as transparency") !=
        std::string::npos);
}
