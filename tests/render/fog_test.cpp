// Fog (render/fog.h): pixels against POV-Ray's formulas, C' = (1 − a)F + a·((1 − f) + f·F)·C
// with a = max(exp(−τ/d), transmit), τ the stretch's length (constant fog) or its length
// times the mean ground-fog density.
#include "scene_builder.h"

#include "render/fog.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace lucent;
using namespace lucent::test;

namespace {

const Color kFog(0.5f, 0.6f, 0.7f);
const Color kWall(1.0f, 0.2f, 0.0f);

Fog constantFog(double distance) {
  Fog f;
  f.color = kFog;
  f.distance = distance;
  return f;
}

// An emissive wall, the plane z = z0 facing +z (the camera at the origin is outside it).
void addWall(Scene& scene, double z0, const Color& emitted = kWall) {
  addShape(scene, PlaneSpec{Vec3(0, 0, 1), z0}, addMaterial(scene, emissive(emitted)));
}

// The expected colour of C seen through fog that keeps a (no filter, no transmit).
Color mixed(double a, const Color& c) {
  const float k = static_cast<float>(a);
  return (1.0f - k) * kFog + k * c;
}

void checkColor(const Color& got, const Color& want) {
  CHECK(got.r == Approx(want.r).margin(1e-6));
  CHECK(got.g == Approx(want.g).margin(1e-6));
  CHECK(got.b == Approx(want.b).margin(1e-6));
}

// The ground fog's density at height y (the graph in POV-Ray's ComputeGroundFogColour).
double density(const Fog& f, double y) {
  double s = (y - f.offset) / f.altitude;
  return s <= 0.0 ? 1.0 : 1.0 / (1.0 + s * s);
}

// ∫ density along the ray, by Simpson's rule on n intervals.
double integrated(const Fog& f, const Vec3& o, const Vec3& d, double length, int n = 20000) {
  double h = length / n, sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * density(f, glm::dot(o + d * (i * h), f.up));
  }
  return sum * h / 3.0;
}

}  // namespace

TEST_CASE("fog: a surface at distance t keeps exp(-t/distance) of its colour", "[render][fog]") {
  Scene scene;
  scene.fogs = {constantFog(5.0)};
  addWall(scene, -4.0);
  World world(scene);
  // Straight ahead the wall is 4 away; along (0.6, 0, -0.8) it is 5 away.
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(std::exp(-4.0 / 5.0), kWall));
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0.6, 0, -0.8))), mixed(std::exp(-1.0), kWall));
  // The distance is measured in world units, whatever the length of the ray's direction.
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -2))), mixed(std::exp(-4.0 / 5.0), kWall));
}

TEST_CASE(
    "fog: a ray that leaves the scene shows the fog colour, or keeps transmit of the background",
    "[render][fog]") {
  Scene scene;
  scene.render.background = Color(0.2f, 0.4f, 0.9f);
  scene.fogs = {constantFog(5.0)};
  {
    World world(scene);
    CHECK(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))) == kFog);
  }
  scene.fogs[0].transmit = 0.3f;
  World world(scene);
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(0.3, scene.render.background));
}

TEST_CASE("fog: transmit is the least share kept, filter tints it by the fog colour",
          "[render][fog]") {
  Scene scene;
  scene.fogs = {constantFog(2.0)};
  scene.fogs[0].filter = 0.5f;
  scene.fogs[0].transmit = 0.25f;
  addWall(scene, -4.0);
  World world(scene);
  // exp(-4/2) = 0.135 is below transmit: a = 0.25.
  const float a = 0.25f;
  const Color want = (1.0f - a) * kFog + a * (0.5f + 0.5f * kFog) * kWall;
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), want);
}

TEST_CASE("fog: no fog inside a solid, fog along reflected rays", "[render][fog]") {
  SECTION("a clear slab 2 thick in front of a wall 6 away: 4 of fog") {
    Scene scene;
    scene.fogs = {constantFog(5.0)};
    addWall(scene, -6.0);
    Material clear;
    clear.transmissive = Color(1.0f);
    addShape(scene, BoxSpec{Vec3(-10, -10, -3), Vec3(10, 10, -1)}, addMaterial(scene, clear));
    World world(scene);
    checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(std::exp(-4.0 / 5.0), kWall));
  }
  SECTION("a mirror 2 ahead and a wall 3 behind: 2 + 5 of fog") {
    Scene scene;
    scene.fogs = {constantFog(5.0)};
    Material mirror;
    mirror.reflective = Color(1.0f);
    addShape(scene, PlaneSpec{Vec3(0, 0, 1), -2.0}, addMaterial(scene, mirror));
    addShape(scene, PlaneSpec{Vec3(0, 0, -1), -3.0}, addMaterial(scene, emissive(kWall)));
    World world(scene);
    checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(std::exp(-7.0 / 5.0), kWall));
  }
}

TEST_CASE(
    "ground fog: a level ray at height y keeps exp(-t / (distance (1 + s^2))), s = (y - "
    "offset)/altitude",
    "[render][fog]") {
  Scene scene;
  Fog fog = constantFog(3.0);
  fog.type = FogType::Ground;
  fog.offset = 0.5;
  fog.altitude = 0.8;
  scene.fogs = {fog};
  addWall(scene, -4.0);
  World world(scene);
  for (double y : {-1.0, 0.5, 1.3, 2.9}) {
    double s = (y - 0.5) / 0.8;
    double d = s <= 0.0 ? 1.0 : 1.0 / (1.0 + s * s);
    INFO("height " << y);
    checkColor(traceOne(world, Ray(Vec3(0, y, 0), Vec3(0, 0, -1))),
               mixed(std::exp(-4.0 * d / 3.0), kWall));
  }
}

TEST_CASE("ground fog: the depth of a stretch is the integral of the density along it",
          "[render][fog]") {
  Fog fog = constantFog(1.0);
  fog.type = FogType::Ground;
  fog.offset = 0.3;
  fog.altitude = 0.7;
  fog.up = glm::normalize(Vec3(0.1, 1.0, -0.2));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    Vec3 o(3 * u(rng), 2 * u(rng), 3 * u(rng));
    Vec3 d = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    double length = 5.0 * (1.0 + u(rng));
    INFO("ray " << i);
    CHECK(fogDepth(fog, o, d, length) == Approx(integrated(fog, o, d, length)).epsilon(1e-8));
  }
  // A ray that leaves the scene: the limit of long stretches, finite only if it rises.
  const Vec3 o(0, 0.1, 0);
  const Vec3 level = glm::normalize(glm::cross(fog.up, Vec3(1, 0, 0)));
  const Vec3 rising = glm::normalize(level + 0.3 * fog.up),
             falling = glm::normalize(level - 0.01 * fog.up);
  CHECK(fogDepth(fog, o, rising, kInf) == Approx(fogDepth(fog, o, rising, 1e9)).epsilon(1e-8));
  CHECK(fogDepth(fog, o, falling, kInf) == kInf);
  CHECK(fogDepth(fog, o, level, kInf) == kInf);
}
