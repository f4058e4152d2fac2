// <bump-map> exported as POV-Ray's uv-mapped bump_map: the normal block on a mesh with
// uvs and on a sphere, and the shapes whose (u,v) or bump frame POV-Ray builds differently
// (errors naming them).
#include "povray/pov_export.h"

#include "../support/paths.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

using namespace lucent;

namespace {

// Scenes beside examples/gallery/, so that textures/bumps.png resolves.
PovExport exportBumpScene(const std::string& shape, std::string& messages) {
  std::string xml =
      "<scene version=\"1\">\n<camera position=\"0 1 5\"/>\n"
      "<material id=\"studs\" diffuse=\"0.8\"><bump-map src=\"textures/bumps.png\" "
      "depth=\"-1.25\"/></material>\n" +
      shape + "\n</scene>\n";
  ParseResult parsed =
      parseSceneString(xml, std::string(lucentSourceDir()) + "/examples/gallery/bump-test.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  PovExport e = exportPov(*parsed.scene);
  for (const PovIssue& i : e.issues) messages += i.message + "\n";
  UNSCOPED_INFO(messages);
  UNSCOPED_INFO(e.text);
  return e;
}

bool has(const PovExport& e, const std::string& s) { return e.text.find(s) != std::string::npos; }

// The normal block written for the test scenes' material, ending with `extra` lines.
std::string bumpNormalBlock(const std::string& extra) {
  const std::string path = std::string(lucentSourceDir()) + "/examples/gallery/textures/bumps.png";
  return "    normal {\n"
         "      uv_mapping\n"
         "      bump_map { png \"" +
         path +
         "\" gamma 1.0 interpolate 2 use_color }\n"
         "      bump_size -1.25\n" +
         extra + "    }\n";
}

}  // namespace

TEST_CASE("a bump map on a mesh with uvs is a uv-mapped bump_map read as stored",
          "[povray][bump-map]") {
  std::string messages;
  PovExport e = exportBumpScene(
      R"XML(<mesh positions="0 0 0  1 0 0  1 0 -1" uvs="0 0  1 0  1 1" indices="0 1 2" material="studs"/>)XML",
      messages);
  REQUIRE(e.ok());
  CHECK(messages.empty());
  CHECK(has(e, bumpNormalBlock("")));
  // Written inline with the shape, not declared.
  CHECK_FALSE(has(e, "#declare M1 = texture"));
}

TEST_CASE("a bump map on a sphere is a uv-mapped bump_map turned to Lucent's longitude",
          "[povray][bump-map]") {
  std::string messages;
  PovExport e =
      exportBumpScene(R"XML(<sphere center="1 2 3" radius="2" material="studs"/>)XML", messages);
  REQUIRE(e.ok());
  CHECK(messages.empty());
  // (u, v, 0) to (0.75 - u, v, 0) by a half turn about y, so that the bump frame is kept
  // (examples/gallery/bump-map-sphere.xml holds it to POV-Ray's image).
  CHECK(has(e, bumpNormalBlock("      scale <-1, 1, -1>\n      translate <0.75, 0, 0>\n")));
}

TEST_CASE("a bump map on a shape without POV-Ray's equal uv mapping is an export error",
          "[povray][bump-map]") {
  for (const char* shape : {R"XML(<plane normal="0 1 0" offset="0" material="studs"/>)XML",
                            R"XML(<disc material="studs"/>)XML"}) {
    std::string messages;
    PovExport e = exportBumpScene(shape, messages);
    CHECK_FALSE(e.ok());
    CHECK(messages.find("with the bump map of material 'studs': POV-Ray's bump_map bends the "
                        "normal as Lucent's only with uv_mapping, whose (u,v) equal Lucent's "
                        "only on meshes with uvs and on spheres") != std::string::npos);
  }
  std::string messages;
  PovExport box = exportBumpScene(R"XML(<box material="studs"/>)XML", messages);
  CHECK_FALSE(box.ok());
  CHECK(messages.find("<box> with the bump map") != std::string::npos);
}
