// The scene reader's image_map: map_type, once, interpolate, filter all and transmit all, a
// palette entry's own filter and transmit read into a projected <image>, placed by the pigment's
// transforms; and what stays refused.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "images/image_values_file.h"
#include "scenegraph/image_pattern.h"
#include "scenegraph/map_blend.h"
#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

const ImageTexture& imageOf(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const Node& n = *scene.root->children[i];
  REQUIRE(n.material);
  return std::get<ImageTexture>(scene.materials.at(*n.material).texture);
}

bool anyContains(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("scene reader image_map: projection, once, interpolation and filter and transmit all",
          "[sdl][scene][texture][image-map]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" } } }
sphere { 0, 1 pigment { image_map { "scenes/image_maps.png" map_type 1 interpolate 4
  once filter all 0.25 transmit all 0.5 } scale 2 } }
sphere { 0, 1 pigment { image_map { png "scenes/image_maps" map_type 2 interpolate 3 } } }
sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" map_type 5 interpolate 2 } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const ImageTexture& planar = imageOf(s, 0);
  CHECK(planar.projection == ImageProjection::planar);
  CHECK(planar.interpolation == ImageInterpolation::none);  // POV-Ray's default
  CHECK_FALSE(planar.once);
  CHECK(planar.path.find("image_maps.png") != std::string::npos);

  const ImageTexture& spherical = imageOf(s, 1);
  CHECK(spherical.projection == ImageProjection::spherical);
  CHECK(spherical.interpolation == ImageInterpolation::normalized);
  CHECK(spherical.once);
  CHECK(spherical.all.filter == 0.25f);
  CHECK(spherical.all.transmit == 0.5f);
  // scale 2 in POV-Ray's space (and Lucent's z negation).
  CHECK(spherical.placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(spherical.placement.patternFromObject[2][2] == Approx(-0.5));

  // A name without an extension is a png.
  CHECK(imageOf(s, 2).projection == ImageProjection::cylindrical);
  CHECK(imageOf(s, 2).interpolation == ImageInterpolation::bicubic);
  CHECK(imageOf(s, 3).projection == ImageProjection::torus);
  CHECK(imageOf(s, 3).interpolation == ImageInterpolation::bilinear);
}

TEST_CASE("scene reader image_map: what POV-Ray refuses and what Lucent does not read",
          "[sdl][scene][texture][image-map]") {
  CHECK(anyContains(
      errorsOf(
          R"(sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" map_type 3 } } })"),
      "map_type 3 is not one POV-Ray 3.7 projects an image by"));
  CHECK(anyContains(
      errorsOf(
          R"(sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" interpolate 1 } } })"),
      "interpolate 1 is not one POV-Ray takes"));
  // POV-Ray 3.7's image_map reads neither use_index nor use_color: both are accepted.
  CHECK(readScene(R"(sphere { 0, 1 pigment { image_map { png "scenes/image_pattern_palette.png"
  use_index } } })")
            ->load.scene != nullptr);
  CHECK(anyContains(
      errorsOf(
          R"(sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" filter 2, 0.5 } } })"),
      "Keyword 'filter' cannot be used with non color-mapped image."));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { pigment_pattern {
  gradient y pigment_map { [0 image_map { png "scenes/image_maps.png" }] [1 rgb 1] } } } })"),
                    "'image_map' in a pigment_pattern is not supported"));
  CHECK(anyContains(errorsOf(R"(sky_sphere { pigment { gradient y pigment_map {
  [0 image_map { png "scenes/image_maps.png" }] [1 rgb 1] } } })"),
                    "'image_map' in a sky_sphere is not supported by Lucent"));
  CHECK(anyContains(
      errorsOf(
          R"(sky_sphere { pigment { image_map { png "scenes/image_maps.png" map_type 1 } } })"),
      "'image_map' in a sky_sphere is not supported by Lucent"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { iff "x.iff" } } })"),
                    "image maps from 'iff' files are not supported by Lucent"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { png "missing.png" } } })"),
                    "missing.png"));
}

