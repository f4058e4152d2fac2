// The scene reader's textures: pattern pigments with their colour maps, block patterns,
// normals, declared colour maps and normals, and where a pattern lies on its shape
// (texture transforms in POV-Ray's order), checked field by field; and what is refused,
// where, including refusals inside declarations that are reported only when used.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

const Material& materialOf(const Scene& scene, const Node& n) {
  REQUIRE(n.material);
  return scene.materials.at(*n.material);
}

const Node& top(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

void checkColor(const Color& got, const Color& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-6));
}

void checkMat(const Mat4& got, const Mat4& want) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(got[i][j] == Approx(want[i][j]).margin(1e-12));
}

// Lucent's space is POV-Ray's with z negated: a pattern's point is S·p in POV-Ray's.
const Mat4 kS = glm::scale(Mat4(1.0), Vec3(1, 1, -1));

Mat4 scaling(double s) { return glm::scale(Mat4(1.0), Vec3(s)); }
Mat4 translation(const Vec3& v) { return glm::translate(Mat4(1.0), v); }

}  // namespace

TEST_CASE("scene reader textures: a pattern pigment's colour map, entry by entry",
          "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 pigment { bozo frequency 2 phase 0.25 sine_wave turbulence <0.5, 0.25, 0>
    octaves 3 omega 0.4 lambda 3 noise_generator 1
    color_map { [0 rgb 1] [0.5, 0.8 color rgb <1, 0, 0> color rgb <0, 0, 1>] [1 color red 1] } }
  finish { ambient 0.2 diffuse 0.5 } }
global_settings { noise_generator 3 }
sphere { 0, 1 pigment { granite } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = materialOf(s, top(s, 0));
  const auto& t = std::get<PatternTexture>(m.texture);
  CHECK(t.pattern.type == PatternType::bozo);
  CHECK(t.pattern.frequency == 2.0);
  CHECK(t.pattern.phase == 0.25);
  CHECK(t.pattern.wave == WaveShape::sine);
  CHECK(t.pattern.noiseGenerator == 1);
  CHECK(t.pattern.placement.turbulence == Vec3(0.5, 0.25, 0));
  CHECK(t.pattern.placement.octaves == 3);
  CHECK(t.pattern.placement.omega == 0.4);
  CHECK(t.pattern.placement.lambda == 3.0);
  REQUIRE(t.map.entries.size() == 4);
  CHECK(t.map.entries[0].at == 0.0);
  checkColor(t.map.entries[0].color, Color(1.0f));
  CHECK(t.map.entries[1].at == 0.5);
  checkColor(t.map.entries[1].color, Color(1, 0, 0));
  CHECK(t.map.entries[2].at == 0.8);
  checkColor(t.map.entries[2].color, Color(0, 0, 1));
  CHECK(t.map.entries[3].at == 1.0);
  checkColor(t.map.entries[3].color, Color(1, 0, 0));
  // The texture multiplies diffuse and ambient, each the finish's number.
  checkColor(m.diffuse, Color(0.5f));
  checkColor(m.ambient, Color(0.2f));
  CHECK(m.ambientIsScalar);
  // A pattern that chooses no noise takes global_settings' one; granite's default map
  // is POV-Ray's black to white (Lucent's empty map).
  const auto& granite = std::get<PatternTexture>(materialOf(s, top(s, 1)).texture);
  CHECK(granite.pattern.noiseGenerator == 3);
  CHECK(granite.map.entries.empty());
}

