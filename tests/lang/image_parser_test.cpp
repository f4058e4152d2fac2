// <image>'s projections (projection, its placement, once, interpolate, filter and
// transmit): read field by field, written by the scene writer and read back to the same
// text, and their errors.
#include "../support/paths.h"
#include "../support/scene_text.h"

#include "images/image_values_file.h"
#include "lang/scene_writer.h"
#include "scenegraph/image_pattern.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// Parsed as a file of examples/, so that textures/uvgrid.png is found.
std::string sceneName() { return std::string(lucentSourceDir()) + "/examples/images.xml"; }

// Written as a file of examples/ too: its file references relative to that folder.
WriteOptions inExamples() {
  WriteOptions o;
  o.folder = std::string(lucentSourceDir()) + "/examples";
  return o;
}

const char* kImages = R"XML(
<material id="uv"><image src="textures/uvgrid.png" scale="2 1" once="true"/></material>
<material id="sphere"><image src="textures/uvgrid.png" projection="spherical"
  transform="rotate-y(30)" interpolate="normalized" transmit="0.25"/></material>
<material id="torus"><image src="textures/uvgrid.png" projection="torus" interpolate="none"
  filter="0.5" turbulence="0.1"/></material>
<material id="bump"><bump-map src="textures/uvgrid.png" depth="2" projection="cylindrical"
  once="true" interpolate="bicubic" keep-facing-away="true" transform="scale(2)"/></material>
<sphere material="uv"/><sphere material="sphere"/><sphere material="torus"/>
<sphere material="bump"/>)XML";

}  // namespace

TEST_CASE("image projections: each attribute is read", "[lang][texture][image-map]") {
  auto s = parseClean(kImages, sceneName());
  const auto& uv = std::get<ImageTexture>(materialNamed(*s, "uv").texture);
  CHECK(uv.projection == ImageProjection::uv);
  CHECK(uv.scale == Vec2(2.0, 1.0));
  CHECK(uv.once);
  CHECK(uv.interpolation == ImageInterpolation::bilinear);
  CHECK_FALSE(uv.plainUV());
  CHECK(textureSeeThrough(materialNamed(*s, "uv").texture));  // clear off the image

  const auto& sphere = std::get<ImageTexture>(materialNamed(*s, "sphere").texture);
  CHECK(sphere.projection == ImageProjection::spherical);
  CHECK(sphere.interpolation == ImageInterpolation::normalized);
  CHECK(sphere.all.transmit == 0.25f);
  CHECK_FALSE(sphere.once);
  // rotate-y(30) places the image: the pattern space is rotated back.
  CHECK(sphere.placement.patternFromObject[0][0] == Approx(std::cos(M_PI / 6)));

  const auto& torus = std::get<ImageTexture>(materialNamed(*s, "torus").texture);
  CHECK(torus.projection == ImageProjection::torus);
  CHECK(torus.interpolation == ImageInterpolation::none);
  CHECK(torus.all.filter == 0.5f);
  CHECK(torus.placement.turbulence == Vec3(0.1));

  const Material& bumpy = materialNamed(*s, "bump");
  REQUIRE(bumpy.bumpMap);
  CHECK(bumpy.bumpMap->projection == ImageProjection::cylindrical);
  CHECK(bumpy.bumpMap->once);
  CHECK(bumpy.bumpMap->interpolation == ImageInterpolation::bicubic);
  CHECK(bumpy.bumpMap->keepFacingAway);
  CHECK(bumpy.bumpMap->depth == 2.0);
  CHECK(bumpy.bumpMap->placement.patternFromObject[1][1] == Approx(0.5));
}

TEST_CASE("image projections: the scene writer writes them and they read back to the same text",
          "[lang][scene-writer][image-map]") {
  const std::string first = writeSceneXml(*parseClean(kImages, sceneName()), inExamples());
  CHECK(first.find("projection=\"spherical\"") != std::string::npos);
  CHECK(first.find("interpolate=\"none\"") != std::string::npos);
  CHECK(first.find("once=\"true\"") != std::string::npos);
  CHECK(first.find("projection=\"cylindrical\"") != std::string::npos);
  CHECK(first.find("keep-facing-away=\"true\"") != std::string::npos);
  auto reread = parseSceneString(first, sceneName());
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, inExamples())) == withoutComments(first));
}