TEST_CASE("scene reader bump_map: projected as an image map, placed by the normal's transforms",
          "[sdl][scene][texture][image-map][bump]") {
  auto r = readScene(R"(
sphere { 0, 1 normal { bump_map { png "scenes/image_maps.png" map_type 2 once interpolate 3
  bump_size 2 } scale 4 } }
sphere { 0, 1 normal { bump_map { png "scenes/image_maps.png" } bump_size -1.5 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& a = s.materials.at(*s.root->children[0]->material);
  REQUIRE(a.bumpMap);
  CHECK_FALSE(a.normal);
  CHECK(a.bumpMap->projection == ImageProjection::cylindrical);
  CHECK(a.bumpMap->once);
  CHECK(a.bumpMap->interpolation == ImageInterpolation::bicubic);
  CHECK(a.bumpMap->depth == 2.0);
  CHECK(a.bumpMap->keepFacingAway);  // POV-Ray's rule
  CHECK(a.bumpMap->placement.patternFromObject[0][0] == Approx(0.25));
  const Material& b = s.materials.at(*s.root->children[1]->material);
  REQUIRE(b.bumpMap);
  CHECK(b.bumpMap->projection == ImageProjection::planar);
  CHECK(b.bumpMap->interpolation == ImageInterpolation::none);
  CHECK(b.bumpMap->depth == -1.5);  // the normal's bump_size after the block
  // use_index: a palette image's indices are the heights; an image without a palette has
  // none, and reads its grey levels as with use_color (the last of the two counts).
  auto palette = readScene(R"(
sphere { 0, 1 normal { bump_map { png "scenes/image_pattern_palette.png" use_index } } }
sphere { 0, 1 normal { bump_map { png "scenes/image_maps.png" use_index } } }
sphere { 0, 1 normal { bump_map { png "scenes/image_pattern_palette.png" use_index use_color } } }
)");
  REQUIRE(palette->load.scene);
  const Scene& p = *palette->load.scene;
  const BumpMapSpec& indexed = *p.materials.at(*p.root->children[0]->material).bumpMap;
  CHECK(indexed.useIndex);
  REQUIRE(indexed.indices);
  CHECK_FALSE(indexed.indices->indices.empty());
  const BumpMapSpec& plain = *p.materials.at(*p.root->children[1]->material).bumpMap;
  CHECK(plain.useIndex);
  CHECK(!plain.indices);
  CHECK_FALSE(p.materials.at(*p.root->children[2]->material).bumpMap->useIndex);
}

TEST_CASE("scene reader material_map: its image read by index, its textures numbered in order",
          "[sdl][scene][texture][material-map]") {
  auto r = readScene(R"(
sphere { 0, 1 texture { material_map { png "scenes/mm_palette.png" map_type 1 once interpolate 2
  texture { pigment { rgb 1 } } texture { pigment { rgb <1, 0, 0> } finish { ambient 1 } }
  texture { pigment { checker } } } scale 2 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = s.materials.at(*s.root->children[0]->material);
  const ImagePattern* image = mapIndexImage(m);
  REQUIRE(image);
  CHECK(image->projection == ImageProjection::spherical);
  CHECK(image->once);
  CHECK(image->interpolation == ImageInterpolation::bilinear);
  REQUIRE(image->values);
  CHECK(image->values->indices.size() == 24);
  REQUIRE(m.mapEntries.size() == 3);
  CHECK(m.mapEntries[0].at == 0.0);
  CHECK(m.mapEntries[2].at == 2.0);
  // scale 2 (after the block) moves the map: its pattern space is the object's halved.
  const auto& spec = std::get<PatternTexture>(m.mapPattern).pattern;
  CHECK(spec.placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 texture { material_map { png
  "scenes/mm_palette.png" } } })"),
                    "a material_map needs at least one texture"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 texture { material_map { png
  "scenes/mm_palette.png" texture { pigment { rgb 1 } } once } } })"),
                    "a texture or '}' expected after a material_map's textures"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 texture { material_map { png
  "scenes/mm_palette.png" map_type 3 texture { pigment { rgb 1 } } } } })"),
                    "map_type 3 is not one POV-Ray 3.7 projects an image by"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 texture { material_map { png
  "scenes/mm_palette.png" repeat <2, 2> texture { pigment { rgb 1 } } } } })"),
                    "'repeat' in a material map is not supported by Lucent"));
}

namespace {

const PatternSpec& patternOf(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const Node& n = *scene.root->children[i];
  REQUIRE(n.material);
  return std::get<PatternTexture>(scene.materials.at(*n.material).texture).pattern;
}

}  // namespace

TEST_CASE(
    "scene reader image_pattern: its file read with map_type, once, interpolate and use_alpha, "
    "in pigments and normals",
    "[sdl][scene][texture][image-pattern]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { image_pattern { png "scenes/image_pattern_palette.png" } } }
sphere { 0, 1 pigment { image_pattern { "scenes/image_pattern_rgba8.png" map_type 1 once
  interpolate 3 use_alpha } color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } scale 2 } }
