// <material-map> whose pattern is an image-pattern read by index (POV-Ray's material_map):
// the reader, the scene writer's round trip, export-pov's material_map block and the
// messages for what it cannot take. The images are tests/data/sdl/scenes/mm_*.png.
#include "../support/paths.h"
#include "../support/scene_text.h"

#include "images/image_values_file.h"
#include "lang/scene_writer.h"
#include "povray/pov_export.h"
#include "scenegraph/image_pattern.h"
#include "scenegraph/map_blend.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::string folder() { return std::string(lucentSourceDir()) + "/tests/data/sdl/scenes"; }
std::string sceneName() { return folder() + "/index-maps.xml"; }

const char* const kIndexMaps = R"XML(
<material id="red" ambient="1 0 0"/>
<material id="by-index">
  <material-map>
    <pattern type="image-pattern" src="mm_palette.png" index="true" once="true"
      interpolate="bilinear" projection="cylindrical" transform="scale(2)"/>
    <entry material="red"/>
    <entry><material reflective="1"/></entry>
    <entry><material><material-map><checker/>
      <entry at="0" material="red"/><entry at="1"><material/></entry></material-map></material></entry>
  </material-map>
</material>
<material id="bumped" diffuse="1">
  <bump-map src="mm_palette.png" depth="0.02" projection="planar" use-index="true"/>
</material>
<material id="rgb-bumped" diffuse="1">
  <bump-map src="mm_rgb.png" depth="0.02" projection="planar" use-index="true"/>
</material>
<sphere material="by-index"/><sphere center="3 0 0" material="bumped"/>
<sphere center="6 0 0" material="rgb-bumped"/>)XML";

WriteOptions beside() {
  WriteOptions o;
  o.folder = folder();
  return o;
}

}  // namespace

TEST_CASE("material-map by index: the image read by index and the entries numbered in order",
          "[lang][material][material-map][image-pattern]") {
  auto s = parseClean(kIndexMaps, sceneName());
  const Material& m = materialNamed(*s, "by-index");
  REQUIRE(m.mapped());
  const ImagePattern* image = mapIndexImage(m);
  REQUIRE(image);
  CHECK(image->byIndex);
  CHECK(image->once);
  CHECK(image->interpolation == ImageInterpolation::bilinear);
  CHECK(image->projection == ImageProjection::cylindrical);
  REQUIRE(image->values);
  CHECK(image->values->width == 6);
  CHECK(image->values->indices.size() == 24);  // a palette image keeps its indices
  REQUIRE(m.mapEntries.size() == 3);
  for (size_t k = 0; k < 3; ++k) CHECK(m.mapEntries[k].at == double(k));
  CHECK(m.mapEntries[0].material.ambient == Color(1, 0, 0));
  CHECK(m.mapEntries[2].material.mapped());
  CHECK(!mapIndexImage(m.mapEntries[2].material));
  // use-index keeps a palette image's indices; an image without a palette has none.
  const BumpMapSpec& bump = *materialNamed(*s, "bumped").bumpMap;
  CHECK(bump.useIndex);
  REQUIRE(bump.indices);
  CHECK(bump.indices->indices.size() == 24);
  CHECK_FALSE(bump.plainUV());
  const BumpMapSpec& rgb = *materialNamed(*s, "rgb-bumped").bumpMap;
  CHECK(rgb.useIndex);
  CHECK(!rgb.indices);
}

TEST_CASE("material-map by index: the scene writer writes it and it reads back to the same text",
          "[lang][scene-writer][material-map][image-pattern]") {
  const std::string first = writeSceneXml(*parseClean(kIndexMaps, sceneName()), beside());
  INFO(first);
  CHECK(first.find("src=\"mm_palette.png\" projection=\"cylindrical\" once=\"true\" "
                   "interpolate=\"bilinear\" index=\"true\"") != std::string::npos);
  CHECK(first.find("<entry>") != std::string::npos);           // numbered by their order
  CHECK(first.find("<entry at=\"1\">") != std::string::npos);  // the inner checker map's
  CHECK(first.find("use-index=\"true\"") != std::string::npos);
  auto reread = parseSceneString(first, sceneName());
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, beside())) == withoutComments(first));
}

