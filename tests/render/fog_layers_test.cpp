// POV-Ray's fog beyond one smooth fog (render/fog.h): turbulence, several fogs, and fog
// inside hollow solids. Turbulence shortens a stretch of length t to
// t·(1 − exp(−t/d)·min(1, turb_depth·T(v ⊙ m))), m the stretch's middle, T POV-Ray's
// turbulence (scenegraph/turbulence.h, held to POV-Ray's values by its own tests).
#include "scene_builder.h"

#include "render/fog.h"
#include "scenegraph/turbulence.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

const Color kFog(0.5f, 0.6f, 0.7f);
const Color kWall(1.0f, 0.2f, 0.0f);

Fog constantFog(double distance, const Color& color = kFog) {
  Fog f;
  f.color = color;
  f.distance = distance;
  return f;
}

FogTurbulence turbulence(const Vec3& strength, double depth) {
  FogTurbulence t;
  t.strength = strength;
  t.octaves = 5;
  t.omega = 0.35;
  t.lambda = 1.25;
  t.depth = depth;
  return t;
}

// POV-Ray's scalar turbulence with the fog's octaves, omega and lambda.
double T(const FogTurbulence& t, const Vec3& q) {
  PatternPlacement p;
  p.octaves = t.octaves;
  p.omega = t.omega;
  p.lambda = t.lambda;
  return lucent::turbulence(q, p, t.noiseGenerator);
}

void checkColor(const Color& got, const Color& want) {
  CHECK(got.r == Approx(want.r).margin(1e-6));
  CHECK(got.g == Approx(want.g).margin(1e-6));
  CHECK(got.b == Approx(want.b).margin(1e-6));
}

Color mixed(double a, const Color& c) {
  const float k = static_cast<float>(a);
  return (1.0f - k) * kFog + k * c;
}

}  // namespace

TEST_CASE("fog turbulence: constant fog, the noise at the turbulence times the middle",
          "[render][fog]") {
  Fog fog = constantFog(5.0);
  fog.turbulence = turbulence(Vec3(0.5, 0.25, 2.0), 0.7);
  // From (1, 2, 3) along -z for 4: the middle is (1, 2, 1), scaled to (0.5, 0.5, 2).
  const double t = T(*fog.turbulence, Vec3(0.5, 0.5, 2.0));
  const double want = 4.0 * (1.0 - std::exp(-4.0 / 5.0) * std::min(1.0, 0.7 * t));
  CHECK(fogDepth(fog, Vec3(1, 2, 3), Vec3(0, 0, -1), 4.0) == Approx(want).epsilon(1e-15));
  CHECK(want != Approx(4.0).epsilon(1e-3));  // the noise does change it here

  SECTION("a large turb_depth saturates: t (1 - exp(-t/d))") {
    fog.turbulence->depth = 1e9;
    REQUIRE(t > 0.0);
    CHECK(fogDepth(fog, Vec3(1, 2, 3), Vec3(0, 0, -1), 4.0) ==
          Approx(4.0 * (1.0 - std::exp(-0.8))).epsilon(1e-15));
  }
  SECTION("the transform places the noise: its inverse takes the middle first") {
    Mat4 mirror(1.0);
    mirror[2][2] = -1.0;
    fog.turbulence->noiseFromWorld = mirror;
    const double mirrored = T(*fog.turbulence, Vec3(0.5, 0.5, -2.0));
    CHECK(fogDepth(fog, Vec3(1, 2, 3), Vec3(0, 0, -1), 4.0) ==
          Approx(4.0 * (1.0 - std::exp(-0.8) * std::min(1.0, 0.7 * mirrored))).epsilon(1e-15));
  }
  SECTION("a ray that leaves the scene is not changed") {
    CHECK(fogDepth(fog, Vec3(1, 2, 3), Vec3(0, 0, -1), kInf) == kInf);
  }
}

TEST_CASE("fog turbulence: ground fog shortens the stretch, then takes its mean density",
          "[render][fog]") {
  Fog fog = constantFog(1.5);
  fog.type = FogType::Ground;
  fog.offset = 0.0;
  fog.altitude = 1.0;
  Fog smooth = fog;
  fog.turbulence = turbulence(Vec3(0.15), 1.0);
  // A level stretch at height 1 (density 1/2) from (0, 1, 0) to (0, 1, -3).
  const Vec3 o(0, 1, 0), d(0, 0, -1);
  CHECK(fogDepth(smooth, o, d, 3.0) == Approx(1.5).epsilon(1e-15));
  const double t = T(*fog.turbulence, Vec3(0.0, 0.15, -0.225));
  const double shortened = 3.0 * (1.0 - std::exp(-3.0 / 1.5) * std::min(1.0, t));
  CHECK(fogDepth(fog, o, d, 3.0) == Approx(shortened * 0.5).epsilon(1e-15));
}

