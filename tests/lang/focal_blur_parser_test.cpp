// <camera><focal-blur/></camera>: read with its defaults, written back by the scene writer
// and read again the same; refused on a thin-lens camera and where a value is out of range.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("focal blur: read with POV-Ray's defaults", "[lang][camera][focal-blur]") {
  auto scene = parseClean("<sphere/>", "test.xml",
                          R"(<camera position="0 1 5"><focal-blur aperture="0.5"/></camera>)");
  const Camera& c = scene->cameras.front();
  REQUIRE(c.focalBlur);
  CHECK(c.focalBlur->aperture == 0.5);
  CHECK(!c.focalBlur->focalPoint);
  CHECK(c.focalBlur->samples == 37);
  CHECK(c.focalBlur->minSamples == 0);
  CHECK(c.focalBlur->confidence == 0.9);
  CHECK(c.focalBlur->variance == 1.0 / 10000.0);
  CHECK(c.focalBlur->loc.line == 1);
}

TEST_CASE("focal blur: written back and read again the same", "[lang][camera][focal-blur]") {
  auto scene = parseClean(
      "<sphere/>", "test.xml",
      R"(<camera type="orthographic" width="3" position="0 1 5"><normal type="bumps" depth="0.1"/><focal-blur aperture="0.25" focal-point="1 0.5 -2" samples="120" min-samples="12" confidence="0.95" variance="0.001953125"/></camera>)");
  const Camera& c = scene->cameras.front();
  REQUIRE(c.focalBlur);
  const std::string text = writeSceneXml(*scene, WriteOptions{});
  INFO(text);
  CHECK(text.find("<focal-blur aperture=\"0.25\"") != std::string::npos);
  ParseResult again = parseSceneString(text, "again.xml");
  INFO(messages(again));
  REQUIRE(again.scene);
  const Camera& back = again.scene->cameras.front();
  REQUIRE(back.focalBlur);
  REQUIRE(back.normal);
  CHECK(back.type == CameraType::Orthographic);
  CHECK(back.focalBlur->aperture == 0.25);
  CHECK(back.focalBlur->focalPoint == Vec3(1.0, 0.5, -2.0));
  CHECK(back.focalBlur->samples == 120);
  CHECK(back.focalBlur->minSamples == 12);
  CHECK(back.focalBlur->confidence == 0.95);
  CHECK(back.focalBlur->variance == 0.001953125);
}

TEST_CASE("focal blur: bad values and a thin-lens camera are errors at the focal blur",
          "[lang][camera][focal-blur]") {
  const auto errorOf = [](const std::string& camera) {
    ParseResult r = parseBody("<sphere/>", "test.xml", camera);
    INFO(messages(r));
    CHECK(!r.scene);
    return messages(r);
  };
  CHECK_THAT(errorOf(R"(<camera><focal-blur/></camera>)"),
             Catch::Contains("test.xml:1:28: error: <focal-blur> needs 'aperture'"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="0"/></camera>)"),
             Catch::Contains("attribute 'aperture': expected a positive number, got '0'"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1" samples="0"/></camera>)"),
             Catch::Contains("attribute 'samples'"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1" samples="8" min-samples="9"/></camera>)"),
             Catch::Contains("'min-samples' (9) must not exceed 'samples' (8)"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1" confidence="1"/></camera>)"),
             Catch::Contains("attribute 'confidence'"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1" variance="-0.1"/></camera>)"),
             Catch::Contains("attribute 'variance'"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1" focus="2"/></camera>)"),
             Catch::Contains("unknown attribute 'focus'"));
  CHECK_THAT(errorOf(R"(<camera type="thin-lens"><focal-blur aperture="1"/></camera>)"),
             Catch::Contains("a thin-lens camera has its own lens"));
  CHECK_THAT(errorOf(R"(<camera><focal-blur aperture="1"/><focal-blur aperture="2"/></camera>)"),
             Catch::Contains("<camera> holds one <focal-blur> at most"));
}