sphere { 0, 1 normal { image_pattern { png "scenes/image_pattern_grey8.png" map_type 5 use_alpha
  use_index } 0.5 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternSpec& plain = patternOf(s, 0);
  CHECK(plain.type == PatternType::image);
  CHECK(plain.frequency == 0.0);  // POV-Ray's image_pattern is unwrapped
  REQUIRE(plain.image);
  CHECK(plain.image->projection == ImageProjection::planar);
  CHECK(plain.image->interpolation == ImageInterpolation::none);
  CHECK_FALSE(plain.image->once);
  CHECK_FALSE(plain.image->useAlpha);
  REQUIRE(plain.image->values);
  CHECK(plain.image->values->width == 5);
  CHECK(plain.image->values->indices.size() == 20);  // a palette image

  const PatternSpec& alpha = patternOf(s, 1);
  REQUIRE(alpha.image);
  CHECK(alpha.image->projection == ImageProjection::spherical);
  CHECK(alpha.image->once);
  CHECK(alpha.image->interpolation == ImageInterpolation::bicubic);
  CHECK(alpha.image->useAlpha);
  CHECK(alpha.placement.patternFromObject[0][0] == Approx(0.5));

  const Node& n = *s.root->children[2];
  const NormalSpec& normal = *s.materials.at(*n.material).normal;
  CHECK(normal.pattern.type == PatternType::image);
  CHECK(normal.depth == 0.5);
  REQUIRE(normal.pattern.image);
  CHECK(normal.pattern.image->projection == ImageProjection::torus);
  CHECK_FALSE(normal.pattern.image->useAlpha);  // use_index after use_alpha: the grey again
}

TEST_CASE(
    "scene reader image_pattern: bad modifiers and unreadable files are errors at their place",
    "[sdl][scene][texture][image-pattern]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sphere { 0, 1 pigment { image_pattern { png \"scenes/image_pattern_grey8.png\" gamma_x } } "
       "}",
       "test.pov:1:78: error: 'gamma_x' is not an image_pattern modifier"},
      {"sphere { 0, 1 pigment { image_pattern { png \"scenes/image_pattern_grey8.png\" map_type 3 "
       "} } "
       "}",
       "test.pov:1:78: error: map_type 3 is not one POV-Ray 3.7 projects an image by"},
      {"sphere { 0, 1 pigment { image_pattern { png \"scenes/image_pattern_grey8.png\" repeat <1, "
       "1> } "
       "} }",
       "test.pov:1:78: error: 'repeat' in an image pattern is not supported by Lucent"},
      {"sphere { 0, 1 pigment { image_pattern { png \"scenes/none.png\" } } }",
       "test.pov:1:45: error:"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = errorsOf(text);
    REQUIRE(errors.size() >= 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}

TEST_CASE("scene reader image_map: an entry of a pigment map or of a block pattern's list",
          "[sdl][scene][texture][image-map][pigment-map]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { gradient y pigment_map {
  [0.2 image_map { png "scenes/image_maps.png" map_type 1 once interpolate 2 transmit all 0.5 }
       scale 2]
  [0.8 rgb 1] } } }
sphere { 0, 1 pigment { checker pigment { image_map { png "scenes/image_maps.png" } }
  pigment { rgb <1, 0, 0> } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.size() == 2);
  const Material& mapped = s.materials.at(*s.root->children[0]->material);
  const auto& pattern = std::get<PatternTexture>(mapped.texture);
  REQUIRE(pattern.pigments.size() == 2);
  const auto& image = std::get<ImageTexture>(pattern.pigments[0].texture);
  CHECK(image.projection == ImageProjection::spherical);
  CHECK(image.once);
  CHECK(image.interpolation == ImageInterpolation::bilinear);
  CHECK(image.all.transmit == 0.5f);
  // Its own scale 2, from the map's space (POV-Ray's z negated on neither side: the entry's
  // placement is taken from the map's pattern space).
  CHECK(image.placement.patternFromObject[0][0] == Approx(0.5));
  const Material& listed = s.materials.at(*s.root->children[1]->material);
  const auto& checker = std::get<CheckerTexture>(listed.texture);
  REQUIRE(checker.pigments.size() == 2);
  CHECK(std::get<ImageTexture>(checker.pigments[0].texture).projection == ImageProjection::planar);
}

