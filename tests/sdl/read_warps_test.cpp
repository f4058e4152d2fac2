// The scene reader's warps: `warp { }` blocks and the pattern's transforms read as one
// ordered list of steps (POV-Ray 3.7's warp list), each warp's parameters with POV-Ray's
// defaults, and what is refused.
#include <catch2/catch.hpp>

#include "scene_read_support.h"

#include "sdl/scene_reader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::checkMat;
using sdltest::checkVec;
using sdltest::errorsOf;
using sdltest::readScene;

const Mat4 kS = glm::scale(Mat4(1.0), Vec3(1.0, 1.0, -1.0));

// The placement of the pigment of the scene's shape i.
const PatternPlacement& pigmentPlacement(const Scene& s, size_t i) {
  REQUIRE(s.root->children.size() > i);
  const Node& n = *s.root->children[i];
  REQUIRE(n.material);
  const Material& m = s.materials.at(*n.material);
  return std::get<PatternTexture>(m.texture).pattern.placement;
}

}  // namespace

TEST_CASE(
    "scene reader warps: transforms before a warp become a step, those after it place "
    "the pattern",
    "[sdl][scene][texture][warp]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { bozo scale 2 warp { repeat x*2 offset y flip z } translate x } }\n"
      "sphere { 0, 1 pigment { crackle warp { turbulence 0.6 octaves 4 lambda 3 } scale 2 "
      "turbulence 0.2 } }\n"
      "sphere { 0, 1 pigment { wood warp { turbulence <0.1, 0.2, 0.3> } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;

  const PatternPlacement& a = pigmentPlacement(s, 0);
  REQUIRE(a.warps.size() == 2);
  checkMat(std::get<TransformWarp>(a.warps[0]).patternFromPrevious,
           glm::scale(Mat4(1.0), Vec3(0.5)));
  const auto& repeat = std::get<RepeatWarp>(a.warps[1]);
  CHECK(repeat.axis == 0);
  CHECK(repeat.width == 2.0);
  CHECK(repeat.offset == Vec3(0.0, 1.0, 0.0));
  CHECK(!repeat.flip[0]);
  CHECK(!repeat.flip[1]);
  CHECK(repeat.flip[2]);
  checkMat(a.patternFromObject, glm::translate(Mat4(1.0), Vec3(-1.0, 0.0, 0.0)) * kS);

  // The turbulence warp is a step; the classic turbulence stays the placement's (last).
  const PatternPlacement& b = pigmentPlacement(s, 1);
  REQUIRE(b.warps.size() == 1);
  const auto& turb = std::get<TurbulenceWarp>(b.warps[0]);
  CHECK(turb.strength == Vec3(0.6));
  CHECK(turb.octaves == 4);
  CHECK(turb.lambda == 3.0);
  CHECK(turb.omega == 0.5);
  CHECK(b.turbulence == Vec3(0.2));
  checkMat(b.patternFromObject, glm::scale(Mat4(1.0), Vec3(0.5)) * kS);

  const PatternPlacement& c = pigmentPlacement(s, 2);
  REQUIRE(c.warps.size() == 1);
  CHECK(std::get<TurbulenceWarp>(c.warps[0]).strength == Vec3(0.1, 0.2, 0.3));
  CHECK(c.turbulence == Vec3(0.0));
}

TEST_CASE("scene reader warps: black holes with POV-Ray's defaults and its settled repeat",
          "[sdl][scene][texture][warp]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { bozo warp { black_hole <1, 2, 3>, 0.5 } } }\n"
      "sphere { 0, 1 pigment { bozo warp { black_hole 0, 0.5 falloff 3 strength 0.75 inverse "
      "repeat <1, 1.5, 0> turbulence <1, 0.5, 0> } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& a = std::get<BlackHoleWarp>(pigmentPlacement(s, 0).warps.at(0));
  CHECK(a.center == Vec3(1.0, 2.0, 3.0));
  CHECK(a.radius == 0.5);
  CHECK(a.strength == 1.0);
  CHECK(a.falloff == 2.0);
  CHECK(!a.inverse);
  CHECK(a.repeat == Vec3(0.0));
  const auto& b = std::get<BlackHoleWarp>(pigmentPlacement(s, 1).warps.at(0));
  CHECK(b.falloff == 3.0);
  CHECK(b.strength == 0.75);
  CHECK(b.inverse);
  // POV-Ray raises the centre to the radius and the repeat to centre + radius + turbulence
  // on each repeated axis, with a warning.
  CHECK(b.center == Vec3(0.5, 0.5, 0.0));
  CHECK(b.repeat == Vec3(2.0, 1.5, 0.0));
  CHECK(b.turbulence == Vec3(1.0, 0.5, 0.0));
  bool warned = false;
  for (const std::string& w : r->out.warnings)
    warned |= w ==
              "test.pov:2:37: warning: the black hole's repeat along x is too small: increased "
              "to 2, as POV-Ray does";
  CHECK(warned);
}

