// The scene reader's averages of textures (`average texture_map { [w T] ... }`) as material
// maps with an <average>, and a texture_map's entries placed from the map's warped space.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "scenegraph/map_blend.h"
#include "sdl/scene_reader.h"

#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::materialOf;

using sdltest::checkMat;
using sdltest::errorsOf;
using sdltest::readScene;

// Lucent's space is POV-Ray's with z negated: a pattern's point is S·p in POV-Ray's.
const Mat4 kS = glm::scale(Mat4(1.0), Vec3(1, 1, -1));
Mat4 scaling(double s) { return glm::scale(Mat4(1.0), Vec3(s)); }
Mat4 translation(const Vec3& v) { return glm::translate(Mat4(1.0), v); }

}  // namespace

TEST_CASE("scene reader textures: an average of textures becomes an averaged material map",
          "[sdl][scene][texture][material-map]") {
  auto r = readScene(R"(
#declare T_Two = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
sphere { 0, 1 texture { average texture_map { [pigment { rgb 1 }] [3, T_Two]
  [0.5 pigment { bozo scale 2 } finish { phong 1 }] } scale 4 } interior { ior 1.5 } }
)");
  REQUIRE(r->load.scene);
  CHECK(r->load.diagnostics.all().empty());
  const Material& m = materialOf(*r->load.scene, 0);
  REQUIRE(mapAverages(m));
  CHECK(m.ior == 1.5);
  checkMat(std::get<AverageTexture>(m.mapPattern).placement.patternFromObject, scaling(0.25) * kS);
  REQUIRE(m.mapEntries.size() == 3);
  CHECK(m.mapEntries[0].at == 1.0);  // a weight left out is 1, as POV-Ray's
  CHECK(m.mapEntries[1].at == 3.0);
  CHECK(m.mapEntries[2].at == 0.5);  // weights in any order
  CHECK(m.mapEntries[1].material.layers.size() == 1);
  // The entry's pattern lies in the average's space: its own scale 2 after the map's 4.
  const Material& bozo = m.mapEntries[2].material;
  checkMat(std::get<PatternTexture>(bozo.texture).pattern.placement.patternFromObject,
           scaling(0.5) * scaling(0.25) * kS);
  CHECK(bozo.phong == Color(1.0f));
}

TEST_CASE("scene reader textures: a warped texture_map's entries lie in its warped space",
          "[sdl][scene][texture][material-map][warp]") {
  // The map's scale 2 before the warp is a warp step, its translate after it the
  // placement's transform: the entries are placed by both (POV-Ray hands them the point
  // after every step), and nothing is warned.
  auto r = readScene(R"(
sphere { 0, 1 texture { gradient x texture_map { [0 pigment { bozo scale 3 }] [1 pigment { rgb 1 }] }
  scale 2 warp { repeat x } translate y turbulence 0.3 } }
)");
  REQUIRE(r->load.scene);
  CHECK(r->load.diagnostics.all().empty());
  const Material& m = materialOf(*r->load.scene, 0);
  const PatternPlacement& place = std::get<PatternTexture>(m.mapPattern).pattern.placement;
  REQUIRE(place.warps.size() == 2);
  checkMat(place.patternFromObject, translation(Vec3(0, -1, 0)) * kS);
  CHECK(place.turbulence == Vec3(0.3));
  const Material& bozo = m.mapEntries[0].material;
  checkMat(std::get<PatternTexture>(bozo.texture).pattern.placement.patternFromObject,
           scaling(1.0 / 3.0) * scaling(0.5) * translation(Vec3(0, -1, 0)) * kS);
}

TEST_CASE("scene reader textures: an average without its map or with a weight of 0 is refused",
          "[sdl][scene][texture][errors]") {
  const auto errors = errorsOf(
      "sphere { 0, 1 texture { average texture_map { [0 pigment { rgb 1 }] } } }\n"
      "sphere { 0, 1 texture { average pigment { rgb 1 } } }\n");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] ==
        "test.pov:1:48: error: an average's weight must be above 0 (Lucent's averages take "
        "positive weights)");
  CHECK(errors[1] ==
        "test.pov:2:33: error: a texture_map expected after the pattern 'average', not "
        "'pigment'");
}
