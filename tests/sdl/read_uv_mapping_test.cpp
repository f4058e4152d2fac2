// The scene reader's uv_mapping: a uv-mapped pigment or texture becomes mapping="uv" placed
// by its own transforms only (POV-Ray ignores the outer pigment's, which the object's later
// transforms reach), on every shape; normals are bent where POV-Ray bends them; in map
// entries it is refused.
#include <catch2/catch.hpp>

#include "scene_read_support.h"

#include "sdl/scene_reader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <variant>

using namespace lucent;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

void checkMat(const Mat4& got, const Mat4& want) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(got[i][j] == Approx(want[i][j]).margin(1e-12));
}

const char* const kQuad =
    "#declare Q = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
    "  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } face_indices { 2, <0,1,2>, <0,2,3> } }\n";

const Material& materialOf(const Scene& s, size_t i) {
  REQUIRE(s.root->children.size() > i);
  REQUIRE(s.root->children[i]->material);
  return s.materials.at(*s.root->children[i]->material);
}

}  // namespace

TEST_CASE("scene reader uv_mapping: a pigment's own transforms place it, the object's do not",
          "[sdl][scene][texture][uv-mapping]") {
  auto r = readScene(std::string(kQuad) +
                     "object { Q pigment { uv_mapping gradient x scale 0.5 translate y } "
                     "rotate y*30 scale 2 }\n"
                     "object { Q texture { uv_mapping pigment { checker rgb 1, rgb 0 } scale 4 } "
                     "translate x }\n"
                     "#declare P = pigment { uv_mapping bozo scale 3 }\n"
                     "object { Q pigment { P scale 5 } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& gradient = std::get<PatternTexture>(materialOf(s, 0).texture);
  CHECK(gradient.pattern.placement.uv);
  checkMat(
      gradient.pattern.placement.patternFromObject,
      glm::inverse(glm::translate(Mat4(1.0), Vec3(0, 1, 0)) * glm::scale(Mat4(1.0), Vec3(0.5))));
  const auto& checker = std::get<CheckerTexture>(materialOf(s, 1).texture);
  CHECK(checker.placement.uv);
  checkMat(checker.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(0.25)));
  // The declared pigment's scale 3; the scale 5 after it is the outer pigment's.
  const auto& bozo = std::get<PatternTexture>(materialOf(s, 2).texture);
  CHECK(bozo.pattern.placement.uv);
  checkMat(bozo.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(1.0 / 3.0)));
}

TEST_CASE("scene reader uv_mapping: a uv-mapped texture_map maps its entries too",
          "[sdl][scene][texture][uv-mapping]") {
  auto r = readScene(std::string(kQuad) +
                     "object { Q texture { uv_mapping gradient x texture_map {\n"
                     "  [0 pigment { rgb 1 }] [1 pigment { bozo scale 0.1 }] } scale 2 } }\n");
  REQUIRE(r->load.scene);
  const Material& m = materialOf(*r->load.scene, 0);
  REQUIRE(m.mapped());
  const auto& pattern = std::get<PatternTexture>(m.mapPattern);
  CHECK(pattern.pattern.placement.uv);
  checkMat(pattern.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(0.5)));
  const auto& bozo = std::get<PatternTexture>(m.mapEntries.at(1).material.texture);
  CHECK(bozo.pattern.placement.uv);
  // The entry's scale 0.1 after the map's scale 2, from (u, v, 0).
  checkMat(bozo.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(5.0)));
}

TEST_CASE("scene reader uv_mapping: every shape is read, normal entries are refused",
          "[sdl][scene][texture][uv-mapping][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { uv_mapping checker } }\n"
      "sphere { 0, 1 normal { uv_mapping bumps 0.5 } }\n"
      "sphere { 0, 1 pigment { gradient x pigment_map { [0 uv_mapping checker] [1 rgb 1] } } }\n"
      "box { 0, 1 pigment { uv_mapping checker } }\n"
      "torus { 1, 0.25 pigment { uv_mapping checker } }\n"
      "cylinder { 0, y, 1 pigment { uv_mapping checker } }\n"
      "sphere { 0, 1 normal { gradient x normal_map { [0 uv_mapping bumps] [1 dents] } } }\n"
      "sphere { 0, 1 pigment { checker uv_mapping } }\n");
  // The last is POV-Ray's parse error, which stops the reading.
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].rfind("test.pov:7:51: error: 'uv_mapping' inside a map or a list of normals "
                        "is not supported by Lucent",
                        0) == 0);
  CHECK(errors[1] ==
        "test.pov:8:33: error: 'uv_mapping' must come first in a pigment, as POV-Ray reads it");
  const auto normal = errorsOf("sphere { 0, 1 normal { bumps uv_mapping } }\n");
  REQUIRE(normal.size() == 1);
  CHECK(normal[0] ==
        "test.pov:1:30: error: 'uv_mapping' must come first in a normal, as POV-Ray reads it");
}

