// The scene reader's quilted, mandel, julia and magnet patterns, dents, ripples and waves
// as pigments, and spherical, cylindrical, boxed and cells: each keyword's arguments and modifiers
// with POV-Ray's defaults (parstxtr.cpp), field by field, as pigments and as normals; and the bad
// inputs, each one error at its place.
#include <catch2/catch.hpp>

#include "../support/scene_text.h"
#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;
using lucent::test::nodePigmentPattern;

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

TEST_CASE(
    "scene reader patterns: quilted's controls and frequency 0, dents, ripples and waves "
    "as pigments",
    "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { quilted } }
sphere { 0, 1 pigment { quilted control0 0.25 control1 0.75 frequency 2 } }
sphere { 0, 1 normal { quilted 0.6 control0 0 } }
sphere { 0, 1 pigment { dents } }
sphere { 0, 1 pigment { ripples frequency 3 phase 0.5 } }
sphere { 0, 1 pigment { waves } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternSpec& plain = nodePigmentPattern(s, 0);
  CHECK(plain.type == PatternType::quilted);
  CHECK(plain.frequency == 0.0);
  CHECK(plain.quilted.control0 == 1.0);
  CHECK(plain.quilted.control1 == 1.0);
  const PatternSpec& tuned = nodePigmentPattern(s, 1);
  CHECK(tuned.quilted.control0 == 0.25);
  CHECK(tuned.quilted.control1 == 0.75);
  CHECK(tuned.frequency == 2.0);
  const NormalSpec& n = normalOf(s, 2);
  CHECK(n.pattern.type == PatternType::quilted);
  CHECK(n.depth == 0.6);
  CHECK(n.pattern.quilted.control0 == 0.0);
  CHECK(n.pattern.frequency == 0.0);
  CHECK(nodePigmentPattern(s, 3).type == PatternType::dents);
  const PatternSpec& ripples = nodePigmentPattern(s, 4);
  CHECK(ripples.type == PatternType::ripples);
  CHECK(ripples.frequency == 3.0);
  CHECK(ripples.phase == 0.5);
  CHECK(nodePigmentPattern(s, 5).type == PatternType::waves);
}

TEST_CASE(
    "scene reader patterns: spherical, cylindrical, boxed and cells in pigments, normals, "
    "pigment maps and texture maps",
    "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { spherical color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } }
sphere { 0, 1 pigment { cylindrical frequency 2 sine_wave } }
sphere { 0, 1 normal { boxed 0.6 scale 2 } }
sphere { 0, 1 pigment { cells pigment_map { [0 rgb 1] [1 checker] } } }
sphere { 0, 1 texture { boxed texture_map { [0 pigment { rgb 1 }] [1 pigment { cells }] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK(nodePigmentPattern(s, 0).type == PatternType::spherical);
  const PatternSpec& cylindrical = nodePigmentPattern(s, 1);
  CHECK(cylindrical.type == PatternType::cylindrical);
  CHECK(cylindrical.frequency == 2.0);
  CHECK(cylindrical.waveShape() == WaveShape::sine);
  const NormalSpec& n = normalOf(s, 2);
  CHECK(n.pattern.type == PatternType::boxed);
  CHECK(n.depth == 0.6);
  const PatternSpec& cells = nodePigmentPattern(s, 3);
  CHECK(cells.type == PatternType::cells);
  const auto& t = std::get<PatternTexture>(s.materials.at(*s.root->children[3]->material).texture);
  CHECK(t.pigments.size() == 2);
  const Material& mapped = s.materials.at(*s.root->children[4]->material);
  REQUIRE(mapped.mapped());
  CHECK(std::get<PatternTexture>(mapped.mapPattern).pattern.type == PatternType::boxed);
  REQUIRE(mapped.mapEntries.size() == 2);
  CHECK(std::get<PatternTexture>(mapped.mapEntries[1].material.texture).pattern.type ==
        PatternType::cells);
}

TEST_CASE(
    "scene reader patterns: pigment_pattern holds its pigment, with POV-Ray's default map "
    "and its own transform",
    "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { pigment_pattern { bozo scale 2 } color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 normal { pigment_pattern { rgb <1, 0.5, 0> } 0.4 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternSpec& p = nodePigmentPattern(s, 0);
  CHECK(p.type == PatternType::pigment);
  REQUIRE(p.pigment);
  const auto& bozo = std::get<PatternTexture>(p.pigment->texture);
  CHECK(bozo.pattern.type == PatternType::bozo);
  CHECK(bozo.pattern.noiseGenerator == 2);  // global_settings' default reaches it
  CHECK(bozo.map.entries.size() == 6);      // POV-Ray's default map of bozo
  CHECK(bozo.pattern.placement.patternFromObject[0][0] == Approx(0.5));
  const NormalSpec& n = normalOf(s, 1);
  CHECK(n.pattern.type == PatternType::pigment);
  CHECK(n.depth == 0.4);
  REQUIRE(n.pattern.pigment);
  CHECK(std::holds_alternative<std::monostate>(n.pattern.pigment->texture));
  CHECK(n.pattern.pigment->color.rgb == Color(1, 0.5, 0));
}

TEST_CASE("scene reader patterns: mandel, julia and magnet with their arguments and colourings",
          "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { mandel 50 } }
sphere { 0, 1 pigment { mandel 20 exponent 5 exterior 7, 3 interior 6, 0.5 } }
sphere { 0, 1 pigment { julia <0.3, -0.44>, 30 exponent 3 interior 1, 2 } }
sphere { 0, 1 pigment { magnet 1 mandel 40 } }
sphere { 0, 1 pigment { magnet 2 julia <1.1, 0.3>, 25 exterior 6, 0.01 } }
sphere { 0, 1 normal { mandel 30, 0.4 interior 1, 1 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternSpec& mandel = nodePigmentPattern(s, 0);
  CHECK(mandel.type == PatternType::mandel);
  CHECK(mandel.fractal.iterations == 50);
  CHECK(mandel.fractal.power == 2);
  CHECK(mandel.fractal.exterior.type == 1);
  CHECK(mandel.fractal.exterior.factor == 1.0);
  CHECK(mandel.fractal.interior.type == 0);
  CHECK(mandel.fractal.interior.factor == 1.0);
  CHECK(mandel.frequency == 1.0);
  const PatternSpec& mandel5 = nodePigmentPattern(s, 1);
  CHECK(mandel5.fractal.power == 5);
  CHECK(mandel5.fractal.exterior.type == 7);
  CHECK(mandel5.fractal.exterior.factor == 3.0);
  CHECK(mandel5.fractal.interior.type == 6);
  CHECK(mandel5.fractal.interior.factor == 0.5);
  const PatternSpec& julia = nodePigmentPattern(s, 2);
  CHECK(julia.type == PatternType::julia);
  CHECK(julia.fractal.cReal == 0.3);
  CHECK(julia.fractal.cImaginary == -0.44);
  CHECK(julia.fractal.iterations == 30);
  CHECK(julia.fractal.power == 3);
  CHECK(julia.fractal.interior.type == 1);
  CHECK(julia.fractal.interior.factor == 2.0);
  const PatternSpec& magnet1 = nodePigmentPattern(s, 3);
  CHECK(magnet1.type == PatternType::magnet);
  CHECK(magnet1.fractal.magnetType == 1);
  CHECK_FALSE(magnet1.fractal.juliaForm);
  CHECK(magnet1.fractal.iterations == 40);
  const PatternSpec& magnet2 = nodePigmentPattern(s, 4);
  CHECK(magnet2.fractal.magnetType == 2);
  CHECK(magnet2.fractal.juliaForm);
  CHECK(magnet2.fractal.cReal == 1.1);
  CHECK(magnet2.fractal.cImaginary == 0.3);
  CHECK(magnet2.fractal.iterations == 25);
  CHECK(magnet2.fractal.exterior.type == 6);
  CHECK(magnet2.fractal.exterior.factor == 0.01);
  const NormalSpec& n = normalOf(s, 5);
  CHECK(n.pattern.type == PatternType::mandel);
  CHECK(n.pattern.fractal.iterations == 30);
  CHECK(n.depth == 0.4);
  CHECK(n.pattern.fractal.interior.type == 1);
}

TEST_CASE("scene reader patterns: a mandel exponent outside 2..33 is POV-Ray's warning and 2",
          "[sdl][scene][texture]") {
  auto r = readScene("sphere { 0, 1 pigment { mandel 10 exponent 40 } }\n");
  REQUIRE(r->load.scene);
  CHECK(nodePigmentPattern(*r->load.scene, 0).fractal.power == 2);
  bool warned = false;
  for (const std::string& w : r->out.warnings)
    warned |= w ==
              "test.pov:1:35: warning: the fractal exponent 40 is outside 2..33; POV-Ray "
              "uses 2";
  CHECK(warned);
}

TEST_CASE("scene reader patterns: bad fractal and quilted modifiers are errors at their keyword",
          "[sdl][scene][texture][errors]") {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 pigment { magnet 3 mandel 10 } }",
       "test.pov:1:25: error: magnet's type must be 1 or 2, got 3"},
      {"sphere { 0, 1 pigment { magnet 1 bozo 10 } }",
       "test.pov:1:34: error: 'mandel' or 'julia' expected after 'magnet 1', not"},
      {"sphere { 0, 1 pigment { mandel -5 } }",
       "test.pov:1:25: error: a fractal pattern's iterations must be from 0 to 100000000, got -5"},
      {"sphere { 0, 1 pigment { mandel 10 exterior 9, 1 } }",
       "test.pov:1:35: error: exterior types are 0 to 8, got 9"},
      {"sphere { 0, 1 pigment { julia <0, 0>, 10 interior 7, 1 } }",
       "test.pov:1:42: error: interior types are 0 to 6, got 7"},
      {"sphere { 0, 1 pigment { mandel 10 exterior 7, 0 } }",
       "test.pov:1:35: error: exterior type 7 needs a factor >= 1, got 0"},
      {"sphere { 0, 1 pigment { mandel 10 exterior 8, 0 } }",
       "test.pov:1:35: error: exterior type 8 needs a factor > 0, got 0"},
      {"sphere { 0, 1 pigment { bozo exterior 1, 1 } }",
       "test.pov:1:30: error: 'exterior' is for mandel, julia and magnet"},
      {"sphere { 0, 1 pigment { magnet 1 mandel 10 exponent 3 } }",
       "test.pov:1:44: error: 'exponent' is for mandel and julia"},
      {"sphere { 0, 1 pigment { bozo control0 0.5 } }",
       "test.pov:1:30: error: 'control0' is for quilted"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = errorsOf(text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}

TEST_CASE(
    "scene reader patterns: slope's vector and point in Lucent's space, its altitude in the "
    "pattern's, in pigments, normals and texture maps",
    "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { slope <0.5, 1, 2> } }
sphere { 0, 1 pigment { slope { -y*3, 0, 0.5 altitude <0, 1, 1>, 0.005, 0.4 } } }
sphere { 0, 1 pigment { slope { point_at <1, 2, 3> } } }
sphere { 0, 1 normal { slope { z 0.2, 0.7 } 0.3 } }
sphere { 0, 1 texture { slope x texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternSpec& simple = nodePigmentPattern(s, 0);
  CHECK(simple.type == PatternType::slope);
  CHECK(simple.slope.direction == Vec3(0.5, 1, -2));  // POV-Ray's z negated, as the normal's
  CHECK(simple.slope.altitude == Vec3(0.0));
  CHECK(simple.frequency == 1.0);
  const SlopeParams& full = nodePigmentPattern(s, 1).slope;
  CHECK(full.direction == Vec3(0, -3, 0));
  CHECK(full.low == 0.0);
  CHECK(full.high == 0.5);
  CHECK(full.altitude == Vec3(0, 1, 1));  // the pattern point is POV-Ray's: kept as written
  CHECK(full.altitudeLow == 0.005);
  CHECK(full.altitudeHigh == 0.4);
  const SlopeParams& at = nodePigmentPattern(s, 2).slope;
  CHECK(at.pointAt);
  CHECK(at.direction == Vec3(1, 2, -3));
  const NormalSpec& n = normalOf(s, 3);
  CHECK(n.pattern.type == PatternType::slope);
  CHECK(n.pattern.slope.direction == Vec3(0, 0, -1));
  CHECK(n.pattern.slope.low == 0.2);
  CHECK(n.pattern.slope.high == 0.7);
  CHECK(n.depth == 0.3);
  const Material& mapped = s.materials.at(*s.root->children[4]->material);
  REQUIRE(mapped.mapped());
  const PatternSpec& m = std::get<PatternTexture>(mapped.mapPattern).pattern;
  CHECK(m.type == PatternType::slope);
  CHECK(m.slope.direction == Vec3(1, 0, 0));
}

TEST_CASE("scene reader patterns: slope's POV-Ray errors at their keyword",
          "[sdl][scene][texture][errors]") {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 pigment { slope { point_at y altitude y } } }",
       "test.pov:1:44: error: 'altitude' cannot be used with 'point_at' in slope (as POV-Ray)"},
      {"sphere { 0, 1 pigment { slope { 0 altitude 0 } } }",
       "test.pov:1:25: error: slope: zero length for both slope and altitude (POV-Ray's error)"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = errorsOf(text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}

TEST_CASE("scene reader patterns: facets' size, coords and metric in a normal, amount unused",
          "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 normal { facets } }
sphere { 0, 1 normal { facets coords 0.4 } }
sphere { 0, 1 normal { facets 0.7 size 0.25 metric <1, 0, 0> scale 2 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const NormalSpec& plain = normalOf(s, 0);
  CHECK(plain.pattern.type == PatternType::facets);
  CHECK(plain.pattern.facets == FacetsParams{0.1, 0.0, 2.0});  // POV-Ray's defaults
  CHECK(normalOf(s, 1).pattern.facets == FacetsParams{0.1, 0.4, 2.0});
  const NormalSpec& full = normalOf(s, 2);
  CHECK(full.pattern.facets == FacetsParams{0.25, 0.0, 1.0});
  CHECK(full.pattern.crackle.metric == 2.0);  // facets' own metric, not crackle's
  CHECK(full.depth == 0.7);
}

TEST_CASE("scene reader patterns: facets' POV-Ray errors at their keyword",
          "[sdl][scene][texture][errors]") {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 normal { bumps coords 0.4 } }",
       "test.pov:1:30: error: 'coords' is for facets"},
      {"sphere { 0, 1 normal { bumps size 0.4 } }", "test.pov:1:30: error: 'size' is for facets"},
      {"sphere { 0, 1 pigment { facets } }",
       "test.pov:1:25: error: 'facets' is not supported by Lucent (as a colour pattern; "
       "Lucent's facets is a normal pattern)"},
      {"sphere { 0, 1 normal { facets normal_map { [0 bumps] } } }",
       "test.pov:1:31: error: 'normal_map' cannot be used with this normal type"},
  };
  for (const auto& [text, want] : cases) {
    INFO(text);
    const auto errors = errorsOf(text);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind(want, 0) == 0);
  }
}
