// The cylindrical light (POV-Ray's cylinder light, docs/povray-semantics.md): its incidence
// inside the radius, between radius and falloff, beyond falloff and behind the light, with
// the values POV-Ray 3.7 rendered; and its shadow ray, which stops at the plane through the
// light's position.
#include "scene_builder.h"

#include "render/light_sample.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// A beam straight down from (0, 5, 0).
Light beam(double radius, double falloff, double tightness = 0.0) {
  Light l;
  l.type = LightType::Cylindrical;
  l.position = Vec3(0, 5, 0);
  l.direction = Vec3(0, -1, 0);
  l.radius = radius;
  l.falloff = falloff;
  l.tightness = tightness;
  return l;
}

// The light reaching the floor y = 0 at distance rho from the axis.
double at(const Light& l, double rho) { return lightIncidence(l, Vec3(rho, 0, 0)).radiance.r; }

}  // namespace

TEST_CASE("cylindrical light: full within radius, parallel, its distance along the axis",
          "[render][light]") {
  const Light l = beam(0.5, 1.0);
  const LightIncidence in = lightIncidence(l, Vec3(0.3, 0, 0.2));
  CHECK(in.radiance == Color(1.0f));
  CHECK(in.toLight == Vec3(0, 1, 0));  // −direction wherever the point is
  CHECK(in.distance == 5.0);           // k, not |p − position|
  CHECK(in.parallel);
  const LightIncidence near = lightIncidence(l, Vec3(0.4, 4, 0));
  CHECK(near.radiance == Color(1.0f));
  CHECK(near.distance == 1.0);
  CHECK(lightIncidence(l, Vec3(0, -100, 0)).distance == 105.0);
  CHECK(at(l, 0.5) == 1.0f);  // the radius itself is inside
}

TEST_CASE("cylindrical light: between radius and falloff the smoothstep of the distance",
          "[render][light]") {
  // u = (falloff − ρ)/(falloff − radius) = 0.25/0.5: (3 − 2u)u² = 0.5.
  CHECK(at(beam(0.5, 1.0), 0.75) == 0.5f);
  // u = 0.8: 1.4 · 0.64.
  CHECK(at(beam(0.5, 1.0), 0.6) == Approx(0.896).epsilon(1e-6));
  // POV-Ray's own pixels (povray 3.7.0.10, docs/povray-semantics.md): its defaults radius
  // 0.75, falloff 1, tightness 0 give 0.6480 at ρ = 0.85 and 0.1040 at 0.95.
  CHECK(at(beam(0.75, 1.0), 0.85) == Approx(0.648).margin(5e-5));
  CHECK(at(beam(0.75, 1.0), 0.95) == Approx(0.104).margin(5e-5));
  // radius 0.3, falloff 1, tightness 2: (1 − ρ)² inside the radius, 0.2668 at ρ = 0.45.
  CHECK(at(beam(0.3, 1.0, 2.0), 0.05) == Approx(0.9025).margin(5e-5));
  CHECK(at(beam(0.3, 1.0, 2.0), 0.45) == Approx(0.2668).margin(5e-5));
  // radius 0: no smoothstep; tightness 1 gives 1 − ρ/falloff across the beam.
  CHECK(at(beam(0.0, 1.0, 1.0), 0.35) == Approx(0.65).epsilon(1e-6));
  CHECK(at(beam(0.0, 2.0, 1.0), 0.5) == Approx(0.75).epsilon(1e-6));
}

TEST_CASE("cylindrical light: nothing from falloff on, nor behind the light", "[render][light]") {
  const Light l = beam(0.5, 1.0);
  CHECK(at(l, 1.0) == 0.0f);
  CHECK(at(l, 3.0) == 0.0f);
  // On the plane through the position (k = 0) and behind it, even on the axis.
  CHECK(lightIncidence(l, Vec3(0.1, 5, 0)).radiance == Color(0.0f));
  CHECK(lightIncidence(l, Vec3(0, 6, 0)).radiance == Color(0.0f));
  CHECK(lightIncidence(l, Vec3(0, 50, 0)).radiance == Color(0.0f));
  // radius = falloff: a hard edge.
  const Light hard = beam(1.0, 1.0);
  CHECK(at(hard, 0.999) == 1.0f);
  CHECK(at(hard, 1.0) == 0.0f);
}

TEST_CASE("cylindrical light: attenuation by the distance along the axis, colour, a tilted axis",
          "[render][light]") {
  Light l = beam(0.5, 1.0);
  l.attenuation = Vec3(1, 0, 1);
  l.color = Color(1.0f, 0.5f, 0.25f);
  l.intensity = 2.0;
  // k = 2: 1/(1 + 4), off the axis as on it (|p − position| would give 1/(1 + 4.16)).
  l.position = Vec3(0, 2, 0);
  const Color expected = Color(1.0f, 0.5f, 0.25f) * 0.4f;
  CHECK(lightIncidence(l, Vec3(0, 0, 0)).radiance == expected);
  CHECK(lightIncidence(l, Vec3(0.4, 0, 0)).radiance == expected);

  // A beam along (1, −1, 0)/√2 from the origin: the light comes from (−1, 1, 0)/√2.
  Light tilted = beam(0.5, 1.0);
  tilted.position = Vec3(0.0);
  tilted.direction = glm::normalize(Vec3(1, -1, 0));
  const Vec3 onAxis = 3.0 * tilted.direction;
  const Vec3 across = glm::normalize(Vec3(1, 1, 0));  // perpendicular to the axis
  const LightIncidence in = lightIncidence(tilted, onAxis + 0.75 * across);
  CHECK(glm::length(in.toLight - glm::normalize(Vec3(-1, 1, 0))) <= 1e-15);
  CHECK(in.distance == Approx(3.0).epsilon(1e-14));
  CHECK(in.radiance.r == Approx(0.5).epsilon(1e-6));
  CHECK(lightIncidence(tilted, onAxis + 1.01 * across).radiance == Color(0.0f));
}

TEST_CASE("a cylindrical light's shadow ray stops at the plane through its position",
          "[render][light][shadow]") {
  // A white diffuse floor lit straight down from y = 2; the camera at (0, 1, 3) looks at
  // the origin (N·L = 1, so the colour is the shadow factor times the beam).
  Scene scene;
  Material white;
  white.diffuse = Color(1.0f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, white));
  Light l = beam(1.0, 2.0);
  l.position = Vec3(0, 2, 0);
  scene.lights.push_back(l);
  const Ray eye(Vec3(0, 1, 3), glm::normalize(Vec3(0, -1, -3)));
  CHECK(traceOne(World(scene), eye) == Color(1.0f));
  // A slab over everything, above the light's plane: POV-Ray's cylinder light is not
  // blocked by it.
  Material opaque;
  opaque.diffuse = Color(0.5f);
  const uint32_t grey = addMaterial(scene, opaque);
  addShape(scene, BoxSpec{Vec3(-50, 3, -50), Vec3(50, 4, 50)}, grey);
  CHECK(traceOne(World(scene), eye) == Color(1.0f));
  // A small box between the plane and the floor, above the origin, is.
  addShape(scene, BoxSpec{Vec3(-0.2, 1.0, -0.2), Vec3(0.2, 1.2, 0.2)}, grey);
  CHECK(traceOne(World(scene), eye) == Color(0.0f));
}
