// Cameras in POV-Ray: handedness through `right -x*W/H`, the field of view as `angle`, the
// frame after the camera's transform, and the types POV-Ray cannot express.
#include "pov_test_support.h"

#include "povray/pov_camera.h"

#include <cmath>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("pinhole camera becomes a perspective camera with negative handedness",
          "[povray][camera]") {
  Exported e = exportScene(R"XML(<render width="640" height="480"/>
      <camera position="0 2 8" look-at="0 1 0" up="0 1 0" fov="50"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("camera {\n"
            "  perspective\n"
            "  right -x*640/480\n"
            "  up y\n"
            "  angle 50\n"
            "  location <0, 2, 8>\n"
            "  sky <0, 1, 0>\n"
            "  look_at <0, 1, 0>\n"
            "}\n"));
}

TEST_CASE("vertical and diagonal fov are turned into POV-Ray's horizontal angle",
          "[povray][camera]") {
  Camera c;
  c.fov = 40.0;
  c.fovAxis = FovAxis::Vertical;
  // tan(h/2) = tan(v/2) * W/H
  double expected = 2.0 * std::atan(std::tan(radians(20.0)) * 800.0 / 600.0) * 180.0 / kPi;
  CHECK(horizontalFovDegrees(c, 800, 600) == Approx(expected).epsilon(1e-14));
  c.fovAxis = FovAxis::Diagonal;
  expected = 2.0 * std::atan(std::tan(radians(20.0)) * 800.0 / 1000.0) * 180.0 / kPi;
  CHECK(horizontalFovDegrees(c, 800, 600) == Approx(expected).epsilon(1e-14));
  c.fovAxis = FovAxis::Horizontal;
  CHECK(horizontalFovDegrees(c, 800, 600) == 40.0);
}

TEST_CASE("the camera transform moves location, look_at and sky as the renderer does",
          "[povray][camera]") {
  Exported e = exportScene(R"XML(<camera position="0 0 5" look-at="0 0 0"
                                      transform="rotate-y(90) translate(1 0 0)"/>)XML");
  REQUIRE(e.pov.ok());
  // rotate-y(90) takes (0 0 5) to (5 0 0); then +1 in x.
  CHECK(e.has("  location <6, 0, 0>\n  sky <0, 1, 0>\n  look_at <1, 0, 0>\n"));
}

TEST_CASE("orthographic and fisheye cameras keep explicit right and up", "[povray][camera]") {
  Exported ortho = exportScene(R"XML(<render width="400" height="300"/>
      <camera type="orthographic" position="0 10 0" look-at="0 0 0" up="0 0 -1" width="12"/>)XML");
  REQUIRE(ortho.pov.ok());
  CHECK(ortho.has("  orthographic\n  right -x*12\n  up y*12*300/400\n"));
  CHECK(ortho.has("  sky <0, 0, -1>\n"));

  // POV-Ray's image circle is r = 1 with u, v in [-1, 1] scaled by |right|, |up|; the
  // renderer's circle spans the width (fov-axis horizontal), height or diagonal.
  Exported fish = exportScene(R"XML(<render width="400" height="300"/>
      <camera type="fisheye" position="0 0 0" look-at="0 1 0" up="0 0 -1" fov="180"/>)XML");
  REQUIRE(fish.pov.ok());
  CHECK(fish.has("  fisheye\n  right -x*1\n  up y*300/400\n  angle 180\n"));

  Exported tall = exportScene(R"XML(<render width="400" height="300"/>
      <camera type="fisheye" fov="200" fov-axis="vertical"/>)XML");
  CHECK(tall.has("  fisheye\n  right -x*400/300\n  up y*1\n  angle 200\n"));

  Exported full = exportScene(R"XML(<render width="400" height="300"/>
      <camera type="fisheye" fov="150" fov-axis="diagonal"/>)XML");
  CHECK(full.has("  fisheye\n  right -x*0.8\n  up y*0.6\n  angle 150\n"));
}

TEST_CASE("a spherical camera is POV-Ray's spherical with both angles and the sky reversed",
          "[povray][camera]") {
  // POV-Ray turns the longitude about up whatever the sign of right, and the latitude about
  // right: `right -x` with the sky reversed puts +right at 3/4 of the width and up at the
  // top, as the renderer does (checked against POV-Ray 3.7 by gallery/camera-spherical).
  Exported e = exportScene(R"XML(<render width="400" height="200"/>
      <camera type="spherical" position="0 1 5" look-at="0 1 0" h-angle="300"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.messages().empty());
  CHECK(
      e.has("camera {\n"
            "  spherical\n"
            "  angle 300, 150\n"
            "  right -x\n"
            "  up y\n"
            "  location <0, 1, 5>\n"
            "  sky <0, -1, 0>\n"
            "  look_at <0, 1, 0>\n"
            "}\n"));

  // The sky is the renderer's up after the camera's transform, reversed.
  Exported turned = exportScene(R"XML(<camera type="spherical" v-angle="90" up="0 1 0"
      transform="rotate-z(90)"/>)XML");
  REQUIRE(turned.pov.ok());
  CHECK(
      turned.has("  angle 360, 90\n  right -x\n  up y\n  location <0, 0, 0>\n"
                 "  sky <1, 0, 0>\n  look_at <0, 0, -1>\n"));
}