TEST_CASE("scene reader uv_mapping: normals bent where POV-Ray bends them",
          "[sdl][scene][texture][uv-mapping][normal]") {
  // Lucent's spaces are POV-Ray's with z negated: the placement is T^-1 S, S leaving (u, v, 0)
  // as it is and carrying the bend's z where POV-Ray has it.
  Mat4 s(1.0);
  s[2][2] = -1.0;
  auto r =
      readScene(std::string(kQuad) +
                "object { Q normal { uv_mapping bumps 0.4 scale 0.5 } rotate y*30 }\n"
                "object { Q texture { uv_mapping pigment { checker } normal { bumps 0.3 "
                "scale 2 } } rotate x*20 }\n"
                "object { Q uv_mapping texture { normal { dents 0.2 scale 3 } } rotate z*10 }\n"
                "object { Q texture { normal { uv_mapping wrinkles 0.6 } } }\n");
  REQUIRE(r->load.scene);
  const Scene& sc = *r->load.scene;
  // A normal's own uv_mapping: the world normal is bent.
  const NormalSpec& own = *materialOf(sc, 0).normal;
  CHECK(own.pattern.placement.uv);
  CHECK(own.bendInWorld);
  CHECK(own.depth == Approx(0.4));
  checkMat(own.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(2.0)) * s);
  // A texture's: bent in the texture's space, Lucent's object space (the rotate comes after).
  const NormalSpec& texture = *materialOf(sc, 1).normal;
  CHECK(texture.pattern.placement.uv);
  CHECK_FALSE(texture.bendInWorld);
  checkMat(texture.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(0.5)) * s);
  // An object's: its textures are shaded at (u, v, 0) outside any texture: the world's.
  const NormalSpec& object = *materialOf(sc, 2).normal;
  CHECK(object.pattern.placement.uv);
  CHECK(object.bendInWorld);
  checkMat(object.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(1.0 / 3.0)) * s);
  CHECK(materialOf(sc, 3).normal->bendInWorld);

  // A texture's uv_mapping on a shape turned before the texture: Lucent's object space is not
  // the texture's.
  const auto errors = errorsOf(std::string(kQuad) +
                               "object { Q rotate y*30 texture { uv_mapping normal { bumps } } }\n"
                               "object { Q scale 2 texture { uv_mapping normal { bumps } } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].find("a normal in a uv-mapped texture on a shape turned or stretched before "
                       "the texture is not supported by Lucent") != std::string::npos);
}

TEST_CASE("scene reader uv_mapping: an entry of a map or list of pigments reads (u, v, 0)",
          "[sdl][scene][texture][uv-mapping][pigment-map]") {
  auto r = readScene(std::string(kQuad) +
                     "object { Q pigment { gradient x pigment_map { [0 uv_mapping checker "
                     "scale 0.5] [1 rgb 1] } scale 3 } }\n"
                     "object { Q pigment { checker pigment { uv_mapping bozo scale 0.25 } "
                     "pigment { rgb 0 } } }\n");
  REQUIRE(r->load.scene);
  const auto& map = std::get<PatternTexture>(materialOf(*r->load.scene, 0).texture);
  CHECK_FALSE(map.pattern.placement.uv);
  REQUIRE(map.pigments.size() == 2);
  const auto& checker = std::get<CheckerTexture>(map.pigments[0].texture);
  CHECK(checker.placement.uv);
  // Its own scale 0.5 from (u, v, 0); the map's scale 3 is not its.
  checkMat(checker.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(2.0)));
  const auto& list = std::get<CheckerTexture>(materialOf(*r->load.scene, 1).texture);
  REQUIRE(list.pigments.size() == 2);
  const auto& bozo = std::get<PatternTexture>(list.pigments[0].texture);
  CHECK(bozo.pattern.placement.uv);
  checkMat(bozo.pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(4.0)));

  // Where there is no surface: a pigment_pattern's pigment, a sky.
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { pigment_pattern { gradient x pigment_map { [0 uv_mapping "
      "checker] [1 rgb 1] } } } }\n"
      "sky_sphere { pigment { gradient y pigment_map { [0 uv_mapping checker] [1 rgb 1] } } }\n");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].find("'uv_mapping' in a pigment_pattern's pigment is not supported by Lucent") !=
        std::string::npos);
  CHECK(errors[1].find("'uv_mapping' in a sky_sphere is not supported by Lucent") !=
        std::string::npos);
}
