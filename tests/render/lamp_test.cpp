// A lamp placed by <use>: the floor below the placed light gets exactly the light a light
// written at its world position would give (parsed, placed, rendered).
#include "scene_builder.h"

#include "lang/parser.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("a lamp's light shines from its world position, out of its shadowless bulb",
          "[render][lights]") {
  ParseResult r = parseSceneString(R"XML(<scene version="1"><camera/>
      <plane><material diffuse="1"/></plane>
      <defs>
        <group id="lamp">
          <sphere center="0 2 0" radius="0.2" shadows="false"><material emissive="1"/></sphere>
          <light position="0 2 0" attenuation="0 0 1"/>
        </group>
      </defs>
      <use ref="lamp" transform="scale(2) translate(3 0 0)"/>
    </scene>)XML",
                                   "lamp.xml");
  REQUIRE(r.scene);
  World world(*r.scene);
  // The light is at (3, 4, 0). Straight below it: N·L = 1, attenuation 1/4².
  const Color below = traceOne(world, Ray(Vec3(3, 1, 3), glm::normalize(Vec3(0, -1, -3))));
  CHECK(below.r == Approx(1.0 / 16.0).margin(1e-7));
  // At the origin: distance 5, N·L = 4/5, attenuation 1/25.
  const Color origin = traceOne(world, Ray(Vec3(0, 1, 3), glm::normalize(Vec3(0, -1, -3))));
  CHECK(origin.r == Approx(4.0 / 5.0 / 25.0).margin(1e-7));
  // The bulb (radius 0.4 once scaled) is seen, and emits.
  CHECK(traceOne(world, Ray(Vec3(3, 4, 5), Vec3(0, 0, -1))).r == Approx(1.0f));
}
