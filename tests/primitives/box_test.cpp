#include "shape_checks.h"

#include "primitives/box.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

TEST_CASE("box: corners in any order, face hits, parts and normals", "[primitives][box]") {
  Box b(Vec3(1, 2, 3), Vec3(-1, -2, -3));  // swapped corners, as POV-Ray allows
  CHECK(b.bounds().lo == Vec3(-1, -2, -3));
  CHECK(b.bounds().hi == Vec3(1, 2, 3));
  struct Case {
    Vec3 o, d;
    double t;
    uint32_t part;
    Vec3 n;
  };
  const Case cases[] = {
      {{5, 0, 0}, {-1, 0, 0}, 4.0, 1, {1, 0, 0}}, {{-5, 0, 0}, {2, 0, 0}, 2.0, 0, {-1, 0, 0}},
      {{0, 7, 0}, {0, -1, 0}, 5.0, 3, {0, 1, 0}}, {{0, -7, 0}, {0, 1, 0}, 5.0, 2, {0, -1, 0}},
      {{0, 0, 9}, {0, 0, -3}, 2.0, 5, {0, 0, 1}}, {{0, 0, -9}, {0, 0, 1}, 6.0, 4, {0, 0, -1}},
  };
  for (const Case& c : cases) {
    Ray ray(c.o, c.d);
    Hit h;
    REQUIRE(b.intersect(ray, h));
    CHECK(h.t == c.t);
    CHECK(h.part == c.part);
    SurfaceInfo si = b.surface(ray, h);
    CHECK(si.ng == c.n);
    CHECK(si.pError[c.part / 2] == 0.0);  // the face coordinate is exact
  }
}

TEST_CASE("box: rays with zero direction components, in face planes and along edges",
          "[primitives][box]") {
  Box b(Vec3(-1.0), Vec3(1.0));
  Hit h;
  // Only z varies: the two zero components must neither exclude nor produce NaN.
  REQUIRE(b.intersect(Ray(Vec3(0.5, -0.5, 4), Vec3(0, 0, -1)), h));
  CHECK(h.t == 3.0);
  // Parallel to a slab, outside it: a miss.
  CHECK_FALSE(b.intersect(Ray(Vec3(1.5, 0, 4), Vec3(0, 0, -1)), h));
  // In the plane x = 1 of a face (closed box): hits the z = 1 face at its rim.
  REQUIRE(b.intersect(Ray(Vec3(1, 0, 4), Vec3(0, 0, -1)), h));
  CHECK(h.t == 3.0);
  // Along the edge x = 1, y = 1.
  REQUIRE(b.intersect(Ray(Vec3(1, 1, 4), Vec3(0, 0, -1)), h));
  CHECK(h.t == 3.0);
  // Diagonal through two opposite corners.
  REQUIRE(b.intersect(Ray(Vec3(-2.0), Vec3(1.0)), h));
  CHECK(h.t == 1.0);
  CrossingList cl;
  b.crossings(Ray(Vec3(-2.0), Vec3(1.0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[1].hit.t == 3.0);
}

TEST_CASE("box: crossings from outside, inside and beyond", "[primitives][box]") {
  Box b(Vec3(0.0), Vec3(1.0));
  CrossingList cl;
  b.crossings(Ray(Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0)), cl);
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].hit.t == 0.5);
  CHECK_FALSE(cl.items[0].entering);
  cl.clear();
  b.crossings(Ray(Vec3(3, 0.5, 0.5), Vec3(1, 0, 0)), cl);
  CHECK_FALSE(cl.startsInside);
  CHECK(cl.items.empty());
  cl.clear();
  b.crossings(Ray(Vec3(-1, 0.5, 0.5), Vec3(1, 0, 0), 0.0, 1.5), cl);
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[0].hit.t == 1.0);
}

TEST_CASE("box: inside() is the open box on random points", "[primitives][box]") {
  Rng rng(2);
  Box b(Vec3(-0.5, 0, 0.25), Vec3(0.5, 1, 0.75));
  for (int i = 0; i < 10000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    bool in = p.x > -0.5 && p.x < 0.5 && p.y > 0 && p.y < 1 && p.z > 0.25 && p.z < 0.75;
    REQUIRE(b.inside(p) == in);
  }
}

TEST_CASE("box: each face has its own [0,1]² seen from outside", "[primitives][box]") {
  Box b(Vec3(0.0), Vec3(2.0, 4.0, 8.0));
  auto uv = [&](const Vec3& o, const Vec3& d) {
    Ray ray(o, d);
    Hit h;
    REQUIRE(b.intersect(ray, h));
    SurfaceInfo si = b.surface(ray, h);
    CHECK(si.hasUV);
    return si.uv;
  };
  // +z face seen from +z: u along +x, v along +y. Point (0.5, 3) -> (0.25, 0.75).
  Vec2 t = uv({0.5, 3, 20}, {0, 0, -1});
  CHECK_THAT(t.x, WithinAbs(0.25, 1e-15));
  CHECK_THAT(t.y, WithinAbs(0.75, 1e-15));
  // -z face seen from -z: u along -x.
  t = uv({0.5, 3, -20}, {0, 0, 1});
  CHECK_THAT(t.x, WithinAbs(0.75, 1e-15));
  CHECK_THAT(t.y, WithinAbs(0.75, 1e-15));
  // +x face seen from +x: u along -z.
  t = uv({20, 1, 2}, {-1, 0, 0});
  CHECK_THAT(t.x, WithinAbs(0.75, 1e-15));
  CHECK_THAT(t.y, WithinAbs(0.25, 1e-15));
  // +y face seen from above: u along +x, v along -z.
  t = uv({0.5, 20, 2}, {0, -1, 0});
  CHECK_THAT(t.x, WithinAbs(0.25, 1e-15));
  CHECK_THAT(t.y, WithinAbs(0.75, 1e-15));
  // -y face seen from below: u along +x, v along +z.
  t = uv({0.5, -20, 2}, {0, 1, 0});
  CHECK_THAT(t.x, WithinAbs(0.25, 1e-15));
  CHECK_THAT(t.y, WithinAbs(0.25, 1e-15));
}
