// <light><projected-through> (POV-Ray's projected_through, its TracePointLightShadowRay):
// the light reaches a point only along a shadow ray that meets the objects before the
// light, and only what lies nearer than that meeting shadows it. Each scene is a white
// diffuse ball (diffuse 1, no ambient) of radius 0.9 at the origin, seen head on from +z
// and lit by a point light far along +z, so a lit centre is exactly 1 and a dark one 0.
#include "scene_builder.h"

#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> sceneOf(const std::string& body) {
  return parseClean(
      "<material id=\"white\" diffuse=\"1\"/>"
      "<sphere radius=\"0.9\" material=\"white\"/>" +
      body);
}

// The diffuse light at the ball's surface point seen from (x, 0, 10) looking down −z.
float litAt(const Scene& scene, double x) {
  World world(scene);
  const Color c = traceOne(world, Ray(Vec3(x, 0, 10), Vec3(0, 0, -1)));
  INFO("x " << x << ": " << c.r << " " << c.g << " " << c.b);
  CHECK(c.r == c.g);
  CHECK(c.g == c.b);
  return c.r;
}

// A small ball on the axis half-way to the light, at z = 50.
const std::string kSlide =
    "<projected-through><sphere center=\"0 0 50\" radius=\"0.1\"/></projected-through>";

// A light at (0, 0, 100) through kSlide's ball: the centre's shadow ray runs along the axis,
// through the ball, fully lit; from (0.5, 0, 0.75) the ray to the light passes z = 50 at
// x = 0.25, beside it: dark.
void checkThroughTheBall(const Scene& s) {
  CHECK(litAt(s, 0.0) == Approx(1.0f).margin(1e-6));
  CHECK(litAt(s, 0.5) == 0.0f);
}

}  // namespace

TEST_CASE("a projected-through light reaches only the points whose rays meet its objects",
          "[render][projected-through]") {
  checkThroughTheBall(*sceneOf("<light position=\"0 0 100\">" + kSlide + "</light>"));
  // Without the objects the same point is lit: N·L there.
  auto plain = sceneOf("<light position=\"0 0 100\"/>");
  CHECK(litAt(*plain, 0.5) == Approx(0.82867f).epsilon(1e-4));
}

TEST_CASE("projected-through surfaces (a disc, an annulus, a triangle) let the light through",
          "[render][projected-through]") {
  // Surfaces enclose nothing: only where a shadow ray crosses them counts.
  checkThroughTheBall(
      *sceneOf("<light position=\"0 0 100\"><projected-through><disc center=\"0 0 50\" "
               "normal=\"0 0 1\" radius=\"0.1\"/></projected-through></light>"));
  checkThroughTheBall(
      *sceneOf("<light position=\"0 0 100\"><projected-through><triangle a=\"-0.1 -0.1 50\" "
               "b=\"0.1 -0.1 50\" c=\"0 0.1 50\"/></projected-through></light>"));
  // An annulus whose hole the centre's ray goes through: dark there, lit through the ring.
  auto ring = sceneOf(
      "<light position=\"0 0 100\"><projected-through><disc center=\"0 0 50\" "
      "normal=\"0 0 1\" radius=\"0.4\" inner-radius=\"0.1\"/></projected-through></light>");
  CHECK(litAt(*ring, 0.0) == 0.0f);
  CHECK(litAt(*ring, 0.5) > 0.5f);  // its ray crosses z = 50 at x = 0.25, on the ring
}

TEST_CASE("only what lies nearer than the projected-through objects shadows the light",
          "[render][projected-through]") {
  // A ball between the objects and the light (z = 75) casts no shadow; one between the point
  // and the objects (z = 20, behind the camera) does.
  const std::string beyond = "<sphere center=\"0 0 75\" radius=\"0.5\"/>";
  const std::string nearer = "<sphere center=\"0 0 20\" radius=\"0.5\"/>";
  auto far = sceneOf(beyond + "<light position=\"0 0 100\">" + kSlide + "</light>");
  CHECK(litAt(*far, 0.0) == Approx(1.0f).margin(1e-6));
  auto plainFar = sceneOf(beyond + "<light position=\"0 0 100\"/>");
  CHECK(litAt(*plainFar, 0.0) == 0.0f);  // it does shadow a light without objects
  auto near = sceneOf(nearer + "<light position=\"0 0 100\">" + kSlide + "</light>");
  CHECK(litAt(*near, 0.0) == 0.0f);
  // shadows="false": the objects alone decide.
  auto shadowless =
      sceneOf(nearer + "<light position=\"0 0 100\" shadows=\"false\">" + kSlide + "</light>");
  CHECK(litAt(*shadowless, 0.0) == Approx(1.0f).margin(1e-6));
  CHECK(litAt(*shadowless, 0.5) == 0.0f);
}

TEST_CASE("projected-through objects stand in the light's frame and move with it",
          "[render][projected-through]") {
  // The light's transform takes its position (0, 0, 50) and its ball at the origin to
  // z = 100 and z = 50: the same light as the first test's.
  auto moved = sceneOf(
      "<light position=\"0 0 50\" transform=\"translate(0 0 50)\"><projected-through><sphere "
      "radius=\"0.1\"/></projected-through></light>");
  checkThroughTheBall(*moved);
  // A <use> of a group holding the light places both.
  auto used = sceneOf(
      "<defs><group id=\"lamp\"><light position=\"0 0 50\"><projected-through><sphere "
      "radius=\"0.1\"/></projected-through></light></group></defs>"
      "<use ref=\"lamp\" transform=\"translate(0 0 50)\"/>");
  checkThroughTheBall(*used);
}

TEST_CASE("each sample ray of an area light asks the projected-through objects for itself",
          "[render][projected-through]") {
  // A 2 × 2 grid at x = ±1 (y = ±0.0005) around (0, 0, 100). A small ball where the rays
  // from the centre's point (0, 0, 0.9) to the samples at x = +1 pass half-way, at
  // (0.5, 0, 50.45), lets those two through and not the two at x = −1: half the light
  // (N·L is taken towards the light's centre, 1 here).
  auto s = sceneOf(
      "<light type=\"area\" position=\"0 0 100\" u=\"2 0 0\" v=\"0 0.001 0\" samples=\"2 2\">"
      "<projected-through><sphere center=\"0.5 0 50.45\" radius=\"0.05\"/></projected-through>"
      "</light>");
  CHECK(litAt(*s, 0.0) == Approx(0.5f).margin(1e-6));
}
