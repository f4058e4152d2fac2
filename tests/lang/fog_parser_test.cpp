// <fog>: its attributes and defaults, read into Scene::fogs; a scene without one has none.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) { return parseClean(body, "fog.xml"); }

}  // namespace

TEST_CASE("lang: <fog> is constant fog by default, ground fog takes offset, altitude and up",
          "[lang][fog]") {
  CHECK(parse("")->fogs.empty());

  auto s = parse("<fog color=\"0.7 0.8 0.9\" distance=\"12\"/>");
  REQUIRE(s->fogs.size() == 1);
  CHECK(s->fogs[0].type == FogType::Constant);
  CHECK(s->fogs[0].color == Color(0.7f, 0.8f, 0.9f));
  CHECK(s->fogs[0].distance == 12.0);
  CHECK(s->fogs[0].filter == 0.0f);
  CHECK(s->fogs[0].transmit == 0.0f);

  s = parse(
      "<fog type=\"ground\" color=\"1\" distance=\"3\" filter=\"0.25\" transmit=\"0.5\" "
      "offset=\"-1\" "
      "altitude=\"0.4\" up=\"0 2 0\"/>");
  REQUIRE(s->fogs.size() == 1);
  CHECK(s->fogs[0].type == FogType::Ground);
  CHECK(s->fogs[0].filter == 0.25f);
  CHECK(s->fogs[0].transmit == 0.5f);
  CHECK(s->fogs[0].offset == -1.0);
  CHECK(s->fogs[0].altitude == 0.4);
  CHECK(s->fogs[0].up == Vec3(0, 1, 0));  // normalised

  s = parse("<fog type=\"ground\" color=\"1\" distance=\"3\"/>");
  CHECK(s->fogs[0].offset == 0.0);
  CHECK(s->fogs[0].altitude == 1.0);
  CHECK(s->fogs[0].up == Vec3(0, 1, 0));
}

TEST_CASE("lang: several <fog>s all stay, in order, with turbulence and its parameters",
          "[lang][fog]") {
  auto s = parse(
      "<fog color=\"1\" distance=\"3\"/>"
      "<fog type=\"ground\" color=\"0 0 1\" distance=\"2\" turbulence=\"0.2\"/>"
      "<fog color=\"0.5\" distance=\"9\" turbulence=\"0.1 0.2 0.3\" octaves=\"4\" "
      "omega=\"0.35\" lambda=\"1.25\" turb-depth=\"0.9\" noise-generator=\"1\" "
      "transform=\"scale(2)\"/>");
  REQUIRE(s->fogs.size() == 3);
  CHECK(s->fogs[0].distance == 3.0);
  CHECK_FALSE(s->fogs[0].turbulence);
  REQUIRE(s->fogs[1].turbulence);
  const FogTurbulence& d = *s->fogs[1].turbulence;  // POV-Ray's defaults
  CHECK(d.strength == Vec3(0.2));
  CHECK(d.octaves == 6);
  CHECK(d.omega == 0.5);
  CHECK(d.lambda == 2.0);
  CHECK(d.depth == 0.5);
  CHECK(d.noiseGenerator == 2);
  CHECK(d.noiseFromWorld == Mat4(1.0));
  REQUIRE(s->fogs[2].turbulence);
  const FogTurbulence& t = *s->fogs[2].turbulence;
  CHECK(t.strength == Vec3(0.1, 0.2, 0.3));
  CHECK(t.octaves == 4);
  CHECK(t.omega == 0.35);
  CHECK(t.lambda == 1.25);
  CHECK(t.depth == 0.9);
  CHECK(t.noiseGenerator == 1);
  CHECK(t.noiseFromWorld[0][0] == 0.5);
}
