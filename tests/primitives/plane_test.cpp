#include "shape_checks.h"

#include "primitives/plane.h"

#include <catch2/catch.hpp>
#include <limits>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("plane: distance, outward normal and unbounded bounds", "[primitives][plane]") {
  Plane p(Vec3(0, 1, 0), -1.0);  // y = -1, inside below
  CHECK_FALSE(p.bounds().isBounded());
  Ray ray(Vec3(0, 3, 0), Vec3(0, -2, 0));
  Hit h;
  REQUIRE(p.intersect(ray, h));
  CHECK(h.t == 2.0);
  SurfaceInfo si = p.surface(ray, h);
  CHECK(si.ng == Vec3(0, 1, 0));
  CHECK(si.p.y == -1.0);
  // A ray parallel to the plane never hits it.
  CHECK_FALSE(p.intersect(Ray(Vec3(0, 3, 0), Vec3(1, 0, 0)), h));
  // A tilted plane: normal (1,1,0)/√2, offset √2: x + y = 2.
  Plane q(glm::normalize(Vec3(1, 1, 0)), std::sqrt(2.0));
  REQUIRE(q.intersect(Ray(Vec3(0.0), Vec3(1, 0, 0)), h));
  CHECK_THAT(h.t, WithinRel(2.0, 1e-15));
}

TEST_CASE("plane: square to an axis, its box bounds the half-space on that axis",
          "[primitives][plane]") {
  const double inf = std::numeric_limits<double>::infinity();
  // y < 2: the box's top is y = 2, every other side unbounded.
  AABB b = Plane(Vec3(0, 1, 0), 2.0).bounds();
  CHECK(b.hi.y == 2.0);
  CHECK(b.lo.y == -inf);
  CHECK(b.lo.x == -inf);
  CHECK(b.hi.z == inf);
  // -z < 1.5, that is z > -1.5: the box's bottom.
  b = Plane(Vec3(0, 0, -1), 1.5).bounds();
  CHECK(b.lo.z == -1.5);
  CHECK(b.hi.z == inf);
  // A tilted plane bounds nothing.
  b = Plane(glm::normalize(Vec3(1, 1, 0)), 1.0).bounds();
  CHECK(b.lo == Vec3(-inf));
  CHECK(b.hi == Vec3(inf));
}

TEST_CASE("plane: the half-space below is inside, crossings say so", "[primitives][plane]") {
  Plane p(Vec3(0, 0, 1), 2.0);  // z < 2 inside
  CHECK(p.inside(Vec3(5, 5, 1.999)));
  CHECK_FALSE(p.inside(Vec3(5, 5, 2.001)));
  CrossingList cl;
  p.crossings(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), cl);  // from outside, entering at t = 3
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[0].hit.t == 3.0);
  cl.clear();
  p.crossings(Ray(Vec3(0, 0, 0), Vec3(0, 0, 1)), cl);  // from inside, leaving at t = 2
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK_FALSE(cl.items[0].entering);
  cl.clear();
  p.crossings(Ray(Vec3(0, 0, 0), Vec3(1, 0, 0)), cl);  // parallel, inside
  CHECK(cl.startsInside);
  CHECK(cl.items.empty());
  cl.clear();
  p.crossings(Ray(Vec3(0, 0, 0), Vec3(0, 0, -1)), cl);  // inside, moving away
  CHECK(cl.startsInside);
  CHECK(cl.items.empty());
}

TEST_CASE("plane: inside() is n·x < offset on random points", "[primitives][plane]") {
  Rng rng(3);
  Vec3 n = glm::normalize(Vec3(0.3, -0.4, 0.8));
  Plane p(n, 0.2);
  for (int i = 0; i < 10000; ++i) {
    Vec3 x = randomInBox(rng, Vec3(-2.0), Vec3(2.0));
    double s = glm::dot(n, x) - 0.2;
    if (std::abs(s) < 1e-12) continue;
    REQUIRE(p.inside(x) == (s < 0.0));
  }
}

TEST_CASE("plane: (u,v) are world units along the documented tangents", "[primitives][plane]") {
  Plane ground(Vec3(0, 1, 0), 0.0);
  Ray ray(Vec3(1.5, 2, -3.25), Vec3(0, -1, 0));
  Hit h;
  REQUIRE(ground.intersect(ray, h));
  SurfaceInfo si = ground.surface(ray, h);
  CHECK(si.hasUV);
  CHECK_THAT(si.uv.x, WithinAbs(1.5, 1e-15));   // u = x
  CHECK_THAT(si.uv.y, WithinAbs(3.25, 1e-15));  // v = -z
  Plane wall(Vec3(0, 0, 1), -5.0);              // facing the default camera: u = x, v = y
  ray = Ray(Vec3(0.5, 0.75, 0), Vec3(0, 0, -1));
  REQUIRE(wall.intersect(ray, h));
  si = wall.surface(ray, h);
  CHECK_THAT(si.uv.x, WithinAbs(0.5, 1e-15));
  CHECK_THAT(si.uv.y, WithinAbs(0.75, 1e-15));
  // The frame is right-handed for any normal.
  Rng rng(4);
  for (int i = 0; i < 1000; ++i) {
    Vec3 n = randomUnit(rng), t1, t2;
    planeTangents(n, t1, t2);
    REQUIRE(std::abs(glm::dot(glm::cross(t1, t2), n) - 1.0) < 1e-12);
    REQUIRE(std::abs(glm::dot(t1, n)) < 1e-12);
  }
}
