// Shadow rays: opaque blockers, transparent filters, absorption, area lights.
#include "scene_builder.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// A white diffuse floor y = 0 lit by a light straight above the origin, seen from
// (0, 1, 3): the camera stays below every blocker placed at y >= 1.5.
struct Floor {
  Scene scene;
  Floor(const Light& light) {
    Material floor;
    floor.diffuse = Color(1.0f);
    addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
    scene.lights.push_back(light);
  }
  // The floor point at the origin: N.L = 1, so the colour is A_shadow A_dist I_L.
  Color origin(RayStats* stats = nullptr) {
    World world(scene);
    return traceOne(world, Ray(Vec3(0, 1, 3), glm::normalize(Vec3(0, -1, -3))), stats);
  }
  void slab(double y0, double y1, uint32_t material) {
    addShape(scene, BoxSpec{Vec3(-50, y0, -50), Vec3(50, y1, 50)}, material);
  }
};

Material clear(const Color& kt) {
  Material m;
  m.transmissive = kt;
  m.ior = 1.5;
  return m;
}

}  // namespace

TEST_CASE("an opaque blocker casts a full shadow, a shadowless light ignores it",
          "[render][shadow]") {
  Floor f(pointLight(Vec3(0, 10, 0)));
  CHECK(f.origin() == Color(1.0f));
  Material opaque;
  opaque.diffuse = Color(0.5f);
  f.slab(4, 5, addMaterial(f.scene, opaque));
  CHECK(f.origin() == Color(0.0f));
  f.scene.lights[0].shadows = false;
  RayStats stats;
  CHECK(f.origin(&stats) == Color(1.0f));
  CHECK(stats.shadow == 0);  // no shadow rays for a shadowless light
}

TEST_CASE("a shadow through transparent layers is filtered by k_t at every crossing",
          "[render][shadow]") {
  Floor f(pointLight(Vec3(0, 10, 0)));
  f.slab(2.0, 2.1, addMaterial(f.scene, clear(Color(0.5f))));
  f.slab(3.0, 3.1, addMaterial(f.scene, clear(Color(0.8f, 0.6f, 0.4f))));
  RayStats stats;
  Color c = f.origin(&stats);
  // Each slab is crossed twice (in and out): 0.5^2 (0.8, 0.6, 0.4)^2.
  CHECK(c.r == Approx(0.25 * 0.64).epsilon(1e-6));
  CHECK(c.g == Approx(0.25 * 0.36).epsilon(1e-6));
  CHECK(c.b == Approx(0.25 * 0.16).epsilon(1e-6));
  CHECK(stats.shadow == 1);  // one shadow ray, however many surfaces it crosses
  // An opaque layer on top of them blocks everything.
  Material opaque;
  f.slab(5.0, 5.1, addMaterial(f.scene, opaque));
  CHECK(f.origin() == Color(0.0f));
}

TEST_CASE("a shadow through an absorbing slab is attenuated by exp(-a d)", "[render][shadow]") {
  Floor f(pointLight(Vec3(0, 10, 0)));
  Material m = clear(Color(1.0f));
  m.absorption = Color(0.5f, 1.0f, 2.0f);
  f.slab(2.0, 2.75, addMaterial(f.scene, m));  // thickness 0.75
  Color c = f.origin();
  CHECK(c.r == Approx(std::exp(-0.5 * 0.75)).epsilon(1e-6));
  CHECK(c.g == Approx(std::exp(-1.0 * 0.75)).epsilon(1e-6));
  CHECK(c.b == Approx(std::exp(-2.0 * 0.75)).epsilon(1e-6));
}

TEST_CASE("a light inside an absorbing sphere is attenuated over the path inside",
          "[render][shadow]") {
  Floor f(pointLight(Vec3(0, 3, 0)));
  Material m = clear(Color(1.0f));
  m.absorption = Color(0.2f);
  addShape(f.scene, SphereSpec{Vec3(0, 3, 0), 1.0}, addMaterial(f.scene, m));
  // From the sphere's surface to its centre: distance 1.
  CHECK(f.origin().r == Approx(std::exp(-0.2)).epsilon(1e-5));
}

