// The scene reader's image_map: map_type, once, interpolate, filter all and transmit all read
// into a projected <image>, placed by the pigment's transforms; and what stays refused.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

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
  CHECK(anyContains(
      errorsOf(
          R"(sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" use_index } } })"),
      "'use_index' is not supported by Lucent"));
  CHECK(anyContains(
      errorsOf(
          R"(sphere { 0, 1 pigment { image_map { png "scenes/image_maps.png" filter 2, 0.5 } } })"),
      "a palette entry's own filter"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { gradient y pigment_map {
  [0 image_map { png "scenes/image_maps.png" }] [1 rgb 1] } } })"),
                    "'image_map' inside a map or a list of pigments is not supported"));
  CHECK(anyContains(
      errorsOf(
          R"(sky_sphere { pigment { image_map { png "scenes/image_maps.png" map_type 1 } } })"),
      "'image_map' in a sky_sphere is not supported by Lucent"));
  CHECK(anyContains(errorsOf(R"(sphere { 0, 1 pigment { image_map { gif "x.gif" } } })"),
                    "image maps from 'gif' files are not supported by Lucent"));
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
  CHECK(anyContains(
      errorsOf(R"(sphere { 0, 1 normal { bump_map { png "scenes/image_maps.png" use_index } } })"),
      "'use_index' is not supported by Lucent"));
}
