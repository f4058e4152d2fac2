// The scene reader's uv_mapping: a uv-mapped pigment or texture becomes mapping="uv" placed
// by its own transforms only (POV-Ray ignores the outer pigment's, which the object's later
// transforms reach), on meshes; on other shapes, in normals and in map entries it is refused.
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

TEST_CASE("scene reader uv_mapping: normals and entries are refused, every shape is read",
          "[sdl][scene][texture][uv-mapping][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 pigment { uv_mapping checker } }\n"
      "sphere { 0, 1 normal { uv_mapping bumps 0.5 } }\n"
      "sphere { 0, 1 pigment { gradient x pigment_map { [0 uv_mapping checker] [1 rgb 1] } } }\n"
      "sphere { 0, 1 pigment { checker uv_mapping } }\n"
      "box { 0, 1 pigment { uv_mapping checker } }\n"
      "torus { 1, 0.25 pigment { uv_mapping checker } }\n"
      "cylinder { 0, y, 1 pigment { uv_mapping checker } }\n");
  // The refused normal is then one without a pattern (POV-Ray's 'No normal type given').
  REQUIRE(errors.size() == 4);
  CHECK(errors[0].rfind("test.pov:2:24: error: 'uv_mapping' is not supported by Lucent "
                        "(uv_mapping of normals;",
                        0) == 0);
  CHECK(errors[1] ==
        "test.pov:2:15: error: a normal without a pattern (POV-Ray: 'No normal type given')");
  CHECK(errors[2].rfind("test.pov:3:53: error: 'uv_mapping' inside a map or a list of pigments "
                        "is not supported by Lucent",
                        0) == 0);
  CHECK(errors[3] ==
        "test.pov:4:33: error: 'uv_mapping' must come first in a pigment, as POV-Ray reads it");
}