TEST_CASE("image projections: placement without a projection, scale with one, bad names",
          "[lang][texture][image-map]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><image src=\"textures/uvgrid.png\" transform=\"scale(2)\"/></material>"
      "\n<material id=\"b\"><image src=\"textures/uvgrid.png\" projection=\"planar\" "
      "scale=\"2\"/></material>"
      "\n<material id=\"c\"><image src=\"textures/uvgrid.png\" projection=\"cubic\"/></material>"
      "\n<material id=\"d\"><image src=\"textures/uvgrid.png\" interpolate=\"2\"/></material>",
      sceneName());
  const std::string m = messages(r);
  INFO(m);
  CHECK(m.find("images.xml:2:62: error: <image> attribute 'transform': 'transform' places a "
               "projected <image> only: give a 'projection' (at the shape's (u,v) the shape places "
               "it)") != std::string::npos);
  CHECK(m.find("images.xml:3:78: error: <image> attribute 'scale': 'scale' is for an image at "
               "the shape's (u,v); a projected image is placed by 'transform'") !=
        std::string::npos);
  CHECK(m.find("images.xml:4:") != std::string::npos);
  CHECK(m.find("cubic") != std::string::npos);
  CHECK(m.find("images.xml:5:") != std::string::npos);
  CHECK(r.diagnostics.errorCount() == 4);
}

TEST_CASE(
    "image-pattern: its file and reading are written back and read again, as pattern and normal",
    "[lang][texture][image-pattern]") {
  const char* kImagePatterns = R"XML(
<material id="p"><pattern type="image-pattern" src="textures/uvgrid.png" projection="cylindrical"
  once="true" interpolate="bicubic" use-alpha="true" transform="scale(2)">
  <color-map><entry at="0" color="0 0 0"/><entry at="1" color="1 0.5 0"/></color-map>
</pattern></material>
<material id="n"><normal type="image-pattern" src="textures/uvgrid.png" depth="0.4"/></material>
<sphere material="p"/><sphere center="3 0 0" material="n"/>)XML";
  auto s = parseClean(kImagePatterns, sceneName());
  const auto& p = std::get<PatternTexture>(materialNamed(*s, "p").texture).pattern;
  CHECK(p.type == PatternType::image);
  CHECK(p.frequency == 0.0);
  REQUIRE(p.image);
  CHECK(p.image->projection == ImageProjection::cylindrical);
  CHECK(p.image->once);
  CHECK(p.image->interpolation == ImageInterpolation::bicubic);
  CHECK(p.image->useAlpha);
  REQUIRE(p.image->values);
  CHECK(p.image->values->width > 0);
  const NormalSpec& n = *materialNamed(*s, "n").normal;
  REQUIRE(n.pattern.image);
  CHECK(n.pattern.image->projection == ImageProjection::planar);
  CHECK(n.pattern.image->interpolation == ImageInterpolation::none);
  const std::string first = writeSceneXml(*s, inExamples());
  INFO(first);
  CHECK(first.find("<pattern type=\"image-pattern\" transform=\"matrix(2 ") != std::string::npos);
  CHECK(first.find("src=\"textures/uvgrid.png\" projection=\"cylindrical\" once=\"true\" "
                   "interpolate=\"bicubic\" use-alpha=\"true\"") != std::string::npos);
  CHECK(first.find("<normal type=\"image-pattern\" src=\"textures/uvgrid.png\" depth=\"0.4\"") !=
        std::string::npos);
  auto reread = parseSceneString(first, sceneName());
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, inExamples())) == withoutComments(first));
}

TEST_CASE("image palette entries: read, written back and read again, and their errors",
          "[lang][texture][image-map][palette]") {
  // gallery/textures/emblem.png: a 48 x 48 palette image of 16 entries.
  const char* kPalette = R"XML(
<material id="p"><image src="gallery/textures/emblem.png" projection="planar"
  filter="0.1" interpolate="none"><palette index="3" filter="0.8"/>
  <palette index="15" transmit="0.5" filter="0"/></image></material>
<sphere material="p"/>)XML";
  auto s = parseClean(kPalette, sceneName());
  const auto& p = std::get<ImageTexture>(materialNamed(*s, "p").texture);
  REQUIRE(p.palette.size() == 2);
  CHECK(p.palette[0] == PaletteEntryFT{3, 0.8f, std::nullopt});
  CHECK(p.palette[1] == PaletteEntryFT{15, 0.0f, 0.5f});
  REQUIRE(p.paletteIndices);
  CHECK(p.paletteIndices->paletteSize == 16);
  CHECK(p.paletteFT(15) == FilterTransmit{0.0f, 0.5f});
  CHECK(p.paletteFT(2) == FilterTransmit{0.1f, 0.0f});
  CHECK(textureSeeThrough(materialNamed(*s, "p").texture));

  const std::string first = writeSceneXml(*s, inExamples());
  INFO(first);
  // Filter and transmit are single precision, written exactly (as an image's own).
  CHECK(first.find("<palette index=\"3\" filter=\"0.800000011920929\"/>") != std::string::npos);
  CHECK(first.find("<palette index=\"15\" filter=\"0\" transmit=\"0.5\"/>") != std::string::npos);
  auto reread = parseSceneString(first, sceneName());
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, inExamples())) == withoutComments(first));

  // An entry alone: its own value is what makes the image see-through.
  auto opaque = parseClean(R"XML(
<material id="q"><image src="gallery/textures/emblem.png"><palette index="0"
  transmit="0"/></image></material><sphere material="q"/>)XML",
                           sceneName());
  CHECK_FALSE(textureSeeThrough(materialNamed(*opaque, "q").texture));

  ParseResult r = parseBody(
      "\n<material id=\"a\"><image src=\"textures/uvgrid.png\"><palette index=\"1\" "
      "filter=\"0.5\"/></image></material>"
      "\n<material id=\"b\"><image src=\"gallery/textures/emblem.png\"><palette "
      "index=\"16\" filter=\"0.5\"/></image></material>"
      "\n<material id=\"c\"><image src=\"gallery/textures/emblem.png\"><palette "
      "index=\"2\"/></image></material>"
      "\n<material id=\"d\"><image src=\"gallery/textures/emblem.png\"><palette "
      "index=\"2\" filter=\"1\"/><palette index=\"2\" transmit=\"1\"/></image></material>",
      sceneName());
  const std::string m = messages(r);
  INFO(m);
  CHECK(m.find("images.xml:2:") != std::string::npos);
  CHECK(m.find("<palette> entries need a palette image") != std::string::npos);
  CHECK(m.find("images.xml:3:") != std::string::npos);
  CHECK(m.find("palette index 16 is past the image's palette of 16 entries (0 to 15)") !=
        std::string::npos);
  CHECK(m.find("images.xml:4:") != std::string::npos);
  CHECK(m.find("<palette> needs a 'filter' or a 'transmit'") != std::string::npos);
  CHECK(m.find("images.xml:5:") != std::string::npos);
  CHECK(m.find("palette entry 2 is given twice") != std::string::npos);
  CHECK(r.diagnostics.errorCount() == 4);
}

