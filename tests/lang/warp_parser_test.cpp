// <warp> children of pattern elements (lang/warp_parser.h): each type's attributes and
// defaults, the order they are written in, convert's round trip and export-pov's text.
#include "../support/scene_text.h"
#include "lang/parser.h"
#include "lang/scene_writer.h"
#include "povray/pov_export.h"
#include "render/patterns/pattern_point.h"

#include <catch2/catch.hpp>

#include <string>
#include <variant>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kWarped =
    "<sphere><material><pattern type=\"bozo\" transform=\"scale(2)\">"
    "<warp type=\"transform\" transform=\"translate(1 0 0)\"/>"
    "<warp type=\"repeat\" direction=\"2 0 0\" offset=\"0 0.5 0\" flip=\"0 1 0\"/>"
    "<warp type=\"black-hole\" center=\"0.5 0.5 0\" radius=\"0.5\" strength=\"0.75\" "
    "falloff=\"3\" inverse=\"true\" repeat=\"2 2 0\" turbulence=\"0.5 0.25 0\"/>"
    "<warp type=\"turbulence\" turbulence=\"0.3 0.2 0.1\" octaves=\"3\" lambda=\"2.5\"/>"
    "<warp type=\"planar\" normal=\"0 2 0\" distance=\"0.5\"/>"
    "<warp type=\"spherical\" orientation=\"1 0 0\" dist-exp=\"1\"/>"
    "<warp type=\"cylindrical\"/>"
    "<warp type=\"toroidal\" major-radius=\"2\"/>"
    "<warp type=\"cubic\"/>"
    "<color-map><entry at=\"0\" color=\"0\"/><entry at=\"1\" color=\"1\"/></color-map>"
    "</pattern></material></sphere>";

const PatternPlacement& placementOf(const Scene& s) {
  for (const Material& m : s.materials)
    if (const auto* p = std::get_if<PatternTexture>(&m.texture)) return p->pattern.placement;
  FAIL("no pattern");
  throw 0;
}

}  // namespace

TEST_CASE("warps: each type's attributes, in the order written", "[lang][warp]") {
  auto scene = parseClean(kWarped, "warps.xml");
  const PatternPlacement& p = placementOf(*scene);
  REQUIRE(p.warps.size() == 9);
  CHECK(p.patternFromObject[0][0] == 0.5);
  CHECK(std::get<TransformWarp>(p.warps[0]).patternFromPrevious[3] == Vec4(-1, 0, 0, 1));
  const auto& r = std::get<RepeatWarp>(p.warps[1]);
  CHECK(r.axis == 0);
  CHECK(r.width == 2.0);
  CHECK(r.offset == Vec3(0.0, 0.5, 0.0));
  CHECK((!r.flip[0] && r.flip[1] && !r.flip[2]));
  const auto& h = std::get<BlackHoleWarp>(p.warps[2]);
  CHECK(h.center == Vec3(0.5, 0.5, 0.0));
  CHECK(h.radius == 0.5);
  CHECK(h.strength == 0.75);
  CHECK(h.falloff == 3.0);
  CHECK(h.inverse);
  CHECK(h.repeat == Vec3(2.0, 2.0, 0.0));
  CHECK(h.turbulence == Vec3(0.5, 0.25, 0.0));
  const auto& t = std::get<TurbulenceWarp>(p.warps[3]);
  CHECK(t.strength == Vec3(0.3, 0.2, 0.1));
  CHECK(t.octaves == 3);
  CHECK(t.omega == 0.5);
  CHECK(t.lambda == 2.5);
  const auto& planar = std::get<MappingWarp>(p.warps[4]);
  CHECK(planar.kind == MappingWarpKind::planar);
  CHECK(planar.orientation == Vec3(0.0, 1.0, 0.0));  // normalised
  CHECK(planar.distance == 0.5);
  const auto& sphere = std::get<MappingWarp>(p.warps[5]);
  CHECK(sphere.kind == MappingWarpKind::spherical);
  CHECK(sphere.orientation == Vec3(1.0, 0.0, 0.0));
  CHECK(sphere.distExp == 1.0);
  const auto& cyl = std::get<MappingWarp>(p.warps[6]);
  CHECK(cyl.orientation == Vec3(0.0, 0.0, 1.0));
  CHECK(cyl.distExp == 0.0);
  CHECK(std::get<MappingWarp>(p.warps[7]).majorRadius == 2.0);
  CHECK(std::get<MappingWarp>(p.warps[8]).kind == MappingWarpKind::cubic);
}

TEST_CASE("warps: the point goes through the transform, the warps last first, the turbulence",
          "[lang][warp]") {
  auto scene = parseClean(
      "<sphere><material><pattern type=\"bozo\" transform=\"scale(2)\">"
      "<warp type=\"transform\" transform=\"translate(1 0 0)\"/>"
      "<warp type=\"repeat\" direction=\"2 0 0\"/></pattern></material></sphere>",
      "warps.xml");
  // (7, 1, 1): halved (3.5, 0.5, 0.5), repeated (1.5, ...), moved back by x.
  CHECK(warpPoint(placementOf(*scene), Vec3(7.0, 1.0, 1.0)) == Vec3(0.5, 0.5, 0.5));
}

TEST_CASE("warps: convert writes them back in their order and they read back the same",
          "[lang][warp][scene-writer]") {
  const std::string first = writeSceneXml(*parseClean(kWarped, "warps.xml"), WriteOptions{});
  CHECK(first.find("<warp type=\"repeat\" direction=\"2 0 0\" offset=\"0 0.5 0\" "
                   "flip=\"0 1 0\"/>") != std::string::npos);
  CHECK(first.find("<warp type=\"cubic\"/>") != std::string::npos);
  CHECK(first.find("type=\"transform\"") < first.find("type=\"repeat\""));
  CHECK(first.find("type=\"toroidal\"") < first.find("type=\"cubic\""));
  auto reread = parseSceneString(first, "warps.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("warps: export-pov writes POV-Ray's warp blocks before the placement's transform",
          "[lang][warp][povray]") {
  auto scene = parseClean(kWarped, "warps.xml");
  const PovExport e = exportPov(*scene);
  auto at = [&](const std::string& s) {
    const size_t k = e.text.find(s);
    INFO(e.text);
    CHECK(k != std::string::npos);
    return k;
  };
  const size_t repeat = at("warp { repeat <2, 0, 0> offset <0, 0.5, 0> flip <0, 1, 0> }");
  const size_t hole =
      at("warp { black_hole <0.5, 0.5, 0>, 0.5 strength 0.75 falloff 3 inverse repeat <2, 2, 0> "
         "turbulence <0.5, 0.25, 0> }");
  const size_t turb = at("warp { turbulence <0.3, 0.2, 0.1> octaves 3 omega 0.5 lambda 2.5 }");
  const size_t planar = at("warp { planar <0, 1, 0>, 0.5 }");
  at("warp { spherical orientation <1, 0, 0> dist_exp 1 }");
  at("warp { toroidal orientation <0, 0, 1> dist_exp 0 major_radius 2 }");
  const size_t cubic = at("warp { cubic }");
  CHECK(repeat < hole);
  CHECK(hole < turb);
  CHECK(turb < planar);
  CHECK(planar < cubic);
}
