// The scene reader's normal maps, block patterns' lists of normals, slope maps and
// #default normals: read field by field (each entry placed by its own transforms from the
// map's pattern space, every normal starting from the #default one), and POV-Ray's errors.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

const NormalSpec& normalOf(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  const Node& n = *scene.root->children[i];
  REQUIRE(n.material);
  const Material& m = scene.materials.at(*n.material);
  REQUIRE(m.normal);
  return *m.normal;
}

}  // namespace

TEST_CASE("scene reader normal maps: entries, lists and slope maps, placed in the map's space",
          "[sdl][scene][texture][normal-map]") {
  auto r = readScene(R"(
sphere { 0, 1 normal { gradient x normal_map { [0.3 marble 0.9 turbulence 0.5]
  [0.7 gradient y scallop_wave scale 0.5] } scale 2 } }
sphere { 0, 1 normal { checker normal { bumps 0.8 scale 0.25 }, normal { wrinkles } scale 0.5 } }
sphere { 0, 1 normal { brick normal { granite } normal { bumps } brick_size <1, 0.4, 0.6> mortar 0.1 } }
sphere { 0, 1 normal { onion 0.8 slope_map { [0 <0, 1>] [0.5, <1, 1>] [0.5 1] [1 <0, -1>] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const NormalSpec& map = normalOf(s, 0);
  CHECK(map.pattern.type == PatternType::gradient);
  CHECK(map.pattern.placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(map.keepFacingAway);
  REQUIRE(map.map.size() == 2);
  CHECK(map.map[0].at == 0.3);
  CHECK(map.map[0].normal.pattern.type == PatternType::marble);
  CHECK(map.map[0].normal.depth == Approx(0.9));
  CHECK(map.map[0].normal.pattern.placement.turbulence == Vec3(0.5));
  CHECK(map.map[1].normal.pattern.wave == WaveShape::scallop);
  // The entry's own scale, from the map's space (not the map's scale 2 again).
  CHECK(map.map[1].normal.pattern.placement.patternFromObject[0][0] == Approx(2.0));
  // An entry takes global_settings' noise generator, as every pattern.
  CHECK(map.map[0].normal.pattern.noiseGenerator == 2);

  const NormalSpec& checker = normalOf(s, 1);
  CHECK(checker.block == NormalBlock::checker);
  REQUIRE(checker.map.size() == 2);
  CHECK(checker.map[0].normal.pattern.type == PatternType::bumps);
  CHECK(checker.map[0].normal.pattern.placement.patternFromObject[0][0] == Approx(4.0));
  CHECK(checker.map[1].at == 1.0);
  CHECK(checker.map[1].normal.pattern.type == PatternType::wrinkles);
  CHECK(checker.pattern.placement.patternFromObject[0][0] == Approx(2.0));

  const NormalSpec& brick = normalOf(s, 2);
  CHECK(brick.block == NormalBlock::brick);
  CHECK(brick.brick.size == Vec3(1, 0.4, 0.6));
  CHECK(brick.brick.mortar == Approx(0.1));

  const NormalSpec& slope = normalOf(s, 3);
  REQUIRE(slope.slopeMap.size() == 4);
  CHECK(slope.slopeMap[1].at == 0.5);
  CHECK(slope.slopeMap[1].slope == 1.0);
  CHECK(slope.slopeMap[2].height == 1.0);  // a float stands for both
  CHECK(slope.slopeMap[2].slope == 1.0);
  CHECK(slope.slopeMap[3].slope == -1.0);
}

TEST_CASE("scene reader normal maps: every normal starts from the #default normal",
          "[sdl][scene][texture][normal-map]") {
  auto r = readScene(R"(
#default { normal { bump_size 1.5 } }
sphere { 0, 1 normal { gradient x normal_map { [0.3 marble] [0.7 bozo 0.4] } } }
#default { normal { onion 0.8 scale 0.4 } }
sphere { 0, 1 normal { slope_map { [0 <0, 1>] [1 <1, 0>] } } }
sphere { 0, 1 pigment { rgb 1 } }
sphere { 0, 1 normal { checker normal { bumps } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const NormalSpec& map = normalOf(s, 0);
  REQUIRE(map.map.size() == 2);
  CHECK(map.map[0].normal.depth == 1.5);  // the default's bump_size
  CHECK(map.map[1].normal.depth == Approx(0.4));

  const NormalSpec& slope = normalOf(s, 1);
  CHECK(slope.pattern.type == PatternType::onion);
  CHECK(slope.depth == Approx(0.8));
  CHECK(slope.pattern.placement.patternFromObject[0][0] == Approx(2.5));
  CHECK(slope.slopeMap.size() == 2);

  // An object without a normal of its own takes the default texture's.
  CHECK(normalOf(s, 2).pattern.type == PatternType::onion);

  // A list shorter than the cells takes the #default normal for the rest, as POV-Ray.
  const NormalSpec& checker = normalOf(s, 3);
  REQUIRE(checker.map.size() == 2);
  CHECK(checker.map[0].normal.pattern.type == PatternType::bumps);
  CHECK(checker.map[1].normal.pattern.type == PatternType::onion);
}

TEST_CASE("scene reader normal maps: POV-Ray's errors and what Lucent refuses, at the keyword",
          "[sdl][scene][texture][normal-map][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 normal { gradient x normal_map { [0.6 bumps] [0.2 dents] } } }\n"
      "sphere { 0, 1 normal { checker normal { bumps } normal { dents } normal_map { [0 bumps] } } "
      "}\n"
      "sphere { 0, 1 pigment { gradient x slope_map { [0 <0, 1>] } } }\n"
      "sphere { 0, 1 normal { checker normal { bumps } } }\n"
      "sphere { 0, 1 normal { onion slope_map { [0.5 <0, 1>] [0.1 <1, 0>] } } }\n"
      "sphere { 0, 1 normal { bump_size 2 } }\n");
  REQUIRE(errors.size() == 6);
  CHECK(errors[0] == "test.pov:1:35: error: the normal map's entries must be in ascending order");
  CHECK(errors[1] ==
        "test.pov:2:66: error: 'normal_map' cannot be used with this normal type (as POV-Ray's "
        "parser says)");
  CHECK(errors[2] == "test.pov:3:36: error: 'slope_map' belongs in a normal, not a pigment");
  CHECK(errors[3] ==
        "test.pov:4:24: error: the list of normals needs 2 normals here (POV-Ray 3.7 fills a "
        "shorter list with the #default normal, and there is none)");
  CHECK(errors[4] == "test.pov:5:30: error: the slope map's entries must be in ascending order");
  CHECK(errors[5].rfind("test.pov:6:", 0) == 0);
  CHECK(errors[5].find("a normal without a pattern (POV-Ray: 'No normal type given')") !=
        std::string::npos);
}

TEST_CASE(
    "scene reader normal maps: a slope_map on a normal-only pattern is ignored, with a warning",
    "[sdl][scene][texture][normal-map]") {
  auto r = readScene("sphere { 0, 1 normal { bumps 0.5 slope_map { [0 <0, 1>] [1 <1, 0>] } } }\n");
  REQUIRE(r->load.scene);
  CHECK(normalOf(*r->load.scene, 0).slopeMap.empty());
  REQUIRE(r->out.warnings.size() == 1);
  CHECK(r->out.warnings[0] ==
        "test.pov:1:34: warning: the slope_map has no effect on bumps (POV-Ray bends by that "
        "pattern's own normal, not by a slope)");
}
