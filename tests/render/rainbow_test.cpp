// <rainbow> against POV-Ray 3.7's rule (its Trace::ComputeRainbow, worked by hand): a ring
// from 35 to 45 degrees around −z, red at its inner edge and blue at its outer, over a
// background of (0.2, 0.4, 0.6). Rays leave from the origin; a ray at 40 degrees takes the
// map's middle, (0.5, 0, 0.5).
#include "scene_builder.h"

#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

const Color kBackground(0.2f, 0.4f, 0.6f), kMiddle(0.5f, 0.0f, 0.5f);
constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string rainbow(const std::string& attributes, const std::string& filter = "0") {
  return "<rainbow direction=\"0 0 -1\" angle=\"40\" width=\"10\" " + attributes +
         "><color-map><entry at=\"0\" color=\"1 0 0\" filter=\"" + filter +
         "\"/><entry at=\"1\" color=\"0 0 1\" filter=\"" + filter + "\"/></color-map></rainbow>";
}

std::unique_ptr<Scene> sceneOf(const std::string& body) {
  return parseClean("<render background=\"0.2 0.4 0.6\"/>" + body);
}

// The colour of the ray from the origin at `degrees` from −z, turned `around` degrees from
// up (+y) towards +x.
Color seen(const Scene& scene, double degrees, double around = 0.0) {
  World world(scene);
  const double a = degrees * kDegree, b = around * kDegree;
  const Vec3 d(std::sin(a) * std::sin(b), std::sin(a) * std::cos(b), -std::cos(a));
  return traceOne(world, Ray(Vec3(0.0), d));
}

void checkColor(const Color& got, const Color& want) {
  INFO("got " << got.r << " " << got.g << " " << got.b << ", want " << want.r << " " << want.g
              << " " << want.b);
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-5));
}

}  // namespace

TEST_CASE("a rainbow shows its map across the ring on rays that leave the scene",
          "[render][rainbow]") {
  auto s = sceneOf(rainbow(""));
  checkColor(seen(*s, 40.0), kMiddle);                    // k = 0: the map's colour alone
  checkColor(seen(*s, 37.5), Color(0.75f, 0.0f, 0.25f));  // a quarter across
  checkColor(seen(*s, 40.0, 120.0), kMiddle);             // the whole ring by default
  checkColor(seen(*s, 30.0), kBackground);                // inside the ring
  checkColor(seen(*s, 50.0), kBackground);                // outside it
  checkColor(seen(*s, 140.0), kBackground);               // towards the sun (d·direction < 0)
}

TEST_CASE("a rainbow fades with the distance to what the ray meets", "[render][rainbow]") {
  // A white emitting wall at z = −10: a ray at 40 degrees meets it at t = 10/cos 40°.
  const std::string wall =
      "<plane normal=\"0 0 1\" offset=\"-10\"><material emissive=\"1 1 1\" diffuse=\"0\"/></plane>";
  const double k = std::exp(-1.0 / std::cos(40.0 * kDegree));
  auto s = sceneOf(wall + rainbow("distance=\"10\""));
  const auto kf = static_cast<float>(k);
  checkColor(seen(*s, 40.0), kf * Color(1.0f) + (1.0f - kf) * kMiddle);
  // A filter tints what is kept: f = filter·(1 − k).
  auto filtered = sceneOf(wall + rainbow("distance=\"10\"", "1"));
  const float f = 1.0f - kf;
  checkColor(seen(*filtered, 40.0),
             kf * Color(1.0f) * ((1.0f - f) + f * kMiddle) + (1.0f - kf) * kMiddle);
}

TEST_CASE("a rainbow's arc and its falloff", "[render][rainbow]") {
  // arc-angle 90: drawn within 45 degrees of up only.
  auto arc = sceneOf(rainbow("arc-angle=\"90\""));
  checkColor(seen(*arc, 40.0, 30.0), kMiddle);
  checkColor(seen(*arc, 40.0, 60.0), kBackground);
  // arc-angle 180, falloff-angle 0: at 45 degrees round, s = 0.5, fade = s²(3 − 2s) = 0.5,
  // k = 0.5: half the background, half the map.
  auto fading = sceneOf(rainbow("arc-angle=\"180\" falloff-angle=\"0\""));
  checkColor(seen(*fading, 40.0, 45.0), 0.5f * kBackground + 0.5f * kMiddle);
  checkColor(seen(*fading, 40.0, 0.0), kMiddle);
}

TEST_CASE("rainbows that a ray meets are averaged, and the fog acts after them",
          "[render][rainbow]") {
  // A second ring, green, from 38 to 48 degrees: at 40 degrees both apply.
  const std::string green =
      "<rainbow direction=\"0 0 -1\" angle=\"43\" width=\"10\"><color-map><entry at=\"0\" "
      "color=\"0 1 0\"/></color-map></rainbow>";
  auto both = sceneOf(rainbow("") + green);
  checkColor(seen(*both, 40.0), 0.5f * (kMiddle + Color(0.0f, 1.0f, 0.0f)));
  checkColor(seen(*both, 46.0), Color(0.0f, 1.0f, 0.0f));  // the green one alone
  // A fog keeping half of what lies beyond (its transmit) mixes its colour with the
  // rainbow's, not the background's: the rainbow first.
  auto fogged = sceneOf(rainbow("") + "<fog color=\"1 1 1\" distance=\"1\" transmit=\"0.5\"/>");
  checkColor(seen(*fogged, 40.0), 0.5f * Color(1.0f) + 0.5f * kMiddle);
}

TEST_CASE("a rainbow's jitter repeats for a direction and differs between directions",
          "[render][rainbow]") {
  auto plain = sceneOf(rainbow(""));
  auto jittered = sceneOf(rainbow("jitter=\"0.5\""));
  int differing = 0;
  for (int i = 0; i < 36; ++i) {
    const double around = 10.0 * i;
    checkColor(seen(*plain, 40.0, around), kMiddle);
    const Color c = seen(*jittered, 40.0, around);
    checkColor(seen(*jittered, 40.0, around), c);  // the same ray, the same colour
    if (std::abs(c.r - kMiddle.r) > 1e-3f) ++differing;
  }
  CHECK(differing > 30);
}

TEST_CASE("shadow rays see no rainbow", "[render][rainbow]") {
  // A grey floor seen from straight above (90 degrees from the ring's axis, outside it),
  // lit by a light 40 degrees from −z: the shadow ray runs along the ring's middle.
  const double a = 40.0 * kDegree;
  const std::string lit =
      "<plane normal=\"0 1 0\"><material diffuse=\"0.5\"/></plane><light position=\"0 " +
      std::to_string(20.0 * std::sin(a)) + " " + std::to_string(-20.0 * std::cos(a)) + "\"/>";
  auto without = sceneOf(lit);
  auto with = sceneOf(lit + rainbow(""));
  const Ray down(Vec3(0.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0));
  const Color plainFloor = traceOne(World(*without), down);
  CHECK(plainFloor.r > 0.1f);
  checkColor(traceOne(World(*with), down), plainFloor);
}
