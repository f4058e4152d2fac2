// <fog>: its attributes and defaults, read into Scene::fog; a scene without one has none.
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
  CHECK_FALSE(parse("")->fog);

  auto s = parse("<fog color=\"0.7 0.8 0.9\" distance=\"12\"/>");
  REQUIRE(s->fog);
  CHECK(s->fog->type == FogType::Constant);
  CHECK(s->fog->color == Color(0.7f, 0.8f, 0.9f));
  CHECK(s->fog->distance == 12.0);
  CHECK(s->fog->filter == 0.0f);
  CHECK(s->fog->transmit == 0.0f);

  s = parse(
      "<fog type=\"ground\" color=\"1\" distance=\"3\" filter=\"0.25\" transmit=\"0.5\" "
      "offset=\"-1\" "
      "altitude=\"0.4\" up=\"0 2 0\"/>");
  REQUIRE(s->fog);
  CHECK(s->fog->type == FogType::Ground);
  CHECK(s->fog->filter == 0.25f);
  CHECK(s->fog->transmit == 0.5f);
  CHECK(s->fog->offset == -1.0);
  CHECK(s->fog->altitude == 0.4);
  CHECK(s->fog->up == Vec3(0, 1, 0));  // normalised

  s = parse("<fog type=\"ground\" color=\"1\" distance=\"3\"/>");
  CHECK(s->fog->offset == 0.0);
  CHECK(s->fog->altitude == 1.0);
  CHECK(s->fog->up == Vec3(0, 1, 0));
}
