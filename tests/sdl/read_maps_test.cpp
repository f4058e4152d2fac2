// The scene reader's maps of pigments (pigment_map, declared ones too), block patterns'
// lists of pigments, average of pigments and of normals: read field by field, with each
// entry placed by its own transforms from the enclosing pattern's space; and what stays
// refused.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::materialOf;

using sdltest::errorsOf;
using sdltest::readScene;

}  // namespace

TEST_CASE("scene reader maps: a pigment map's entries, each placed by its own transforms",
          "[sdl][scene][texture][pigment-map]") {
  auto r = readScene(R"(
#declare P = pigment { checker rgb <0, 0, 1>, rgb <0, 1, 0> scale 0.5 }
#declare M = pigment_map { [0 rgb 1] [1 rgb 0] }
sphere { 0, 1
  pigment { gradient y
    pigment_map { [0 rgb <1, 0, 0>] [0.5 P scale 4] [1 color rgbt <0, 0, 1, 0.5>] }
    scale 3 }
}
sphere { 0, 1 pigment { bozo pigment_map { M } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = materialOf(s, 0);
  const auto& t = std::get<PatternTexture>(m.texture);
  REQUIRE(t.pigments.size() == 3);
  CHECK(t.pigments[0].at == 0.0);
  CHECK(t.pigments[0].color.rgb == Color(1, 0, 0));
  CHECK(std::holds_alternative<std::monostate>(t.pigments[0].texture));
  // P's scale 0.5, then the entry's scale 4: cubes of edge 2 in the gradient's space.
  const auto& c = std::get<CheckerTexture>(t.pigments[1].texture);
  CHECK(c.color1 == Color(0, 0, 1));
  CHECK(c.placement.patternFromObject[0][0] == Approx(0.5));
  CHECK(c.placement.patternFromObject[2][2] == Approx(0.5));  // POV-Ray's space: no S
  CHECK(t.pigments[2].color.ft.transmit == 0.5f);
  // The outer pattern: its scale 3 and Lucent's z negation.
  CHECK(t.pattern.placement.patternFromObject[0][0] == Approx(1.0 / 3.0));
  CHECK(t.pattern.placement.patternFromObject[2][2] == Approx(-1.0 / 3.0));
  CHECK(m.isTransmissive());
  CHECK(m.transmissive == Color(0.0f));  // per point, not the material's

  const auto& declared = std::get<PatternTexture>(materialOf(s, 1).texture);
  REQUIRE(declared.pigments.size() == 2);
  CHECK(declared.pigments[1].color.rgb == Color(0.0f));
}

TEST_CASE("scene reader maps: block patterns' pigments, averages of pigments and normals",
          "[sdl][scene][texture][pigment-map]") {
  auto r = readScene(R"(
#declare Clear = pigment { gradient x color_map { [0 rgbt <1, 1, 1, 0.3>] [1 rgbt <0, 0, 0, 0.3>] } }
sphere { 0, 1 pigment { checker pigment { Clear } pigment { rgb <0, 1, 0> } } }
sphere { 0, 1 pigment { hexagon pigment { rgb 1 }, pigment { rgb 0.5 }, pigment { bozo } } }
sphere { 0, 1
  pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 brick pigment { rgb 1 } pigment { rgb 0 }] }
    rotate z * 90 }
  normal { average normal_map { [2 bumps 0.6 scale 0.5] [1 ripples 0.8] } scale 2 }
}
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& c = std::get<CheckerTexture>(materialOf(s, 0).texture);
  REQUIRE(c.pigments.size() == 2);
  // The declared pigment's uniform transmit is back in its colours inside the list.
  const auto& clear = std::get<PatternTexture>(c.pigments[0].texture);
  REQUIRE(clear.map.entries.size() == 2);
  CHECK(clear.map.entries[0].ft.transmit == 0.3f);
  CHECK(clear.map.entries[1].ft.transmit == 0.3f);
  CHECK(c.pigments[1].color.rgb == Color(0, 1, 0));

  const auto& h = std::get<HexagonTexture>(materialOf(s, 1).texture);
  REQUIRE(h.pigments.size() == 3);
  CHECK(std::get<PatternTexture>(h.pigments[2].texture).pattern.type == PatternType::bozo);
  // The nested bozo takes global_settings' noise generator (POV-Ray 3.7's 2).
  CHECK(std::get<PatternTexture>(h.pigments[2].texture).pattern.noiseGenerator == 2);

  const Material& m = materialOf(s, 2);
  const auto& a = std::get<AverageTexture>(m.texture);
  REQUIRE(a.entries.size() == 2);
  CHECK(a.entries[0].at == 1.0);
  CHECK(a.entries[1].at == 3.0);
  CHECK(std::get<BrickTexture>(a.entries[1].texture).pigments.size() == 2);
  CHECK(a.placement.patternFromObject[0][1] == Approx(-1.0));  // rotate z 90, inverted

  REQUIRE(m.normal);
  REQUIRE(m.normal->average.size() == 2);
  CHECK(m.normal->average[0].weight == 2.0);
  CHECK(m.normal->average[0].normal.pattern.type == PatternType::bumps);
  CHECK(m.normal->average[0].normal.depth == 0.6);
  CHECK(m.normal->average[0].normal.pattern.placement.patternFromObject[0][0] == Approx(2.0));
  CHECK(m.normal->average[1].normal.pattern.type == PatternType::ripples);
  CHECK(m.normal->average[1].normal.depth == 0.8);
  CHECK(m.normal->pattern.placement.patternFromObject[0][0] == Approx(0.5));
}

TEST_CASE("scene reader maps: what stays refused, at its keyword",
          "[sdl][scene][texture][pigment-map][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { average } }\n"
      "sphere { 0, 1 pigment { checker pigment { rgb 1 } rgb 0 } }\n"
      "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb 1] [1 cubic] } } }\n"
      "sphere { 0, 1 pigment { gradient y pigment_map { [0.5 rgb 1] [0.2 rgb 0] } } }\n");
  REQUIRE(errors.size() == 4);
  CHECK(errors[0] ==
        "test.pov:1:25: error: 'average' needs a pigment_map (the pigments it averages)");
  CHECK(errors[1] ==
        "test.pov:2:51: error: a colour after a block pattern's pigments (POV-Ray: \"No "
        "matching } in 'pigment'\"; a list is pigments alone, the cells it leaves take the "
        "#default pigment)");
  CHECK(errors[2].rfind("test.pov:3:63: error: 'cubic' is not supported by Lucent (a pattern "
                        "Lucent does not have; its patterns are gradient",
                        0) == 0);
  CHECK(errors[3] == "test.pov:4:36: error: the pigment map's entries must be in ascending order");
}