TEST_CASE("material-map by index: export-pov writes material_map with its textures in order",
          "[povray][materials][material-map][image-pattern]") {
  ParseResult parsed = parseSceneString(
      R"XML(<scene version="1"><camera position="0 0 5"/>
<material id="a" ambient="1 0 0"/>
<box><material><material-map>
  <pattern type="image-pattern" src="mm_rgb.png" index="true" once="true" interpolate="normalized"
    transform="translate(0.5 0 0)"/>
  <entry material="a"/>
  <entry><material ambient="0 0 1"><pattern type="bozo" transform="scale(0.5) translate(0.5 0 0)"/></material></entry>
</material-map></material></box>
<sphere><material diffuse="1"><bump-map src="mm_palette.png" projection="planar" use-index="true"/></material></sphere>
</scene>)XML",
      sceneName());
  for (const Diagnostic& d : parsed.diagnostics.all()) UNSCOPED_INFO(d.str());
  REQUIRE(parsed.scene);
  const PovExport e = exportPov(*parsed.scene);
  INFO(e.text);
  REQUIRE(e.ok());
  const std::string path = folder() + "/mm_rgb.png";
  CHECK(e.text.find("  material_map {\n    png \"" + path +
                    "\" once interpolate 4\n    texture {\n"
                    "      pigment { rgbft <1, 1, 1, 0, 0> }") != std::string::npos);
  // The entry's bozo in the map's space: its scale alone; the map keeps its translate.
  CHECK(e.text.find("        matrix <0.5, 0, 0,  0, 0.5, 0,  0, 0, 0.5,  0, 0, 0>") !=
        std::string::npos);
  CHECK(e.text.find("  }\n  matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0.5, 0, 0>") !=
        std::string::npos);
  CHECK(e.text.find("use_index }") != std::string::npos);
}

TEST_CASE("material-map by index: index elsewhere, values, at and weight are errors",
          "[lang][material][material-map][image-pattern]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><pattern type=\"image-pattern\" src=\"mm_palette.png\" "
      "index=\"true\"/></material>"
      "\n<material id=\"b\"><material-map><pattern type=\"image-pattern\" src=\"mm_palette.png\" "
      "index=\"true\"/><entry at=\"0\"><material/></entry></material-map></material>"
      "\n<material id=\"c\"><material-map><pattern type=\"image-pattern\" src=\"mm_palette.png\" "
      "index=\"true\" use-alpha=\"true\"/><entry><material/></entry></material-map></material>"
      "\n<material id=\"d\"><material-map><pattern type=\"bozo\" index=\"true\"/>"
      "<entry at=\"0\"><material/></entry></material-map></material>"
      "\n<material id=\"e\"><material-map><pattern type=\"image-pattern\" src=\"mm_palette.png\"/>"
      "<entry><material/></entry></material-map></material>",
      sceneName());
  const std::string text = messages(r);
  INFO(text);
  CHECK(text.find("index-maps.xml:2:") != std::string::npos);
  CHECK(text.find("only the image-pattern that is a <material-map>'s pattern reads its image by "
                  "index") != std::string::npos);
  CHECK(text.find("index-maps.xml:3:") != std::string::npos);
  CHECK(text.find("take no 'at' or 'weight'") != std::string::npos);
  CHECK(text.find("index-maps.xml:4:") != std::string::npos);
  CHECK(text.find("an image-pattern read by index takes no 'use-alpha'") != std::string::npos);
  CHECK(text.find("index-maps.xml:5:") != std::string::npos);
  CHECK(text.find("only type image-pattern takes 'index'") != std::string::npos);
  CHECK(text.find("index-maps.xml:6:") != std::string::npos);
  CHECK(text.find("<entry> needs the attribute 'at'") != std::string::npos);
}
