// crand, POV-Ray's graininess: each light's diffuse term loses u·crand·k_d, u from a hash
// of the hit point and the light, in [0, 1); never where the light does not reach.
#include "scene_builder.h"

#include <catch2/catch.hpp>

#include <set>

using namespace lucent;
using namespace lucent::test;

namespace {

// A floor at y = 0 (k_d 0.8, no ambient) lit from straight above by a white light at
// height 10, and a small opaque ball at (2, 1, 0) that shadows the floor below it.
Scene floorScene(double crand) {
  Scene scene;
  Material floor;
  floor.diffuse = Color(0.8f);
  floor.crand = crand;
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
  Material ball;
  ball.diffuse = Color(0.5f);
  addShape(scene, SphereSpec{Vec3(2, 1, 0), 0.3}, addMaterial(scene, ball));
  scene.lights.push_back(pointLight(Vec3(0, 10, 0)));
  return scene;
}

// The floor's colour at (x, 0, z), seen from straight above.
Color floorAt(const World& world, double x, double z) {
  return traceOne(world, Ray(Vec3(x, 0.5, z), Vec3(0, -1, 0)));
}

}  // namespace

TEST_CASE("crand: the diffuse term loses a hashed share of k_d per point",
          "[render][finish][crand]") {
  const Scene plain = floorScene(0.0), grainy = floorScene(0.4);
  const World plainWorld(plain), grainyWorld(grainy);
  std::set<float> values;
  double lossSum = 0.0;
  int n = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double x = -1.0 + 0.05 * i + 0.0013 * j, z = -1.0 + 0.05 * j;
      const Color a = floorAt(plainWorld, x, z), b = floorAt(grainyWorld, x, z);
      // The loss is u·crand·k_d·light: the same share in every channel, at most crand·k_d.
      const double loss = double(a.x) - double(b.x);
      CHECK(loss >= 0.0);
      CHECK(loss <= 0.4 * 0.8 + 1e-6);
      CHECK(b.y == b.x);
      lossSum += loss;
      ++n;
      values.insert(b.x);
      // The same point gives the same grain.
      CHECK(floorAt(grainyWorld, x, z) == b);
    }
  // u is uniform: its mean is 1/2 (1600 draws: within 0.03), so the mean loss is 0.16.
  CHECK(lossSum / n == Approx(0.5 * 0.4 * 0.8).margin(0.03 * 0.4 * 0.8));
  CHECK(values.size() > 1500);
}

TEST_CASE("crand: none where the light is shadowed or the surface faces away",
          "[render][finish][crand]") {
  const Scene plain = floorScene(0.0), grainy = floorScene(0.4);
  const World plainWorld(plain), grainyWorld(grainy);
  // Under the ball (its shadow is centred at x = 2·10/9): the light is blocked, and
  // nothing else lights the floor there.
  const Color shadowed = floorAt(grainyWorld, 20.0 / 9.0, 0.0);
  CHECK(shadowed == floorAt(plainWorld, 20.0 / 9.0, 0.0));
  CHECK(shadowed == Color(0.0f));
  // Seen from below, the floor faces away from the light.
  const Ray below(Vec3(0.3, -1.0, 0.2), Vec3(0, 1, 0));
  CHECK(traceOne(grainyWorld, below) == traceOne(plainWorld, below));
}

TEST_CASE("crand: each light draws its own share", "[render][finish][crand]") {
  Scene one = floorScene(0.4), two = floorScene(0.4);
  two.lights.push_back(pointLight(Vec3(0, 10, 0)));
  const Scene plain = floorScene(0.0);
  const World w1(one), w2(two), w0(plain);
  int differ = 0;
  for (int i = 0; i < 50; ++i) {
    const double x = -1.0 + 0.037 * i;
    const double loss1 = double(floorAt(w0, x, 0.4).x) - floorAt(w1, x, 0.4).x;
    const double loss2 = 2.0 * floorAt(w0, x, 0.4).x - floorAt(w2, x, 0.4).x;
    CHECK(loss2 >= 0.0);
    CHECK(loss2 <= 2.0 * 0.4 * 0.8 + 1e-6);
    if (std::abs(loss2 - 2.0 * loss1) > 1e-3) ++differ;
  }
  CHECK(differ > 40);
}
