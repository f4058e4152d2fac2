// <camera type="ultra-wide-angle|cylinder|panoramic|omnimax">: their attributes, defaults,
// ranges and located errors, and the attributes they do not take.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

ParseResult parseCamera(const std::string& camera) {
  return parseBody("<sphere/>", "cams.xml", "\n" + camera);
}

const Camera& onlyCamera(const std::unique_ptr<Scene>& s) {
  REQUIRE(s->cameras.size() == 1);
  return s->cameras[0];
}

}  // namespace

TEST_CASE("lang: the POV-Ray family of cameras and their defaults", "[lang][camera]") {
  auto s = parseClean("", "cams.xml", "<camera type=\"ultra-wide-angle\" fov=\"220\"/>");
  CHECK(onlyCamera(s).type == CameraType::UltraWideAngle);
  CHECK(onlyCamera(s).fov == 220.0);
  CHECK(onlyCamera(s).frameAspect == 0.0);

  s = parseClean("", "cams.xml", "<camera type=\"cylinder\"/>");
  CHECK(onlyCamera(s).type == CameraType::Cylinder);
  CHECK(onlyCamera(s).cylinderType == 1);
  CHECK(onlyCamera(s).sweep == 90.0);
  CHECK(onlyCamera(s).axisLength == 0.0);
  s = parseClean("<param name=\"k\" value=\"2\"/>", "cams.xml",
                 "<camera type=\"cylinder\" cylinder-type=\"${k + 2}\" sweep=\"300\" "
                 "axis-length=\"2.5\"/>");
  CHECK(onlyCamera(s).cylinderType == 4);
  CHECK(onlyCamera(s).sweep == 300.0);
  CHECK(onlyCamera(s).axisLength == 2.5);

  s = parseClean("", "cams.xml", "<camera type=\"panoramic\"/>");
  CHECK(onlyCamera(s).type == CameraType::Panoramic);
  CHECK(onlyCamera(s).rightLength == 1.0);
  CHECK(onlyCamera(s).upLength == 1.0);
  s = parseClean("", "cams.xml",
                 "<camera type=\"panoramic\" right-length=\"1.33\" up-length=\"0.5\"/>");
  CHECK(onlyCamera(s).rightLength == 1.33);
  CHECK(onlyCamera(s).upLength == 0.5);

  s = parseClean("", "cams.xml", "<camera type=\"omnimax\" frame-aspect=\"1.2\"/>");
  CHECK(onlyCamera(s).type == CameraType::Omnimax);
  CHECK(onlyCamera(s).frameAspect == 1.2);
}

TEST_CASE("lang: the POV-Ray family's values out of range are located errors", "[lang][camera]") {
  ParseResult r = parseCamera(R"(<camera type="cylinder" cylinder-type="5"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:40: error: <camera> attribute 'cylinder-type': expected a whole number from "
        "1 to 4, got '5'\n");
  r = parseCamera(R"(<camera type="cylinder" cylinder-type="0" sweep="400"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:40: error: <camera> attribute 'cylinder-type': expected a whole number from "
        "1 to 4, got '0'\n"
        "cams.xml:2:50: error: <camera> attribute 'sweep': expected an angle above 0 and at most "
        "360, got '400'\n");
  r = parseCamera(R"(<camera type="cylinder" cylinder-type="2.5" axis-length="-1"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:40: error: <camera> attribute 'cylinder-type': expected a whole number, got "
        "'2.5'\n"
        "cams.xml:2:58: error: <camera> attribute 'axis-length': expected a number >= 0, got "
        "'-1'\n");
  r = parseCamera(R"(<camera type="panoramic" right-length="0" up-length="x"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:40: error: <camera> attribute 'right-length': expected a positive number, "
        "got '0'\n"
        "cams.xml:2:54: error: <camera> attribute 'up-length': expected a number, got 'x'\n");
  r = parseCamera(R"(<camera type="ultra-wide-angle" fov="361"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:38: error: <camera> attribute 'fov': expected an angle above 0 and at most "
        "360, got '361'\n");
}

TEST_CASE("lang: the POV-Ray family's attributes belong to their types", "[lang][camera]") {
  ParseResult r = parseCamera(R"(<camera cylinder-type="2"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:9: error: <camera> attribute 'cylinder-type': belongs to cylinder cameras; "
        "this camera is pinhole (set type=\"cylinder\")\n");
  r = parseCamera(R"(<camera type="omnimax" up-length="2"/>)");
  CHECK(messages(r) ==
        "cams.xml:2:24: error: <camera> attribute 'up-length': belongs to panoramic cameras; "
        "this camera is omnimax (set type=\"panoramic\")\n");
  // fov frames nothing on a cylinder (its sweep does), a panoramic or an omnimax camera.
  r = parseCamera(R"(<camera type="cylinder" fov="90"/>)");
  REQUIRE(r.scene);
  CHECK(messages(r) ==
        "cams.xml:2:1: warning: <camera>: 'fov' has no effect on cameras of type cylinder "
        "(their 'sweep' and 'axis-length' frame the image)\n");
  CHECK(r.scene->cameras[0].sweep == 90.0);
}