TEST_CASE("cameras POV-Ray cannot express are errors naming the element and location",
          "[povray][camera]") {
  Exported lens =
      exportScene(R"XML(<camera type="thin-lens" position="0 1 4" look-at="0 1 0"/>)XML");
  CHECK_FALSE(lens.pov.ok());
  CHECK(lens.pov.text.empty());
  REQUIRE(lens.pov.issues.size() == 1);
  CHECK(lens.pov.issues[0].str() ==
        "test.xml:2:1: error: <camera type=\"thin-lens\">: POV-Ray has no equivalent camera "
        "(pinhole, orthographic, equidistant fisheye, spherical, ultra-wide-angle, cylinder, "
        "panoramic, omnimax and mesh can be exported)");

  Exported equisolid = exportScene(R"XML(<camera type="fisheye" mapping="equisolid"/>)XML");
  REQUIRE(equisolid.pov.issues.size() == 1);
  CHECK(equisolid.pov.issues[0].str() ==
        "test.xml:2:1: error: fisheye camera: mapping 'equisolid' has no POV-Ray equivalent "
        "(POV-Ray's fisheye is equidistant)");

  Exported clipped = exportScene(R"XML(<camera name="main" near="0.5"/>)XML");
  CHECK_FALSE(clipped.pov.ok());
  CHECK(clipped.messages() ==
        "test.xml:2:1: error: camera 'main': near/far clipping has no "
        "POV-Ray equivalent (POV-Ray cameras do not clip)\n");
}

TEST_CASE("a fisheye on a coloured background warns that POV-Ray leaves the corners black",
          "[povray][camera]") {
  Exported diagonal =
      exportScene(R"XML(<camera type="fisheye" fov-axis="diagonal"/><render background="1"/>)XML");
  CHECK(diagonal.pov.issues.empty());

  Exported e = exportScene(R"XML(<camera type="fisheye"/><render background="0.2 0.3 0.4"/>)XML");
  CHECK(e.pov.ok());
  CHECK(e.messages() ==
        "test.xml:2:1: warning: fisheye camera: POV-Ray leaves the pixels "
        "outside the image circle black; Lucent gives them the background\n");
}

TEST_CASE("render settings become global_settings and background after #version 3.7",
          "[povray][settings]") {
  Exported e = exportScene(R"XML(<render width="64" height="48" max-depth="7" min-weight="0.01"
        background="0.1 0.2 0.3" ambient="0.5 0.5 0.4" epsilon="1e-4"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.text.find("#version 3.7;\n") < e.pov.text.find("global_settings"));
  CHECK(
      e.has("global_settings {\n  assumed_gamma 1.0\n  max_trace_level 7\n"
            "  adc_bailout 0.01\n  ambient_light rgb <0.5, 0.5, 0.4>\n}\n"
            "background { rgb <0.1, 0.2, 0.3> }\n"));
  CHECK(e.messages() ==
        "test.xml:3:1: warning: render: epsilon 0.0001 has no POV-Ray "
        "equivalent (POV-Ray ignores hits closer than its own fixed "
        "tolerances)\n");
}

TEST_CASE("a working gamma is exported as POV-Ray's assumed_gamma", "[povray][settings][gamma]") {
  Exported power = exportScene(R"XML(<render working-gamma="2.2"/>)XML");
  REQUIRE(power.pov.ok());
  CHECK(power.has("global_settings {\n  assumed_gamma 2.2\n"));
  Exported srgb = exportScene(R"XML(<render working-gamma="srgb"/>)XML");
  REQUIRE(srgb.pov.ok());
  CHECK(srgb.has("global_settings {\n  assumed_gamma srgb\n"));
}

TEST_CASE("every camera type without a POV-Ray twin is refused by name, with no scene written",
          "[povray][camera]") {
  // POV-Ray 3.7's cameras are perspective, orthographic, fisheye (equidistant), ultra_wide_angle,
  // omnimax, panoramic, cylinder and spherical (latitude-longitude); none of them is a thin
  // lens with deterministic samples, a Panini, a lenslet grid, an octahedral map, a cube map
  // or a Fibonacci sphere.
  for (const char* camera :
       {R"(<camera type="thin-lens"/>)", R"(<camera type="panini" distance="0.5"/>)",
        R"(<camera type="lenslet" lenses="2 2"/>)", R"(<camera type="octahedral"/>)",
        R"(<camera type="cubemap" layout="strip"/>)", R"(<camera type="fibonacci"/>)"}) {
    std::string xml = camera;
    std::string type = xml.substr(xml.find("type=\"") + 6);
    type = type.substr(0, type.find('"'));
    INFO(type);
    Exported e = exportScene(xml);
    CHECK_FALSE(e.pov.ok());
    CHECK(e.pov.text.empty());
    CHECK(e.messages() == "test.xml:2:1: error: <camera type=\"" + type +
                              "\">: POV-Ray has no equivalent camera (pinhole, orthographic, "
                              "equidistant fisheye, spherical, ultra-wide-angle, cylinder, "
                              "panoramic, omnimax and mesh can be "
                              "exported)\n");
  }
}
