// <camera type="spherical">: h-angle and v-angle (POV-Ray's `angle H, V`), v-angle half of
// h-angle unless given, their ranges, and fov, which frames nothing here.
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

ParseResult parseCamera(const std::string& camera) {
  return parseBody("<sphere/>", "pano.xml", "\n" + camera);
}

const Camera& onlyCamera(const std::unique_ptr<Scene>& s) {
  REQUIRE(s->cameras.size() == 1);
  return s->cameras[0];
}

}  // namespace

TEST_CASE("lang: a spherical camera sees 360 x 180 degrees unless told, v-angle h-angle/2",
          "[lang][camera][spherical]") {
  auto s = parseClean("", "pano.xml", "<camera type=\"spherical\"/>");
  CHECK(onlyCamera(s).type == CameraType::Spherical);
  CHECK(onlyCamera(s).hAngle == 360.0);
  CHECK(onlyCamera(s).vAngle == 180.0);

  s = parseClean("", "pano.xml", "<camera type=\"spherical\" h-angle=\"120\"/>");
  CHECK(onlyCamera(s).hAngle == 120.0);
  CHECK(onlyCamera(s).vAngle == 60.0);

  s = parseClean("<param name=\"h\" value=\"90\"/>", "pano.xml",
                 "<camera type=\"spherical\" h-angle=\"${h * 2}\" v-angle=\"$h\"/>");
  CHECK(onlyCamera(s).hAngle == 180.0);
  CHECK(onlyCamera(s).vAngle == 90.0);

  s = parseClean("", "pano.xml", "<camera type=\"spherical\" v-angle=\"30\"/>");
  CHECK(onlyCamera(s).hAngle == 360.0);
  CHECK(onlyCamera(s).vAngle == 30.0);
}

TEST_CASE("lang: a spherical camera's angles out of range are located errors",
          "[lang][camera][spherical]") {
  ParseResult r = parseCamera(R"(<camera type="spherical" h-angle="0" v-angle="180.5"/>)");
  CHECK(messages(r) ==
        "pano.xml:2:35: error: <camera> attribute 'h-angle': expected an angle above 0 and at "
        "most 360, got '0'\n"
        "pano.xml:2:47: error: <camera> attribute 'v-angle': expected an angle above 0 and at "
        "most 180, got '180.5'\n");

  r = parseCamera(R"(<camera type="spherical" h-angle="360.001" v-angle="-1"/>)");
  CHECK(messages(r) ==
        "pano.xml:2:35: error: <camera> attribute 'h-angle': expected an angle above 0 and at "
        "most 360, got '360.001'\n"
        "pano.xml:2:53: error: <camera> attribute 'v-angle': expected an angle above 0 and at "
        "most 180, got '-1'\n");
}

TEST_CASE("lang: h-angle and v-angle belong to spherical cameras, fov frames nothing there",
          "[lang][camera][spherical]") {
  ParseResult r = parseCamera(R"(<camera h-angle="90"/>)");
  CHECK(messages(r) ==
        "pano.xml:2:9: error: <camera> attribute 'h-angle': belongs to spherical cameras; this "
        "camera is pinhole (set type=\"spherical\")\n");

  r = parseCamera(R"(<camera type="fisheye" v-angle="90"/>)");
  CHECK(messages(r) ==
        "pano.xml:2:24: error: <camera> attribute 'v-angle': belongs to spherical cameras; this "
        "camera is fisheye (set type=\"spherical\")\n");

  // fov is a common attribute (docs/scene-language.md) with no effect here: a warning that
  // names the attributes that frame the image, and the angles stay as they were.
  r = parseCamera(R"(<camera type="spherical" fov="90" fov-axis="vertical"/>)");
  REQUIRE(r.scene);
  CHECK(r.diagnostics.errorCount() == 0);
  CHECK(messages(r) ==
        "pano.xml:2:1: warning: <camera>: 'fov' has no effect on cameras of type spherical "
        "(their 'h-angle' and 'v-angle' frame the image)\n"
        "pano.xml:2:1: warning: <camera>: 'fov-axis' has no effect on cameras of type spherical "
        "(their 'h-angle' and 'v-angle' frame the image)\n");
  CHECK(r.scene->cameras[0].hAngle == 360.0);
  CHECK(r.scene->cameras[0].vAngle == 180.0);
}