TEST_CASE("image use-alpha: the image's own transparency read, written back and read again",
          "[lang][texture][image-map][alpha]") {
  // Files of tests/data/sdl/scenes: a 5 x 4 RGBA PNG (its first pixel's alpha 241), a palette
  // PNG whose tRNS gives alphas 255, 128, 0 and 200, and an RGB PNG (no transparency).
  const std::string scene = std::string(lucentSourceDir()) + "/tests/data/sdl/scenes/t.xml";
  auto s = parseClean(R"XML(
<material id="rgba"><image src="image_pattern_rgba8.png" use-alpha="true"/></material>
<material id="palette"><image src="alpha_palette.png" use-alpha="true"/></material>
<material id="rgb"><image src="image_maps.png" use-alpha="true"/></material>
<material id="off"><image src="image_pattern_rgba8.png"/></material>
<sphere material="rgba"/><sphere material="palette"/><sphere material="rgb"/>
<sphere material="off"/>)XML",
                      scene);
  const auto& rgba = std::get<ImageTexture>(materialNamed(*s, "rgba").texture);
  REQUIRE(rgba.alphaTransmit);
  CHECK(rgba.alphaTransmit->width == 5);
  CHECK(rgba.alphaTransmit->at(0, 0) == 1.0f - 241.0f / 255.0f);
  CHECK(textureSeeThrough(materialNamed(*s, "rgba").texture));
  const auto& palette = std::get<ImageTexture>(materialNamed(*s, "palette").texture);
  REQUIRE(palette.alphaTransmit);
  CHECK(palette.alphaTransmit->at(0, 0) == 0.0f);                    // red, alpha 255
  CHECK(palette.alphaTransmit->at(1, 0) == 1.0f - 128.0f / 255.0f);  // green
  CHECK(palette.alphaTransmit->at(2, 0) == 1.0f);                    // blue, alpha 0
  // An opaque image needs no grid, and without use-alpha none is read.
  const auto& rgb = std::get<ImageTexture>(materialNamed(*s, "rgb").texture);
  CHECK(rgb.useAlpha);
  CHECK(!rgb.alphaTransmit);
  CHECK_FALSE(textureSeeThrough(materialNamed(*s, "rgb").texture));
  CHECK(!std::get<ImageTexture>(materialNamed(*s, "off").texture).alphaTransmit);

  WriteOptions o;
  o.folder = std::string(lucentSourceDir()) + "/tests/data/sdl/scenes";
  const std::string text = writeSceneXml(*s, o);
  INFO(text);
  size_t written = 0;
  for (size_t at = text.find("use-alpha=\"true\""); at != std::string::npos;
       at = text.find("use-alpha=\"true\"", at + 1))
    ++written;
  CHECK(written == 3);
  auto reread = parseSceneString(text, scene);
  REQUIRE(reread.scene);
  int withAlpha = 0;
  for (const Material& m : reread.scene->materials)
    if (const auto* image = std::get_if<ImageTexture>(&m.texture))
      withAlpha += image->alphaTransmit ? 1 : 0;
  CHECK(withAlpha == 2);  // the RGBA and the palette image
}