TEST_CASE("scene reader image_map: a palette entry's own filter and transmit, in POV-Ray's order",
          "[sdl][scene][texture][image-map][palette]") {
  // mm_palette.png: 16 entries. `all` sets every entry's value, so an entry's own one given
  // before it is gone; one given after it stays. The index is rounded as POV-Ray rounds it.
  auto r = readScene(R"(
sphere { 0, 1 pigment { image_map { png "scenes/mm_palette.png"
  filter 3, 0.8 transmit 5, 0.6 filter 6.995, 0.5 transmit 7, 0.3 } } }
sphere { 0, 1 pigment { image_map { png "scenes/mm_palette.png"
  filter 3, 0.8 transmit 3, 0.1 filter all 0.2 transmit 4, 1 } } }
)");
  REQUIRE(r->load.scene);
  const ImageTexture& first = imageOf(*r->load.scene, 0);
  REQUIRE(first.palette.size() == 3);
  CHECK(first.palette[0] == PaletteEntryFT{3, 0.8f, std::nullopt});
  CHECK(first.palette[1] == PaletteEntryFT{5, std::nullopt, 0.6f});
  CHECK(first.palette[2] == PaletteEntryFT{7, 0.5f, 0.3f});
  REQUIRE(first.paletteIndices);
  CHECK(first.paletteIndices->paletteSize == 16);
  CHECK(first.paletteFT(3) == FilterTransmit{0.8f, 0.0f});
  CHECK(first.paletteFT(7) == FilterTransmit{0.5f, 0.3f});
  CHECK(first.paletteFT(0) == FilterTransmit{0.0f, 0.0f});

  const ImageTexture& second = imageOf(*r->load.scene, 1);
  CHECK(second.all.filter == 0.2f);
  CHECK(second.paletteFT(3) == FilterTransmit{0.2f, 0.1f});
  CHECK(second.paletteFT(4) == FilterTransmit{0.2f, 1.0f});
  CHECK(second.paletteFT(9) == FilterTransmit{0.2f, 0.0f});

  // POV-Ray's errors: an index past the palette, an image without one.
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { png "scenes/mm_palette.png"
  transmit 16, 0.5 } } })"),
                    "TRANSMIT color register value out of range"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { png "scenes/mm_palette.png"
  filter -2, 0.5 } } })"),
                    "FILTER color register value out of range"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { png "scenes/mm_rgb.png"
  transmit 1, 0.5 } } })"),
                    "Keyword 'transmit' cannot be used with non color-mapped image."));
}

TEST_CASE("POV-Ray image_map: the image's alpha is each pixel's transmit",
          "[sdl][texture][image-map][alpha]") {
  const auto imageOf = [](const std::string& modifiers, const std::string& file) {
    auto r = readScene("plane { z, 0 pigment { image_map { png \"scenes/" + file + "\" " +
                       modifiers + " } } }");
    REQUIRE(r->load.scene);
    return std::get<ImageTexture>(sdltest::materialOf(*r->load.scene, 0).texture);
  };
  const ImageTexture rgba = imageOf("", "image_pattern_rgba8.png");
  CHECK(rgba.useAlpha);
  REQUIRE(rgba.alphaTransmit);
  CHECK(rgba.alphaTransmit->at(0, 0) == 1.0f - 241.0f / 255.0f);
  // transmit all adds to an RGBA image's alpha, but replaces a palette image's.
  CHECK(imageOf("transmit all 0.25", "image_pattern_rgba8.png").alphaTransmit);
  const ImageTexture palette = imageOf("", "alpha_palette.png");
  REQUIRE(palette.alphaTransmit);
  CHECK(palette.alphaTransmit->at(2, 0) == 1.0f);
  // On the palette image, transmit all is every entry's own transmit (in place of its
  // alpha), but an entry's own value written after it.
  const ImageTexture replaced = imageOf("transmit all 0.3 transmit 2, 0.75", "alpha_palette.png");
  CHECK(replaced.useAlpha);
  CHECK(replaced.alphaTransmit);
  CHECK(replaced.all.transmit == 0.0f);
  REQUIRE(replaced.palette.size() == 4);
  CHECK(replaced.paletteFT(0).transmit == 0.3f);
  CHECK(replaced.paletteFT(2).transmit == 0.75f);
  CHECK(replaced.paletteFT(3).transmit == 0.3f);
  // An opaque image reads no grid.
  CHECK(!imageOf("", "image_maps.png").alphaTransmit);
}