TEST_CASE("several fogs: the shares kept multiply, the fog colours add (POV-Ray's rule)",
          "[render][fog]") {
  Scene scene;
  const Color orange(1.0f, 0.5f, 0.0f);
  scene.fogs = {constantFog(5.0), constantFog(8.0, orange)};
  scene.fogs[1].filter = 0.5f;
  addShape(scene, PlaneSpec{Vec3(0, 0, 1), -4.0}, addMaterial(scene, emissive(kWall)));
  World world(scene);
  const float a1 = static_cast<float>(std::exp(-4.0 / 5.0));
  const float a2 = static_cast<float>(std::exp(-4.0 / 8.0));
  const Color want =
      (1.0f - a1) * kFog + (1.0f - a2) * orange + a1 * a2 * (0.5f + 0.5f * orange) * kWall;
  checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), want);

  SECTION("one fog alone is what it was") {
    scene.fogs.pop_back();
    World one(scene);
    checkColor(traceOne(one, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(a1, kWall));
  }
}

TEST_CASE("hollow solids: the fog goes on inside them", "[render][fog]") {
  SECTION("a clear slab 2 thick in front of a wall 6 away: 4 of fog, 6 if hollow") {
    for (bool hollow : {false, true}) {
      Scene scene;
      scene.fogs = {constantFog(5.0)};
      addShape(scene, PlaneSpec{Vec3(0, 0, 1), -6.0}, addMaterial(scene, emissive(kWall)));
      Material clear;
      clear.transmissive = Color(1.0f);
      clear.hollow = hollow;
      addShape(scene, BoxSpec{Vec3(-10, -10, -3), Vec3(10, 10, -1)}, addMaterial(scene, clear));
      World world(scene);
      INFO("hollow " << hollow);
      checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))),
                 mixed(std::exp(-(hollow ? 6.0 : 4.0) / 5.0), kWall));
    }
  }
  SECTION("a camera inside an opaque ball sees its inside through fog only if it is hollow") {
    for (bool hollow : {false, true}) {
      Scene scene;
      scene.fogs = {constantFog(5.0)};
      Material dome = emissive(kWall);
      dome.hollow = hollow;
      addShape(scene, SphereSpec{Vec3(0.0), 10.0}, addMaterial(scene, dome));
      World world(scene);
      INFO("hollow " << hollow);
      checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))),
                 hollow ? mixed(std::exp(-10.0 / 5.0), kWall) : kWall);
    }
  }
  SECTION("a hollow glass inside a solid glass: no fog, the outer one is not hollow") {
    Scene scene;
    scene.fogs = {constantFog(5.0)};
    addShape(scene, PlaneSpec{Vec3(0, 0, 1), -6.0}, addMaterial(scene, emissive(kWall)));
    Material outer, inner;
    outer.transmissive = inner.transmissive = Color(1.0f);
    inner.hollow = true;
    addShape(scene, BoxSpec{Vec3(-10, -10, -5), Vec3(10, 10, -1)}, addMaterial(scene, outer));
    addShape(scene, BoxSpec{Vec3(-5, -5, -4), Vec3(5, 5, -2)}, addMaterial(scene, inner));
    World world(scene);
    // Fogged: 0..1 and 5..6 outside; 2..4 is in the hollow box but also in the outer one.
    checkColor(traceOne(world, Ray(Vec3(0.0), Vec3(0, 0, -1))), mixed(std::exp(-2.0 / 5.0), kWall));
  }
}

TEST_CASE("media-attenuation: the fogs dim a light along its shadow rays, by their kept share",
          "[render][fog]") {
  // A light 8 above a white floor, looked at from 3 above it: the floor is lit by
  // k_d·I·(N·L) times what the fog keeps over the 8 up to the light.
  for (bool attenuated : {false, true}) {
    Scene scene;
    Fog fog = constantFog(10.0);
    fog.filter = 0.5f;
    scene.fogs = {fog};
    Material floor;
    floor.diffuse = Color(1.0f);
    addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, floor));
    Light light;
    light.position = Vec3(0, 8, 0);
    light.mediaAttenuation = attenuated;
    scene.lights = {light};
    World world(scene);
    const float eye = static_cast<float>(std::exp(-3.0 / 10.0));
    const float lit = attenuated ? static_cast<float>(std::exp(-8.0 / 10.0)) : 1.0f;
    const Color tint = 0.5f + 0.5f * kFog;
    const Color onFloor = attenuated ? lit * tint : Color(1.0f);
    INFO("media-attenuation " << attenuated);
    checkColor(traceOne(world, Ray(Vec3(0, 3, 0), Vec3(0, -1, 0))),
               (1.0f - eye) * kFog + eye * tint * onFloor);
  }
}
