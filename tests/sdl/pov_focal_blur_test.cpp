// POV-Ray's focal blur read by the scene reader: aperture, blur_samples [MIN,] MAX,
// confidence, variance and focal_point become Lucent's <focal-blur> (half the aperture
// across; the focus on the view axis at POV-Ray's focal distance), with POV-Ray's checks.
#include "scene_read_support.h"

using namespace lucent;
using namespace sdltest;

namespace {

std::string scene(const std::string& cameraModifiers) {
  return "camera { location <0, 1, -5> look_at <0, 1, 0> " + cameraModifiers +
         " }\nsphere { 0, 1 pigment { rgb 1 } }\n";
}

bool warned(const Read& r, const std::string& words) {
  for (const std::string& w : r.out.warnings)
    if (w.find(words) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("POV-Ray focal blur: aperture, samples, confidence, variance and focal point",
          "[sdl][camera][focal-blur]") {
  auto r = readScene(scene(
      "aperture 0.8 blur_samples 12, 40 confidence 0.95 variance 1/256 focal_point <3, 1, -1>"));
  REQUIRE(r->load.scene);
  const Camera& c = r->load.scene->cameras.front();
  REQUIRE(c.focalBlur);
  CHECK(c.focalBlur->aperture == 0.4);  // POV-Ray's lens points lie within aperture/4
  CHECK(c.focalBlur->samples == 40);
  CHECK(c.focalBlur->minSamples == 12);
  CHECK(c.focalBlur->confidence == 0.95);
  CHECK(c.focalBlur->variance == 1.0 / 256.0);
  // |focal_point − location| = 5, on the view axis (Lucent's z is POV-Ray's −z).
  REQUIRE(c.focalBlur->focalPoint);
  checkVec(*c.focalBlur->focalPoint, c.position + 5.0 * glm::normalize(c.lookAt - c.position));
  checkVec(c.position, Vec3(0.0, 1.0, 5.0));
}

TEST_CASE("POV-Ray focal blur: without a focal point the focus is at |direction|",
          "[sdl][camera][focal-blur]") {
  auto r = readScene(scene("direction <0, 0, 2.5> aperture -1 blur_samples 9"));
  REQUIRE(r->load.scene);
  const Camera& c = r->load.scene->cameras.front();
  REQUIRE(c.focalBlur);
  CHECK(c.focalBlur->aperture == 0.5);  // a negative aperture mirrors the lens
  CHECK(c.focalBlur->samples == 9);
  CHECK(c.focalBlur->minSamples == 0);
  REQUIRE(c.focalBlur->focalPoint);
  CHECK(glm::length(*c.focalBlur->focalPoint - c.position) == Approx(2.5));
}

TEST_CASE("POV-Ray focal blur: off without an aperture or without samples",
          "[sdl][camera][focal-blur]") {
  for (const char* modifiers : {"blur_samples 20", "aperture 1", "aperture 0 blur_samples 20"}) {
    auto r = readScene(scene(modifiers));
    REQUIRE(r->load.scene);
    CHECK(!r->load.scene->cameras.front().focalBlur);
  }
}

TEST_CASE("POV-Ray focal blur: POV-Ray's warnings and errors", "[sdl][camera][focal-blur]") {
  SECTION("a confidence or variance out of range keeps the default, warned") {
    auto r = readScene(scene("aperture 1 blur_samples 10 confidence 1 variance 2"));
    REQUIRE(r->load.scene);
    CHECK(r->load.scene->cameras.front().focalBlur->confidence == 0.9);
    CHECK(r->load.scene->cameras.front().focalBlur->variance == 1.0 / 10000.0);
    CHECK(warned(*r, "illegal confidence value 1"));
    CHECK(warned(*r, "illegal variance value 2"));
  }
  SECTION("no samples") {
    const auto errors = errorsOf(scene("aperture 1 blur_samples 0"));
    REQUIRE(!errors.empty());
    CHECK_THAT(errors[0], Catch::Contains("illegal number of focal blur samples"));
  }
  SECTION("a minimum above the maximum") {
    const auto errors = errorsOf(scene("aperture 1 blur_samples 30, 20"));
    REQUIRE(!errors.empty());
    CHECK_THAT(errors[0], Catch::Contains("minimum must not be larger than maximum"));
  }
  SECTION("bokeh") {
    const auto errors = errorsOf(scene("aperture 1 blur_samples 20 bokeh { pigment { rgb 1 } }"));
    REQUIRE(!errors.empty());
    CHECK_THAT(errors[0], Catch::Contains("'bokeh'"));
  }
  SECTION("an orthographic camera: POV-Ray 3.7.0 starts every ray at the location") {
    auto r = readScene(
        "camera { orthographic location <0, 1, -5> look_at <0, 1, 0> aperture 1 "
        "blur_samples 10 }\nsphere { 0, 1 pigment { rgb 1 } }\n");
    REQUIRE(r->load.scene);
    CHECK(r->load.scene->cameras.front().focalBlur);
    CHECK(warned(*r, "starts every ray"));
  }
}