TEST_CASE("scene reader textures: declared colour maps and normals, POV-Ray's default maps",
          "[sdl][scene][texture]") {
  auto r = readScene(R"(
#declare M = colour_map { [0.2 rgbt <1, 1, 0, 0.5>] [0.9 rgbt <0, 0, 1, 0.5>] }
#declare N = normal { bumps 0.4 scale 0.1 }
sphere { 0, 1 pigment { marble turbulence 0.5 color_map { M } } normal { N } }
sphere { 0, 1 pigment { wood } normal { ripples bump_size 0.7 } }
sphere { 0, 1 pigment { checker } }
sphere { 0, 1 pigment { hexagon rgb 1, rgb 0.5 } }
sphere { 0, 1 pigment { brick color rgb <1, 1, 1>, color rgb 0 brick_size <1, 2, 3> mortar 0.1 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = materialOf(s, top(s, 0));
  const auto& marble = std::get<PatternTexture>(m.texture);
  CHECK(marble.pattern.type == PatternType::marble);
  REQUIRE(marble.map.entries.size() == 2);
  CHECK(marble.map.entries[0].at == Approx(0.2));
  checkColor(marble.map.entries[1].color, Color(0, 0, 1));
  // One transmit for all the map's colours: the pigment's.
  checkColor(m.transmissive, Color(0.5f));
  checkColor(m.diffuse, Color(0.6f * 0.5f));
  REQUIRE(m.normal);
  CHECK(m.normal->pattern.type == PatternType::bumps);
  CHECK(m.normal->depth == 0.4);
  CHECK(m.normal->keepFacingAway);  // POV-Ray's rule for bent normals facing away
  checkMat(m.normal->pattern.placement.patternFromObject, scaling(10.0) * kS);

  const Material& wood = materialOf(s, top(s, 1));
  const auto& woodMap = std::get<PatternTexture>(wood.texture).map.entries;
  REQUIRE(woodMap.size() == 2);  // POV-Ray's default wood map
  CHECK(woodMap[0].at == Approx(0.6));
  checkColor(woodMap[0].color, Color(0.666f, 0.312f, 0.2f));
  checkColor(woodMap[1].color, Color(0.4f, 0.1333f, 0.066f));
  REQUIRE(wood.normal);
  CHECK(wood.normal->pattern.type == PatternType::ripples);
  CHECK(wood.normal->depth == 0.7);

  const auto& checker = std::get<CheckerTexture>(materialOf(s, top(s, 2)).texture);
  checkColor(checker.color1, Color(0, 0, 1));  // POV-Ray's default blue and green
  checkColor(checker.color2, Color(0, 1, 0));
  const auto& hexagon = std::get<HexagonTexture>(materialOf(s, top(s, 3)).texture);
  checkColor(hexagon.spec.colors[0], Color(1.0f));
  checkColor(hexagon.spec.colors[1], Color(0.5f));
  checkColor(hexagon.spec.colors[2], Color(1, 0, 0));  // the third not written: POV-Ray's
  const auto& brick = std::get<BrickTexture>(materialOf(s, top(s, 4)).texture);
  checkColor(brick.spec.color1, Color(1.0f));
  checkColor(brick.spec.color2, Color(0.0f));
  CHECK(brick.spec.size == Vec3(1, 2, 3));
  CHECK(brick.spec.mortar == 0.1);
}

TEST_CASE("scene reader textures: a texture follows only the transforms written after it",
          "[sdl][scene][texture]") {
  auto r = readScene(R"(
sphere { 0, 1 scale 2 pigment { checker rgb 1, rgb 0 scale 0.5 } rotate y*90 translate x }
union {
  sphere { 0, 1 translate x }
  sphere { 0, 1 scale 3 pigment { bozo } }
  sphere { 0, 1 }
  translate y*2
  texture { pigment { agate } translate z }
  scale 4
}
#declare D = sphere { 0, 1 translate x pigment { spotted translate y } }
object { D scale 2 }
sphere { 0, 1 pigment { bozo } translate x pigment { scale 2 } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  // inverse(Ttex)·B·S: B the sphere's scale 2 before the pigment, Ttex its scale 0.5.
  const auto& checker = std::get<CheckerTexture>(materialOf(s, top(s, 0)).texture);
  checkMat(checker.placement.patternFromObject, scaling(4.0) * kS);
  CHECK(checker.scale == 1.0);

  // The union's texture, written after its translate: B = translate y*2; each operand's
  // own transform leads to the union's space, the second operand keeps its own pigment.
  const Node& u = top(s, 1);
  REQUIRE(u.children.size() == 3);
  const Mat4 unionTexture = glm::inverse(translation(Vec3(0, 0, 1))) * translation(Vec3(0, 2, 0));
  const auto& first = std::get<PatternTexture>(materialOf(s, *u.children[0]).texture);
  CHECK(first.pattern.type == PatternType::agate);
  checkMat(first.pattern.placement.patternFromObject,
           unionTexture * translation(Vec3(1, 0, 0)) * kS);
  const auto& second = std::get<PatternTexture>(materialOf(s, *u.children[1]).texture);
  CHECK(second.pattern.type == PatternType::bozo);
  // Written after the operand's scale 3: not scaled by it.
  checkMat(second.pattern.placement.patternFromObject, scaling(3.0) * kS);
  // An operand with no transform of its own shares the union's material.
  CHECK(!u.children[2]->material);
  checkMat(std::get<PatternTexture>(materialOf(s, u).texture).pattern.placement.patternFromObject,
           unionTexture * kS);

  // A declared object's texture follows the transforms object { } adds.
  const auto& spotted = std::get<PatternTexture>(materialOf(s, top(s, 2)).texture);
  checkMat(spotted.pattern.placement.patternFromObject,
           glm::inverse(translation(Vec3(0, 1, 0))) * translation(Vec3(1, 0, 0)) * kS);

  // A pigment block continues the pigment the object has: bozo, moved by translate x,
  // then scaled by 2 in the object's space.
  const auto& continued = std::get<PatternTexture>(materialOf(s, top(s, 3)).texture);
  CHECK(continued.pattern.type == PatternType::bozo);
  checkMat(
      continued.pattern.placement.patternFromObject,
      glm::inverse(translation(Vec3(1, 0, 0))) * scaling(0.5) * translation(Vec3(1, 0, 0)) * kS);
}

TEST_CASE("scene reader textures: layered textures, each layer with its own terms and place",
          "[sdl][scene][texture][layers]") {
  auto r = readScene(R"(
#declare T_Two = texture { pigment { rgb <1, 0.5, 0> } finish { ambient 0.2 phong 0.5 } }
  texture { pigment { bozo color_map { [0 rgbt 1] [1 rgbf <0, 0, 1, 0.5>] } scale 2 } }
sphere { 0, 1 texture { T_Two } }
sphere { 0, 1 pigment { rgb 0.5 } texture { T_Two translate x } scale 3
  texture { pigment { rgbt <1, 1, 1, 0.5> } finish { diffuse 0.8 } } pigment { rgbt 0.25 } }
box { 0, 1 material { texture { pigment { rgb 1 } } texture { pigment { rgbf <1, 0, 0, 1> } }
  interior { ior 1.5 } } }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;

  // A declared layered texture: the first texture is the material, the second its layer.
  const Material& two = materialOf(s, top(s, 0));
  REQUIRE(two.layers.size() == 1);
  checkColor(two.diffuse, Color(0.6f, 0.3f, 0.0f));  // POV-Ray's diffuse 0.6 times the pigment
  checkColor(two.ambient, Color(0.2f, 0.1f, 0.0f));
  checkColor(two.phong, Color(0.5f));
  const Material& bozo = two.layers[0];
  const auto& pattern = std::get<PatternTexture>(bozo.texture);
  CHECK(pattern.pattern.type == PatternType::bozo);
  CHECK(pattern.pattern.noiseGenerator == 2);  // global_settings' default, as the material's
  checkMat(pattern.pattern.placement.patternFromObject, scaling(0.5) * kS);
  CHECK(pattern.map.entries.at(1).ft.filter == 0.5f);
  CHECK(bozo.ambient == Color(0.1f));  // its own finish: POV-Ray's default
  CHECK(bozo.phong == Color(0.0f));

  // Layers over an object's pigment: the pigment's texture at the bottom, then the declared
  // texture's two layers (moved by its translate, and like every layer by the object's
  // scale written after them), then the last texture, whose pigment the last block changes.
  const Material& stacked = materialOf(s, top(s, 1));
  checkColor(stacked.diffuse, Color(0.3f));
  REQUIRE(stacked.layers.size() == 3);
  checkColor(stacked.layers[0].diffuse, Color(0.6f, 0.3f, 0.0f));
  checkMat(std::get<PatternTexture>(stacked.layers[1].texture).pattern.placement.patternFromObject,
           scaling(0.5) * glm::inverse(translation(Vec3(1, 0, 0))) * kS);
  const Material& topLayer = stacked.layers[2];
  checkColor(topLayer.diffuse, Color(0.8f * 0.25f * 0.75f));  // diffuse·pigment·opacity
  checkColor(topLayer.transmissive, Color(0.25f));
  // The whole lets light through where every layer does: the bottom layer does not.
  CHECK(!stacked.isTransmissive());
  CHECK(!stacked.fullTir);

  // A material's two textures, and its interior on the whole material.
  const Material& glass = materialOf(s, top(s, 2));
  REQUIRE(glass.layers.size() == 1);
  CHECK(glass.ior == 1.5);
  checkColor(glass.transmissive, Color(0.0f));
  checkColor(glass.layers[0].transmissive, Color(1.0f, 0.0f, 0.0f));
}

TEST_CASE("scene reader textures: under #version 3.1 a layer's filter acts as a transmit",
          "[sdl][scene][texture][layers]") {
  // POV-Ray keeps 3.1's layering for old scenes: a filter in a layer over another becomes a
  // transmit (its Convert_Filter_To_Transmit); from 3.5 on it filters.
  for (const char* version : {"3.1", "3.7"}) {
    auto r = readScene(std::string("#version ") + version +
                       ";\nsphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { "
                       "rgbf <1, 0.5, 0, 0.5> } } }\n");
    REQUIRE(r->load.scene);
    const Material& m = materialOf(*r->load.scene, top(*r->load.scene, 0));
    REQUIRE(m.layers.size() == 1);
    INFO("#version " << version);
    if (std::string(version) == "3.1") checkColor(m.layers[0].transmissive, Color(0.5f));
    else checkColor(m.layers[0].transmissive, Color(0.5f, 0.25f, 0.0f));
  }
}

TEST_CASE("scene reader textures: texture_map and block lists of textures become material maps",
          "[sdl][scene][texture][material-map]") {
  const auto errors = errorsOf(
      "#declare T_Two = texture { pigment { rgb 1 } } texture { pigment { rgb 0 } }\n"
      "sphere { 0, 1 texture { pigment { rgb 1 } } texture { bozo texture_map { [0 T_Two] } } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        "test.pov:2:45: error: a pattern of textures cannot be layered (POV-Ray: \"Cannot layer "
        "over a patterned texture\")");

  auto good = readScene(R"(
#declare T_Two = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
sphere { 0, 1 texture { gradient y texture_map { [0.25 T_Two] [0.75 pigment { bozo scale 2 }
  finish { phong 1 }] } scale 4 } interior { ior 1.5 } }
plane { y, 0 texture { checker texture { pigment { rgb 1 } } texture { T_Two } scale 2 } }
)");
  REQUIRE(good->load.scene);
  const Scene& s = *good->load.scene;
  const Material& gradient = materialOf(s, top(s, 0));
  REQUIRE(gradient.mapped());
  CHECK(gradient.ior == 1.5);
  const auto& pattern = std::get<PatternTexture>(gradient.mapPattern);
  CHECK(pattern.pattern.type == PatternType::gradient);
  checkMat(pattern.pattern.placement.patternFromObject, scaling(0.25) * kS);
  REQUIRE(gradient.mapEntries.size() == 2);
  CHECK(gradient.mapEntries[0].at == 0.25);
  CHECK(gradient.mapEntries[0].material.layers.size() == 1);  // the declared layered texture
  // The entry's pattern lies in the map's pattern space: its own scale 2 after the map's 4.
  const Material& bozo = gradient.mapEntries[1].material;
  checkMat(std::get<PatternTexture>(bozo.texture).pattern.placement.patternFromObject,
           scaling(0.5) * scaling(0.25) * kS);
  checkColor(bozo.phong, Color(1.0f));

  const Material& checker = materialOf(s, top(s, 1));
  REQUIRE(checker.mapped());
  checkMat(std::get<CheckerTexture>(checker.mapPattern).placement.patternFromObject,
           scaling(0.5) * kS);
  REQUIRE(checker.mapEntries.size() == 2);
  CHECK(checker.mapEntries[0].at == 0.0);
  CHECK(checker.mapEntries[1].at == 1.0);
  CHECK(checker.mapEntries[1].material.layered());
}

TEST_CASE("scene reader textures: what Lucent cannot render is refused at its keyword",
          "[sdl][scene][texture][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { cubic } }\n"
      "sphere { 0, 1 pigment { checker pigment_map { [0 rgb 1] } } }\n"
      "sphere { 0, 1 interior_texture { pigment { rgb 1 } } }\n"
      "sphere { 0, 1 texture { brick scale 2 } }\n");
  REQUIRE(errors.size() == 4);
  CHECK(errors[0].rfind("test.pov:1:25: error: 'cubic' is not supported by Lucent (a pattern "
                        "Lucent does not have; its patterns are gradient, onion",
                        0) == 0);
  CHECK(errors[1] ==
        "test.pov:2:33: error: 'pigment_map' on a block pattern is not supported by Lucent (give "
        "it a list of pigments: checker pigment {..} pigment {..})");
  CHECK(errors[2] ==
        "test.pov:3:15: error: 'interior_texture' needs a texture of the object's own, as in "
        "POV-Ray");
  CHECK(errors[3] ==
        "test.pov:4:25: error: 'brick' is not supported by Lucent (a pattern of textures that "
        "Lucent cannot read: it reads texture_map after a pattern, and the texture lists of "
        "checker, hexagon and brick)");
}

TEST_CASE(
    "scene reader textures: a refusal inside a declaration is an error only where it "
    "is used, located in the include",
    "[sdl][scene][texture][errors]") {
  // Declared and never used: no error.
  auto unused = readScene(
      "#include \"refusals.inc\"\n"
      "sphere { 0, 1 pigment { rgb 1 } }\n");
  CHECK(unused->load.scene);
  // Used, directly and through another declaration: the error at the feature in the
  // include, with where the scene uses it; reported once.
  const auto errors = errorsOf(
      "#include \"refusals.inc\"\n"
      "#declare T = texture { pigment { P_Cubic } }\n"
      "sphere { 0, 1 texture { T } }\n"
      "sphere { 0, 1 pigment { P_Cubic } }\n"
      "sphere { 0, 1 texture { T_Uv } }\n"
      "object { J_Unread }\n");
  // T_Uv, a uv-mapped plain colour, is read (a colour is the same at every (u, v)).
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].rfind("refusals.inc:3:30: error: 'cubic' is not supported by Lucent", 0) == 0);
  CHECK(errors[0].find("\ntest.pov:3:25: note: the declaration is used here") != std::string::npos);
  // A block the reader does not read yet, declared: the same.
  CHECK(errors[1].rfind("refusals.inc:6:36: error: a height field from 'iff' is not supported",
                        0) == 0);
  CHECK(errors[1].find("\ntest.pov:6:10: note: the declaration is used here") != std::string::npos);
}

TEST_CASE("scene reader textures: the standard material includes read to their end",
          "[sdl][scene][texture][include]") {
  auto r = readScene(
      "#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"woods.inc\"\n"
      "#include \"woodmaps.inc\"\n#include \"stones.inc\"\n#include \"glass.inc\"\n"
      "#include \"metals.inc\"\n#include \"golds.inc\"\n"
      "sphere { 0, 1 pigment { Jade } }\n"
      "sphere { 0, 1 pigment { P_WoodGrain1A color_map { M_Wood1A } } }\n"
      "sphere { 0, 1 pigment { wood color_map { M_Wood1A } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.size() == 3);
  CHECK(std::get<PatternTexture>(materialOf(s, top(s, 0)).texture).pattern.type ==
        PatternType::marble);
  // woods.inc's grain, through woodmaps.inc's old-style map: two entries per bracket.
  const auto& wood = std::get<PatternTexture>(materialOf(s, top(s, 1)).texture);
  CHECK(wood.pattern.type == PatternType::wood);
  CHECK(wood.pattern.placement.octaves == 3);
  REQUIRE(wood.map.entries.size() >= 4);
  CHECK(wood.map.entries[1].at == Approx(0.1));
  checkColor(wood.map.entries[1].color, Color(0.88f, 0.60f, 0.40f));
}

TEST_CASE("scene reader textures: a sky_sphere of one colour, and of a declared old-style map",
          "[sdl][scene][texture]") {
  auto r = readScene("sky_sphere { pigment { rgb <0.2, 0.3, 0.4> } }\n");
  REQUIRE(r->load.scene);
  REQUIRE(r->load.scene->sky);
  const auto& entries = std::get<PatternTexture>(r->load.scene->sky->layers.at(0)).map.entries;
  REQUIRE(entries.size() == 1);
  checkColor(entries[0].color, Color(0.2f, 0.3f, 0.4f));
  auto m = readScene(
      "#declare M = color_map { [0, 0.5 color rgb 1 color rgb <0, 0, 1>] }\n"
      "sky_sphere { pigment { gradient y color_map { M } } }\n");
  REQUIRE(m->load.scene);
  REQUIRE(m->load.scene->sky);
  const auto& two = std::get<PatternTexture>(m->load.scene->sky->layers.at(0)).map.entries;
  REQUIRE(two.size() == 2);
  CHECK(two[1].at == 0.5);
  checkColor(two[1].color, Color(0, 0, 1));
}

TEST_CASE("scene reader textures: a sky_sphere pattern Lucent lacks is one error, at it",
          "[sdl][scene][texture]") {
  // The refusal reads to the pigment's end: what follows is read as usual.
  const std::vector<std::string> errors = errorsOf(
      "sky_sphere { pigment { cubic color_map { [0 rgb 1] [1 rgb 0] } } }\n"
      "sphere { 0, 1 pigment { rgb 1 } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].find("test.pov:1:24: error: 'cubic'") == 0);
}

TEST_CASE(
    "scene reader textures: colour maps and colour lists keep each colour's filter and "
    "transmit",
    "[sdl][scene][texture]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { bozo color_map { [0 rgbf <1, 0, 0, 0.25>] [0.5 rgb 0.5]\n"
      "  [1 rgbft <0, 0, 1, 0.5, 0.125>] } } }\n"
      "sphere { 0, 1 pigment { checker rgbt <1, 1, 1, 0.75>, rgbf <0, 1, 0, 1> } }\n"
      "sphere { 0, 1 pigment { hexagon rgb 1, rgbt <0, 0, 0, 1>, rgbf <1, 0, 0, 0.5> } }\n"
      "sphere { 0, 1 pigment { brick rgbft <0.5, 0.5, 0.5, 0.1, 0.2>, rgb 1 } }\n"
      "sphere { 0, 1 pigment { gradient y color_map { [0 rgbt <1, 1, 1, 0.5>] [1 rgbt 0.5] } } "
      "}\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& bozo = std::get<PatternTexture>(materialOf(s, top(s, 0)).texture);
  REQUIRE(bozo.map.entries.size() == 3);
  checkColor(bozo.map.entries[0].color, Color(1, 0, 0));
  CHECK(bozo.map.entries[0].ft.filter == 0.25f);
  CHECK(bozo.map.entries[0].ft.transmit == 0.0f);
  CHECK(!bozo.map.entries[1].ft.any());
  CHECK(bozo.map.entries[2].ft.filter == 0.5f);
  CHECK(bozo.map.entries[2].ft.transmit == 0.125f);
  // The material keeps no transmission of its own: the texture carries it, point by point.
  const Material& bozoMaterial = materialOf(s, top(s, 0));
  CHECK(bozoMaterial.transmissive == Color(0.0f));
  CHECK(bozoMaterial.diffuse == Color(0.6f));
  CHECK(bozoMaterial.isTransmissive());
  CHECK(bozoMaterial.fullTir);

  const auto& checker = std::get<CheckerTexture>(materialOf(s, top(s, 1)).texture);
  CHECK(checker.ft1 == FilterTransmit{0.0f, 0.75f});
  CHECK(checker.ft2 == FilterTransmit{1.0f, 0.0f});
  checkColor(checker.color2, Color(0, 1, 0));
  const auto& hexagon = std::get<HexagonTexture>(materialOf(s, top(s, 2)).texture);
  CHECK(!hexagon.spec.ft[0].any());
  CHECK(hexagon.spec.ft[1] == FilterTransmit{0.0f, 1.0f});
  CHECK(hexagon.spec.ft[2] == FilterTransmit{0.5f, 0.0f});
  const auto& brick = std::get<BrickTexture>(materialOf(s, top(s, 3)).texture);
  CHECK(brick.spec.ft1 == FilterTransmit{0.1f, 0.2f});
  CHECK(!brick.spec.ft2.any());

  // One transmit for every colour and no filter: the material's, as before (no per-hit cost).
  const Material& uniform = materialOf(s, top(s, 4));
  CHECK(!textureSeeThrough(uniform.texture));
  CHECK(uniform.transmissive == Color(0.5f));
  CHECK(uniform.diffuse == Color(0.3f));
}

TEST_CASE("scene reader textures: a sky_sphere's pigments become its layers, in order",
          "[sdl][scene][texture]") {
  auto r = readScene(
      "#version 3.7;\n"
      "#declare S = sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } "
      "}\n"
      "  pigment { bozo color_map { [0 rgbt <1, 1, 1, 0>] [1 rgbt <1, 1, 1, 1>] } scale 0.5 }\n"
      "}\n"
      "sky_sphere { S pigment { checker rgbf <1, 0, 0, 0.5>, rgbt 0.25 } rotate x*90 }\n");
  REQUIRE(r->load.scene);
  REQUIRE(r->load.scene->sky);
  const Sky& sky = *r->load.scene->sky;
  REQUIRE(sky.layers.size() == 3);
  CHECK(std::get<PatternTexture>(sky.layers[0]).pattern.type == PatternType::gradient);
  const auto& clouds = std::get<PatternTexture>(sky.layers[1]);
  CHECK(clouds.pattern.type == PatternType::bozo);
  CHECK(clouds.pattern.noiseGenerator == 2);  // global_settings' default, set at the end
  REQUIRE(clouds.map.entries.size() == 2);
  CHECK(clouds.map.entries[1].ft.transmit == 1.0f);
  // The pigment's scale 0.5, from Lucent's space (z negated) into pattern space.
  Mat4 want(2.0);
  want[3][3] = 1.0;
  want[2][2] = -2.0;
  sdltest::checkMat(clouds.pattern.placement.patternFromObject, want);
  const auto& checker = std::get<CheckerTexture>(sky.layers[2]);
  CHECK(checker.ft1 == FilterTransmit{0.5f, 0.0f});
  CHECK(checker.ft2 == FilterTransmit{0.0f, 0.25f});
  CHECK(sky.layering == SkyLayering::pov37);
  // A scene of #version 3.6 layers by POV-Ray's older rule.
  auto old = readScene("#version 3.6;\nsky_sphere { pigment { rgbt <1, 1, 1, 0.5> } }\n");
  REQUIRE(old->load.scene);
  REQUIRE(old->load.scene->sky);
  CHECK(old->load.scene->sky->layering == SkyLayering::pov36);
  // So does a scene with no #version anywhere: POV-Ray's EffectiveLanguageVersion is 3.62
  // until one is read (a standard include's sets it).
  auto none = readScene("sky_sphere { pigment { rgbt <1, 1, 1, 0.5> } }\n");
  REQUIRE(none->load.scene);
  CHECK(none->load.scene->sky->layering == SkyLayering::pov36);
  auto included =
      readScene("#include \"colors.inc\"\nsky_sphere { pigment { rgbt <1, 1, 1, 0.5> } }\n");
  REQUIRE(included->load.scene);
  CHECK(included->load.scene->sky->layering == SkyLayering::pov37);
  // rotate x*90 of POV-Ray's space: its +y goes to +z, Lucent's -z; the sky's inverse brings
  // Lucent's -z back to +y.
  const Vec3 up = Vec3(sky.skyFromWorld * Vec4(0.0, 0.0, -1.0, 0.0));
  sdltest::checkVec(up, Vec3(0.0, 1.0, 0.0));
}

TEST_CASE("scene reader textures: POV-Ray 1's normals in a texture, and blocks that continue",
          "[sdl][scene][texture]") {
  auto r = readScene(
      "sphere { 0, 1 texture { pigment { rgb 1 } wrinkles 0.3 scale 2 } }\n"
      "sphere { 0, 1 texture { pigment { bozo } finish { phong 1 } pigment { scale 4 } "
      "finish { diffuse 0.4 } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Material& m = materialOf(s, top(s, 0));
  REQUIRE(m.normal);
  CHECK(m.normal->pattern.type == PatternType::wrinkles);
  CHECK(m.normal->depth == 0.3);
  checkMat(m.normal->pattern.placement.patternFromObject, scaling(0.5) * kS);
  // The second pigment and finish continue the first ones.
  const Material& c = materialOf(s, top(s, 1));
  const auto& bozo = std::get<PatternTexture>(c.texture);
  CHECK(bozo.pattern.type == PatternType::bozo);
  checkMat(bozo.pattern.placement.patternFromObject, scaling(0.25) * kS);
  checkColor(c.phong, Color(1.0f));
  checkColor(c.diffuse, Color(0.4f));
}

TEST_CASE(
    "scene reader textures: a block pattern's cells read its list or colour map at their "
    "numbers after frequency, phase and wave",
    "[sdl][scene][texture][block]") {
  // POV-Ray's Evaluate_TPat shapes the cell number 0, 1, 2 (frequency: fmod(n·f + phase,
  // 1.00001); then the wave), and its list or colour map is read at the result.
  auto r = readScene(
      "sphere { 0, 1 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> frequency 0.5 } }\n"
      "sphere { 0, 1 pigment { hexagon rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> "
      "triangle_wave } }\n"
      "sphere { 0, 1 pigment { brick rgb <1, 1, 1>, rgb <0, 0, 0> sine_wave } }\n"
      "sphere { 0, 1 pigment { hexagon rgb 0, rgb 0.5, rgb 1 frequency 0.25 phase 0.5 } }\n"
      "sphere { 0, 1 pigment { checker rgb 0, rgb 1 phase 0.3 } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& checker = std::get<CheckerTexture>(materialOf(s, top(s, 0)).texture);
  checkColor(checker.color1, Color(1, 0, 0));
  checkColor(checker.color2, Color(0.5f, 0, 0.5f));  // cell 1 at 0.5: half of each
  // triangle_wave: 0 at every whole number, so each cell takes the first colour.
  const auto& hexagon = std::get<HexagonTexture>(materialOf(s, top(s, 1)).texture);
  for (int i = 0; i < 3; ++i) checkColor(hexagon.spec.colors[i], Color(1, 0, 0));
  // sine_wave: (1 + sin 2πn)/2 = 0.5 for every whole n.
  const auto& brick = std::get<BrickTexture>(materialOf(s, top(s, 2)).texture);
  checkColor(brick.spec.color1, Color(0.5f));
  checkColor(brick.spec.color2, Color(0.5f));
  // n·0.25 + 0.5: 0.5, 0.75, 1 (kept below 1.00001): the list's values at them.
  const auto& shifted = std::get<HexagonTexture>(materialOf(s, top(s, 3)).texture);
  checkColor(shifted.spec.colors[0], Color(0.25f));
  checkColor(shifted.spec.colors[1], Color(0.375f));
  checkColor(shifted.spec.colors[2], Color(0.5f));
  // A phase without a frequency changes nothing (POV-Ray's block frequency is 0).
  const auto& phased = std::get<CheckerTexture>(materialOf(s, top(s, 4)).texture);
  checkColor(phased.color1, Color(0.0f));
  checkColor(phased.color2, Color(1.0f));

  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { checker pigment { rgb 1 } pigment { rgb 0 } frequency 0.5 } }\n"
      "sphere { 0, 1 normal { hexagon 0.5 sine_wave } }\n"
      "sphere { 0, 1 pigment { hexagon color_map { [0 rgb 1] [1 rgb 0] } } }\n");
  REQUIRE(errors.size() == 3);
  CHECK(errors[2] ==
        "test.pov:3:33: error: Cannot use color_map with this pattern type. (POV-Ray's error)");
  CHECK(errors[0].find("frequency, phase or a wave on a block pattern's list of pigments is not "
                       "supported by Lucent") != std::string::npos);
  CHECK(errors[1].find("frequency, phase or a wave on a block pattern's normal is not supported "
                       "by Lucent") != std::string::npos);
}
