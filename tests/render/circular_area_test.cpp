// POV-Ray's circular and orient area lights (render/light_sample.h): sample positions
// against POV-Ray's rule written another way (each grid shell on the circle of its
// half-width, in polar form; the turned axes by their properties and by hand), and the
// shadow they cast.
#include "scene_builder.h"

#include "render/light_sample.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

// POV-Ray's circular grid point (a, b) in polar form: the shell max(|x|, |y|) of the
// offset square coordinates is the radius, their angle the angle.
Vec2 polarGridPoint(int a, int b, int nu, int nv) {
  const double x = double(a) / (nu - 1) - 0.5 + 0.001, y = double(b) / (nv - 1) - 0.5 + 0.001;
  const double r = std::max(std::abs(x), std::abs(y)), angle = std::atan2(y, x);
  return Vec2(r * std::cos(angle), r * std::sin(angle));
}

Light circularLight(int nu, int nv) {
  Light l = areaLight(Vec3(1, 6, -2), Vec3(3, 0, 0), Vec3(0, 1, 2), nu, nv);
  l.circular = true;
  return l;
}

}  // namespace

TEST_CASE("circular area light: every grid shell lies on the circle of its half-width",
          "[render][light]") {
  for (int n : {2, 3, 4, 5, 8}) {
    for (int m : {2, 5}) {
      const Light l = circularLight(n, m);
      for (int k = 0; k < n * m; ++k) {
        const Vec2 xy = polarGridPoint(k % n, k / n, n, m);
        const Vec3 expected = l.position + l.u * xy.x + l.v * xy.y;
        CHECK(glm::length(lightSamplePoint(l, k, Vec2(0.5)) - expected) < 1e-12);
      }
    }
  }
  // By hand: a 4 x 4 grid's corner (−0.499, −0.499) goes to radius 0.499 on the diagonal;
  // (1/3 − 0.5 + 0.001, −0.499) keeps |y| as its radius; a 3 x 3 grid's middle is the
  // offset (0.001, 0.001) scaled by 1/√2.
  const double c = 0.499 / std::sqrt(2.0);
  CHECK(glm::length(areaGridCoordinates(0, 0, 4, 4, true) - Vec2(-c, -c)) < 1e-15);
  const double x = 1.0 / 3.0 - 0.5 + 0.001, y = -0.499;
  const double s = 0.499 / std::sqrt(x * x + y * y);
  CHECK(glm::length(areaGridCoordinates(1, 0, 4, 4, true) - Vec2(x * s, y * s)) < 1e-15);
  CHECK(glm::length(areaGridCoordinates(1, 1, 3, 3, true) -
                    Vec2(0.001 / std::sqrt(2.0), 0.001 / std::sqrt(2.0))) < 1e-15);
  // Without circular, the plain grid.
  CHECK(areaGridCoordinates(1, 0, 4, 4, false) == Vec2(1.0 / 3.0 - 0.5, -0.5));
}

TEST_CASE("circular area light: jitter moves the grid point before the remap", "[render][light]") {
  Light l = circularLight(4, 4);
  l.jitter = true;
  // Grid point (1, 2) moved by (+0.3, −0.2) of a step: the circle rule at (1.3, 1.8).
  const Vec3 p = lightSamplePoint(l, 2 * 4 + 1, Vec2(0.8, 0.3));
  const double x = 1.3 / 3.0 - 0.5 + 0.001, y = 1.8 / 3.0 - 0.5 + 0.001;
  const double r = std::max(std::abs(x), std::abs(y)), angle = std::atan2(y, x);
  const Vec3 expected = l.position + l.u * (r * std::cos(angle)) + l.v * (r * std::sin(angle));
  CHECK(glm::length(p - expected) < 1e-12);
}

