// <rainbow> read and written back; the bad forms are in tests/bad/cases.txt.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kMap =
    "<color-map><entry at=\"0\" color=\"1 0 0\" filter=\"0.8\"/><entry at=\"1\" "
    "color=\"0 0 1\" transmit=\"0.5\"/></color-map>";

}  // namespace

TEST_CASE("a rainbow's attributes, its defaults and its frame", "[lang][rainbow]") {
  auto s = parseClean(std::string("<rainbow direction=\"0 0 -2\" angle=\"42\" width=\"5\" "
                                  "up=\"0 1 1\">") +
                      kMap + "</rainbow>");
  REQUIRE(s->rainbows.size() == 1);
  const Rainbow& r = s->rainbows[0];
  CHECK(r.direction == Vec3(0, 0, -2));  // as written
  CHECK(r.axis == Vec3(0, 0, -1));
  // Up made square to the direction, right = up × direction.
  CHECK(r.upAxis.x == Approx(0.0).margin(1e-15));
  CHECK(r.upAxis.y == Approx(1.0));
  CHECK(r.upAxis.z == Approx(0.0).margin(1e-15));
  CHECK(r.rightAxis.x == Approx(-1.0));
  CHECK(r.angle == 42.0);
  CHECK(r.width == 5.0);
  CHECK(r.distance == 1e7);
  CHECK(r.jitter == 0.0);
  CHECK(r.arcAngle == 360.0);
  CHECK(r.falloffAngle == 360.0);
  REQUIRE(r.map.entries.size() == 2);
  CHECK(r.map.entries[0].ft.filter == 0.8f);
  CHECK(r.map.entries[1].ft.transmit == 0.5f);
  // falloff-angle defaults to arc-angle.
  auto arc = parseClean(std::string("<rainbow direction=\"0 0 -1\" angle=\"42\" width=\"5\" "
                                    "arc-angle=\"120\">") +
                        kMap + "</rainbow>");
  CHECK(arc->rainbows[0].falloffAngle == 120.0);
}

TEST_CASE("rainbows are written and read back", "[lang][rainbow][scene-writer]") {
  const std::string first = writeSceneXml(
      *parseClean(std::string("<rainbow direction=\"-0.2 -0.2 -1\" angle=\"42.5\" width=\"5\" "
                              "distance=\"300\" jitter=\"0.01\" arc-angle=\"150\" "
                              "falloff-angle=\"90\">") +
                      kMap + "</rainbow><rainbow direction=\"0 0 -1\" angle=\"37\" width=\"4\">" +
                      kMap + "</rainbow>",
                  "writer.xml"),
      WriteOptions{});
  INFO(first);
  auto reread = parseSceneString(first, "writer.xml");
  INFO(messages(reread));
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
  REQUIRE(reread.scene->rainbows.size() == 2);
  const Rainbow& r = reread.scene->rainbows[0];
  CHECK(r.distance == 300.0);
  CHECK(r.jitter == 0.01);
  CHECK(r.arcAngle == 150.0);
  CHECK(r.falloffAngle == 90.0);
  CHECK(reread.scene->rainbows[1].angle == 37.0);
}
