// The warning for a camera inside an opaque solid (scenegraph/camera_inside.h): where it is
// given, its text, and the cameras and solids that must not get it.
#include <catch2/catch.hpp>

#include "lang/parser.h"

#include <string>
#include <vector>

using namespace lucent;

namespace {

// The diagnostics of a scene whose body follows a 16x12 <render> (with `render` attributes
// too) on line 2.
std::vector<std::string> messages(const std::string& body, const std::string& render = "") {
  ParseResult r = parseSceneString("<scene version=\"1\">\n  <render width=\"16\" height=\"12\"" +
                                       render + "/>\n" + body + "</scene>\n",
                                   "cam.xml");
  REQUIRE(r.scene);
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics.all()) out.push_back(d.str());
  return out;
}

const char* kFloor =
    "  <plane normal=\"0 1 0\" offset=\"0\">\n"
    "    <material ambient=\"0.2\" diffuse=\"0.7\"/>\n"
    "  </plane>\n";

}  // namespace

TEST_CASE("lang: a camera below a plane whose normal points up is warned about, at the plane",
          "[lang][camera-inside]") {
  auto m = messages("  <camera position=\"0 -1 3\" look-at=\"0 1 0\"/>\n" + std::string(kFloor));
  REQUIRE(m.size() == 1);
  CHECK(m[0] ==
        "cam.xml:4:3: warning: the camera at cam.xml:3:3 is inside this opaque <plane>: its rays "
        "start inside it, so the surfaces they meet from inside lose their ambient term (inside "
        "an object it is multiplied by the transmissive colour, 0 here); to put the camera "
        "outside and keep the surface, negate the normal and the offset: normal=\"0 -1 0\" "
        "offset=\"0\"");
}

TEST_CASE("lang: a camera above the same plane gets no warning", "[lang][camera-inside]") {
  CHECK(
      messages("  <camera position=\"0 1 3\" look-at=\"0 0 0\"/>\n" + std::string(kFloor)).empty());
}

TEST_CASE("lang: the plane's fix negates its offset too", "[lang][camera-inside]") {
  auto m = messages(
      "  <camera position=\"0 0 3\" look-at=\"0 1 0\"/>\n"
      "  <plane normal=\"0 2 0\" offset=\"0.5\"><material ambient=\"0.1\"/></plane>\n");
  REQUIRE(m.size() == 1);
  CHECK_THAT(m[0], Catch::EndsWith("negate the normal and the offset: normal=\"0 -1 0\" "
                                   "offset=\"-0.5\""));
}

TEST_CASE("lang: the camera's transform and names, groups, <use> and CSG are followed",
          "[lang][camera-inside]") {
  // Camera "out" at z = 6; camera "in" moved by its transform to the ball's centre, which a
  // <use> of a group puts at x = 4.
  auto m = messages(
      "  <camera name=\"out\" position=\"0 0 6\"/>\n"
      "  <camera name=\"in\" position=\"0 0 0\" look-at=\"0 0 -1\" transform=\"translate(4 0 "
      "0)\"/>\n"
      "  <material id=\"clay\" ambient=\"0.1\" diffuse=\"0.6\"/>\n"
      "  <defs><group id=\"g\" transform=\"translate(1 0 0)\"><sphere "
      "radius=\"0.5\"/></group></defs>\n"
      "  <use ref=\"g\" material=\"clay\" transform=\"translate(3 0 0)\"/>\n"
      "  <difference material=\"clay\" transform=\"translate(0 0 6)\">\n"
      "    <box/>\n"
      "    <sphere radius=\"0.5\"/>\n"
      "  </difference>\n");
  REQUIRE(m.size() == 1);
  CHECK_THAT(m[0], Catch::StartsWith("cam.xml:6:52: warning: camera \"in\" (cam.xml:4:3) is "
                                     "inside this opaque <sphere>:"));
  CHECK_THAT(m[0], Catch::EndsWith("; move the camera out of it"));

  // Camera "out" sits in the difference's hole; moved into its solid part, it is inside.
  auto solid = messages(
      "  <camera position=\"0 0.8 6\"/>\n"
      "  <difference transform=\"translate(0 0 6)\">\n"
      "    <box><material ambient=\"0.1\"/></box>\n"
      "    <sphere radius=\"0.5\"/>\n"
      "  </difference>\n");
  REQUIRE(solid.size() == 1);
  CHECK_THAT(solid[0], Catch::StartsWith("cam.xml:4:3: warning: the camera at cam.xml:3:3 is "
                                         "inside this opaque <difference>:"));
}

TEST_CASE("lang: no warning inside glass, an emissive dome, or without ambient light",
          "[lang][camera-inside]") {
  const std::string camera = "  <camera position=\"0 0 0\" look-at=\"0 0 -1\"/>\n";
  CHECK(messages(camera + "  <sphere radius=\"2\"><material transmissive=\"0.9\" ior=\"1.33\" "
                          "ambient=\"0.1\"/></sphere>\n")
            .empty());
  CHECK(messages(camera + "  <sphere radius=\"50\"><material emissive=\"0.5 0.6 0.9\"/></sphere>\n")
            .empty());
  CHECK(messages(camera + "  <sphere radius=\"2\"><material ambient=\"0.1\"/></sphere>\n",
                 " ambient=\"0\"")
            .empty());
  // The same opaque sphere with ambient light: warned.
  CHECK(messages(camera + "  <sphere radius=\"2\"><material ambient=\"0.1\"/></sphere>\n").size() ==
        1);
}