TEST_CASE("scene reader warps: the mapping warps, in normals and texture maps too",
          "[sdl][scene][texture][warp]") {
  auto r = readScene(
      "sphere { 0, 1 pigment { bozo warp { planar y, 2 } warp { cubic } } }\n"
      "sphere { 0, 1 pigment { bozo warp { toroidal major_radius 2 dist_exp 1 orientation 2*x } "
      "warp { spherical } warp { cylindrical dist_exp 0.5 } } }\n"
      "sphere { 0, 1 normal { bumps 0.5 warp { spherical orientation y } scale 2 } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const PatternPlacement& a = pigmentPlacement(s, 0);
  REQUIRE(a.warps.size() == 2);
  const auto& planar = std::get<MappingWarp>(a.warps[0]);
  CHECK(planar.kind == MappingWarpKind::planar);
  checkVec(planar.orientation, Vec3(0.0, 1.0, 0.0));
  CHECK(planar.distance == 2.0);
  CHECK(std::get<MappingWarp>(a.warps[1]).kind == MappingWarpKind::cubic);
  const PatternPlacement& b = pigmentPlacement(s, 1);
  REQUIRE(b.warps.size() == 3);
  const auto& torus = std::get<MappingWarp>(b.warps[0]);
  CHECK(torus.kind == MappingWarpKind::toroidal);
  CHECK(torus.majorRadius == 2.0);
  CHECK(torus.distExp == 1.0);
  checkVec(torus.orientation, Vec3(1.0, 0.0, 0.0));  // normalised, as POV-Ray's
  const auto& sphere = std::get<MappingWarp>(b.warps[1]);
  CHECK(sphere.kind == MappingWarpKind::spherical);
  checkVec(sphere.orientation, Vec3(0.0, 0.0, 1.0));
  CHECK(sphere.distExp == 0.0);
  CHECK(std::get<MappingWarp>(b.warps[2]).distExp == 0.5);

  const Node& n = *s.root->children.at(2);
  const Material& m = s.materials.at(*n.material);
  REQUIRE(m.normal);
  REQUIRE(m.normal->pattern.placement.warps.size() == 1);
  checkMat(m.normal->pattern.placement.patternFromObject, glm::scale(Mat4(1.0), Vec3(0.5)) * kS);
}

TEST_CASE("scene reader warps: POV-Ray's errors and a warp on a solid colour",
          "[sdl][scene][texture][warp][errors]") {
  CHECK(errorsOf("sphere { 0, 1 pigment { bozo warp { repeat <1, 1, 0> } } }\n") ==
        std::vector<std::string>{"test.pov:1:37: error: a repeat warp repeats along one axis "
                                 "only (POV-Ray's error)"});
  CHECK(errorsOf("sphere { 0, 1 pigment { bozo warp { repeat 0*x } } }\n") ==
        std::vector<std::string>{
            "test.pov:1:37: error: a repeat warp needs an axis (POV-Ray's error)"});
  CHECK(errorsOf("sphere { 0, 1 pigment { bozo warp { bend 1 } } }\n") ==
        std::vector<std::string>{
            "test.pov:1:37: error: a warp type expected (turbulence, repeat, black_hole, planar, "
            "spherical, cylindrical, toroidal or cubic), not undeclared identifier 'bend'"});
  // POV-Ray takes a warp on a solid colour, which moves nothing: a warning.
  auto r = readScene("sphere { 0, 1 pigment { rgb 1 warp { cubic } } }\n");
  CHECK(r->load.scene);
  CHECK(r->out.warnings ==
        std::vector<std::string>{"test.pov:1:31: warning: 'warp { cubic }' on a solid colour "
                                 "changes nothing (a warp moves a pattern): ignored"});
}