TEST_CASE("oriented area light: a square of side |u| across the direction to its centre",
          "[render][light]") {
  Light l = circularLight(4, 4);
  l.u = Vec3(0, 0, 2);
  l.v = Vec3(2, 0, 0);
  l.orient = true;
  l.position = Vec3(0, 10, 0);
  // By hand. Straight below: d = y, d × z = x, d × x = −z.
  AreaAxes a = areaAxes(l, Vec3(0, 0, 0));
  CHECK(glm::length(a.u - Vec3(2, 0, 0)) < 1e-15);
  CHECK(glm::length(a.v - Vec3(0, 0, -2)) < 1e-15);
  // d = (0.6, 0.8, 0): d × z = (0.8, −0.6, 0), d × that = (0, 0, −1).
  a = areaAxes(l, Vec3(-6, 2, 0));
  CHECK(glm::length(a.u - Vec3(1.6, -1.2, 0)) < 1e-15);
  CHECK(glm::length(a.v - Vec3(0, 0, -2)) < 1e-15);
  // Within 0.01 of ±z POV-Ray crosses with y: d = z gives z × y = −x, z × −x = −y.
  l.position = Vec3(0, 0, 10);
  a = areaAxes(l, Vec3(0, 0, 0));
  CHECK(glm::length(a.u - Vec3(-2, 0, 0)) < 1e-15);
  CHECK(glm::length(a.v - Vec3(0, -2, 0)) < 1e-15);
  // At any point: both axes across d, across each other, as long as u, u across the
  // reference axis, and (u, v, d) right-handed; the samples use them.
  const Vec3 points[] = {Vec3(3, -1, 2), Vec3(-5, 4, 9.9), Vec3(0.05, 0.03, -7), Vec3(1, 2, 3)};
  for (const Vec3& p : points) {
    const Vec3 d = glm::normalize(l.position - p);
    const Vec3 reference = std::abs(std::abs(d.z) - 1.0) < 0.01 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    a = areaAxes(l, p);
    CHECK(glm::length(a.u) == Approx(2.0));
    CHECK(glm::length(a.v) == Approx(2.0));
    CHECK(std::abs(glm::dot(a.u, d)) < 1e-12);
    CHECK(std::abs(glm::dot(a.v, d)) < 1e-12);
    CHECK(std::abs(glm::dot(a.u, a.v)) < 1e-12);
    CHECK(std::abs(glm::dot(a.u, reference)) < 1e-12);
    CHECK(glm::dot(glm::cross(a.u, a.v), d) == Approx(4.0));
    for (int k = 0; k < 16; ++k) {
      const Vec2 xy = polarGridPoint(k % 4, k / 4, 4, 4);
      const Vec3 expected = l.position + a.u * xy.x + a.v * xy.y;
      CHECK(glm::length(lightSamplePoint(l, a, k, Vec2(0.5)) - expected) < 1e-12);
    }
  }
  // A light that does not turn keeps its axes.
  l.orient = false;
  a = areaAxes(l, Vec3(3, -1, 2));
  CHECK(a.u == l.u);
  CHECK(a.v == l.v);
}

TEST_CASE("an oriented circular light's shadow counts its turned samples", "[render][shadow]") {
  // A white floor; the light up and to the side, so that it turns to face the origin.
  Scene scene;
  Material white;
  white.diffuse = Color(1.0f);
  addShape(scene, PlaneSpec{Vec3(0, 1, 0), 0.0}, addMaterial(scene, white));
  Light l = areaLight(Vec3(6, 8, 0), Vec3(2, 0, 0), Vec3(0, 0, 2), 4, 4);
  l.circular = true;
  l.orient = true;
  scene.lights.push_back(l);
  // A slab over x > 4.25 between y = 4 and 5 hides the samples with x/y > 0.85: a shadow
  // ray from the origin meets its top face, y = 5, at x = 5·x/y.
  Material opaque;
  addShape(scene, BoxSpec{Vec3(4.25, 4, -50), Vec3(50, 5, 50)}, addMaterial(scene, opaque));
  auto litShare = [&](const Vec3& u, const Vec3& v) {
    int lit = 0;
    for (int k = 0; k < 16; ++k) {
      const Vec2 xy = polarGridPoint(k % 4, k / 4, 4, 4);
      const Vec3 s = l.position + u * xy.x + v * xy.y;
      REQUIRE(std::abs(s.x / s.y - 0.85) > 1e-3);
      lit += s.x / s.y < 0.85 ? 1 : 0;
    }
    return lit / 16.0;
  };
  // Facing the origin, d = (0.6, 0.8, 0): the axes 2·(0.8, −0.6, 0) and 2·(0, 0, −1).
  const double turned = litShare(Vec3(1.6, -1.2, 0), Vec3(0, 0, -2));
  const double flat = litShare(l.u, l.v);
  CHECK(turned == 12.0 / 16.0);  // the turn changes which samples the slab hides
  CHECK(flat == 14.0 / 16.0);
  const Ray eye(Vec3(0, 1, 3), glm::normalize(Vec3(0, -1, -3)));
  {
    World world(scene);
    // N·L = 0.8 from the centre.
    CHECK(traceOne(world, eye).r == Approx(0.8 * turned).epsilon(1e-6));
  }
  scene.lights[0].orient = false;
  World world(scene);
  CHECK(traceOne(world, eye).r == Approx(0.8 * flat).epsilon(1e-6));
}
