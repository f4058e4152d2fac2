// Image textures as POV-Ray image_maps: the mapping transform per shape kind, and the
// shapes whose (u,v) POV-Ray cannot reproduce.
#include "povray/pov_image_map.h"
#include "povray/pov_export.h"
#include "scenegraph/shape_registry.h"

#include "../support/paths.h"
#include "lang/parser.h"

#include <catch2/catch.hpp>

using namespace lucent;

namespace {

// Scenes beside examples/, so that textures/uvgrid.png resolves.
PovExport exportImageScene(const std::string& shape, const std::string& scale,
                           std::string& messages) {
  std::string xml =
      "<scene version=\"1\">\n<camera position=\"0 1 5\"/>\n"
      "<material id=\"grid\" diffuse=\"1\"><image src=\"textures/uvgrid.png\" "
      "scale=\"" +
      scale + "\"/></material>\n" + shape + "\n</scene>\n";
  ParseResult parsed =
      parseSceneString(xml, std::string(lucentSourceDir()) + "/examples/image-test.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  PovExport e = exportPov(*parsed.scene);
  for (const PovIssue& i : e.issues) messages += i.message + "\n";
  UNSCOPED_INFO(messages);
  UNSCOPED_INFO(e.text);
  return e;
}

bool has(const PovExport& e, const std::string& s) { return e.text.find(s) != std::string::npos; }

}  // namespace

TEST_CASE("an image on a plane is a planar image_map turned onto the plane's tangents",
          "[povray][image]") {
  std::string messages;
  PovExport e = exportImageScene(R"XML(<plane normal="0 0 1" offset="-4" material="grid"/>)XML",
                                 "3 3", messages);
  REQUIRE(e.ok());
  std::string path = std::string(lucentSourceDir()) + "/examples/textures/uvgrid.png";
  // Wall: u = x, v = y; one copy per 3 units.
  CHECK(has(e, "      image_map { png \"" + path +
                   "\" gamma srgb interpolate 2 }\n"
                   "      matrix <3, 0, 0,  0, 3, 0,  0, 0, 1,  0, 0, 0>\n"));
}

TEST_CASE("an image on a sphere is POV-Ray's spherical map, reflected onto Lucent's (u,v)",
          "[povray][image]") {
  std::string messages;
  PovExport e =
      exportImageScene(R"XML(<sphere center="1 2 3" material="grid"/>)XML", "1 1", messages);
  REQUIRE(e.ok());
  CHECK(has(e,
            "gamma srgb map_type 1 interpolate 2 }\n"
            "      matrix <0, 0, -1,  0, 1, 0,  -1, 0, 0,  0, 0, 0>\n"
            "      translate <1, 2, 3>\n"));

  std::string scaled;
  PovExport bad = exportImageScene(R"XML(<sphere material="grid"/>)XML", "2 1", scaled);
  CHECK_FALSE(bad.ok());
  CHECK(scaled ==
        "<sphere> with the image texture of material 'grid': POV-Ray's spherical map "
        "covers the sphere once; image scale 2 1 has no equivalent\n");
}

TEST_CASE("an image on a box becomes six face planes, each with its own copy", "[povray][image]") {
  std::string messages;
  PovExport e =
      exportImageScene(R"XML(<box min="0 0 0" max="2 1 4" material="grid"/>)XML", "1 1", messages);
  REQUIRE(e.ok());
  CHECK(has(e, "intersection {  // <box>"));
  // The +x face: u = (hi_z − z)/4, v = y/1: pattern x = 4 − 4u... as the inverse matrix.
  CHECK(has(e, "  plane {\n    <1, 0, 0>, 2\n"));
  CHECK(has(e, "  plane {\n    <-1, 0, 0>, 0\n"));
  const ShapeSpec box = BoxSpec{Vec3(0, 0, 0), Vec3(2, 1, 4)};
  std::vector<ImageMapFace> faces = shapeTypeOf(box).povImageFaces(box);
  REQUIRE(faces.size() == 6);
  // Face +x (index 1): a point on it maps to Lucent's u = (4 − z)/4, v = y.
  Vec4 uv = faces[1].mapping.uvFromObject * Vec4(2.0, 0.25, 1.0, 1.0);
  CHECK(uv.x == Approx(0.75));
  CHECK(uv.y == Approx(0.25));
  // Face −z (index 4): seen from outside (from −z) right is −x: u = (2 − x)/2.
  uv = faces[4].mapping.uvFromObject * Vec4(0.5, 0.5, 0.0, 1.0);
  CHECK(uv.x == Approx(0.75));
  CHECK(uv.y == Approx(0.5));
}

TEST_CASE("an image on a shape without a POV-Ray mapping is an error naming the shape",
          "[povray][image]") {
  std::string messages;
  PovExport e = exportImageScene(R"XML(<cylinder material="grid"/>)XML", "1 1", messages);
  CHECK_FALSE(e.ok());
  CHECK(messages ==
        "<cylinder> with the image texture of material 'grid': POV-Ray has no "
        "mapping equal to Lucent's (u,v) for it (plane, disc, box, sphere and "
        "meshes with uvs can be exported)\n");
}

TEST_CASE(
    "an image entry of a pigment map or a pigment list is an image_map body placed by its "
    "own transforms",
    "[povray][image][pigment-map]") {
  auto exported = [](const std::string& body, std::string& messages) {
    ParseResult parsed =
        parseSceneString("<scene version=\"1\"><camera position=\"0 1 5\"/>" + body + "</scene>",
                         std::string(lucentSourceDir()) + "/examples/image-test.xml");
    for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
    REQUIRE(parsed.scene);
    PovExport e = exportPov(*parsed.scene);
    for (const PovIssue& i : e.issues) messages += i.message + "\n";
    return e;
  };
  std::string messages;
  PovExport e = exported(R"XML(<sphere><material diffuse="1"><pattern type="gradient"
    axis="1 0 0"><pigment-map><entry at="0"><image src="textures/uvgrid.png"
    projection="spherical" once="true" interpolate="bicubic" transmit="0.25"
    transform="scale(2)"/></entry><entry at="1" color="1 0 0"/></pigment-map></pattern>
    </material></sphere>)XML",
                         messages);
  INFO(messages << e.text);
  REQUIRE(e.ok());
  const std::string path = std::string(lucentSourceDir()) + "/examples/textures/uvgrid.png";
  CHECK(has(e, "[0\n      image_map { png \"" + path +
                   "\" gamma srgb map_type 1 once interpolate 3 transmit all 0.25 }\n"
                   "      matrix <2, 0, 0,  0, 2, 0,  0, 0, 2,  0, 0, 0>\n      ]"));
  // POV-Ray cannot tint an image map: a coloured diffuse around one is an error.
  std::string tinted;
  PovExport box = exported(R"XML(<box><material diffuse="0.5 1 1"><checker><pigment-list>
    <entry><image src="textures/uvgrid.png" projection="planar"/></entry><entry color="0"/>
    </pigment-list></checker></material></box>)XML",
                           tinted);
  CHECK_FALSE(box.ok());
  CHECK(tinted.find("an image map inside a map or a list of pigments of a material with a "
                    "coloured diffuse, which POV-Ray cannot tint") != std::string::npos);
}

TEST_CASE("an image's palette entries are written after filter all as filter N, F",
          "[povray][image][palette]") {
  // gallery/textures/emblem.png: a palette image of 16 entries.
  ParseResult parsed = parseSceneString(
      R"XML(<scene version="1"><camera position="0 1 5"/><box><material diffuse="1">
      <image src="gallery/textures/emblem.png" projection="planar" filter="0.2">
      <palette index="0" transmit="1"/><palette index="9" filter="0.5" transmit="0.25"/>
      </image></material></box></scene>)XML",
      std::string(lucentSourceDir()) + "/examples/image-test.xml");
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  PovExport e = exportPov(*parsed.scene);
  INFO(e.text);
  REQUIRE(e.ok());
  const std::string path = std::string(lucentSourceDir()) + "/examples/gallery/textures/emblem.png";
  CHECK(has(e, "image_map { png \"" + path +
                   "\" gamma srgb interpolate 2 filter all 0.2 transmit 0, 1 filter 9, 0.5 "
                   "transmit 9, 0.25 }"));
}