TEST_CASE("area light: the shadow factor is the fraction of grid samples that see the light",
          "[render][shadow]") {
  Light area;
  area.type = LightType::Area;
  area.position = Vec3(0, 10, 0);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.samplesU = 2;
  area.samplesV = 2;  // the four corners x, z = +-1
  Floor f(area);
  CHECK(f.origin() == Color(1.0f));
  // A blocker over x > 0 at height 5 hides the two corners with x = +1.
  Material opaque;
  addShape(f.scene, BoxSpec{Vec3(0.1, 5, -50), Vec3(50, 6, 50)}, addMaterial(f.scene, opaque));
  RayStats stats;
  Color c = f.origin(&stats);
  CHECK(c.r == Approx(0.5).epsilon(1e-6));
  CHECK(stats.shadow == 4);
  // 3 x 3 samples: the column x = 0 is not blocked (the box starts at 0.1): 6 of 9 lit.
  f.scene.lights[0].samplesU = 3;
  f.scene.lights[0].samplesV = 3;
  CHECK(f.origin().r == Approx(6.0 / 9.0).epsilon(1e-6));
}

TEST_CASE("adaptive area light: POV-Ray's weighted mean from fewer shadow rays",
          "[render][shadow][adaptive]") {
  Light area;
  area.type = LightType::Area;
  area.position = Vec3(0, 10, 0);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.samplesU = 9;
  area.samplesV = 9;  // grid points x = -1 + a/4, a = 0..8
  area.adaptive = 0;
  Floor f(area);
  RayStats stats;
  CHECK(f.origin(&stats) == Color(1.0f));
  CHECK(stats.shadow == 4);  // nothing in the way: the corners agree
  // A blocker over x > 0.1 at height 5 hides the points with x/2 > 0.1, a >= 5.
  Material opaque;
  addShape(f.scene, BoxSpec{Vec3(0.1, 5, -50), Vec3(50, 6, 50)}, addMaterial(f.scene, opaque));
  // Trapezoid weights (1 2 2 2 2 2 2 2 1)/16 of the lit columns 0..4: 9/16.
  Color c = f.origin(&stats);
  CHECK(c.r == Approx(9.0 / 16.0).epsilon(1e-6));
  // Columns 4, 5, 6 around the edge in full, column 0 every 4th row, column 8 every 2nd.
  CHECK(stats.shadow == 3 * 9 + 3 + 5);
  // Without adaptive: all 81 points, the plain mean 45/81.
  f.scene.lights[0].adaptive.reset();
  c = f.origin(&stats);
  CHECK(c.r == Approx(45.0 / 81.0).epsilon(1e-6));
  CHECK(stats.shadow == 81);
}

TEST_CASE("area light direction and distance are taken from its centre", "[render][shadow]") {
  Light area;
  area.type = LightType::Area;
  area.position = Vec3(0, 2, 0);
  area.u = Vec3(8, 0, 0);  // a wide light: its corners are far off-axis
  area.v = Vec3(0, 0, 8);
  area.attenuation = Vec3(0, 0, 1);  // 1/r^2 with r = 2 from the centre
  Floor f(area);
  CHECK(f.origin().r == Approx(0.25).epsilon(1e-6));
}

TEST_CASE("two thin transparent layers filter a shadow once each", "[render][shadow]") {
  // Discs have no inside: the shadow ray crosses each exactly once.
  Floor f(pointLight(Vec3(0, 10, 0)));
  addShape(f.scene, DiscSpec{Vec3(0, 2, 0), Vec3(0, 1, 0), 5.0, 0.0},
           addMaterial(f.scene, clear(Color(0.5f))));
  addShape(f.scene, DiscSpec{Vec3(0, 3, 0), Vec3(0, 1, 0), 5.0, 0.0},
           addMaterial(f.scene, clear(Color(0.8f, 0.6f, 0.4f))));
  Color c = f.origin();
  CHECK(c.r == Approx(0.5 * 0.8).epsilon(1e-6));
  CHECK(c.g == Approx(0.5 * 0.6).epsilon(1e-6));
  CHECK(c.b == Approx(0.5 * 0.4).epsilon(1e-6));
}