TEST_CASE("scene reader maps: an average's weights are optional, 1 by default (POV-Ray's)",
          "[sdl][scene][texture][pigment-map]") {
  auto r = readScene(R"(
sphere { 0, 1
  pigment { average pigment_map { [gradient y] [2, rgb 1] } }
  normal { average normal_map { [gradient x, -5.0 scallop_wave scale 0.5] [3.0 gradient y, 5.0] } }
}
)");
  REQUIRE(r->load.scene);
  const Material& m = materialOf(*r->load.scene, 0);
  const auto& a = std::get<AverageTexture>(m.texture);
  REQUIRE(a.entries.size() == 2);
  CHECK(a.entries[0].at == 1.0);
  CHECK(std::get<PatternTexture>(a.entries[0].texture).pattern.type == PatternType::gradient);
  CHECK(a.entries[1].at == 2.0);
  REQUIRE(m.normal);
  REQUIRE(m.normal->average.size() == 2);
  CHECK(m.normal->average[0].weight == 1.0);
  CHECK(m.normal->average[0].normal.depth == -5.0);
  CHECK(m.normal->average[0].normal.pattern.wave == WaveShape::scallop);
  CHECK(m.normal->average[1].weight == 3.0);
  CHECK(m.normal->average[1].normal.depth == 5.0);
}

TEST_CASE("scene reader maps: number_of_waves gives every ripples and waves its sources",
          "[sdl][scene][settings]") {
  // Wherever global_settings stands, in averages too; other patterns keep the default.
  auto r = readScene(
      "sphere { 0, 1 normal { average normal_map { [1 waves] [1 ripples] } } }\n"
      "sphere { 0, 1 pigment { waves } }\n"
      "sphere { 0, 1 pigment { bozo } }\n"
      "global_settings { number_of_waves 3.7 }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const NormalSpec& n = *materialOf(s, 0).normal;
  REQUIRE(n.average.size() == 2);
  CHECK(n.average[0].normal.pattern.waveSources == 3);  // truncated, as POV-Ray does
  CHECK(n.average[1].normal.pattern.waveSources == 3);
  CHECK(std::get<PatternTexture>(materialOf(s, 1).texture).pattern.waveSources == 3);
  CHECK(std::get<PatternTexture>(materialOf(s, 2).texture).pattern.waveSources == 10);
  CHECK(r->out.warnings.empty());
}

TEST_CASE("scene reader maps: number_of_waves below 1 is 1, above Lucent's limit refused",
          "[sdl][scene][settings]") {
  auto r = readScene("global_settings { number_of_waves 0 }\nsphere { 0, 1 pigment { waves } }\n");
  REQUIRE(r->load.scene);
  CHECK(std::get<PatternTexture>(materialOf(*r->load.scene, 0).texture).pattern.waveSources == 1);
  REQUIRE(r->out.warnings.size() == 1);
  CHECK(r->out.warnings[0] ==
        "test.pov:1:19: warning: number_of_waves below 1 is 1 (as POV-Ray makes it)");
  CHECK(errorsOf("global_settings { number_of_waves 1001 }\n") ==
        std::vector<std::string>{
            "test.pov:1:19: error: number_of_waves above 1000 is not supported by Lucent"});
}
