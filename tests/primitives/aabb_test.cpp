// Slab test: the hard cases (signed zero directions, origins inside and on the
// box, clipped ranges) with exact expected distances.
#include "primitives/aabb.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <limits>

using namespace lucent;

namespace {
Interval slab(const AABB& box, const Ray& r) { return box.slab(r, 1.0 / r.d); }
const AABB unit{Vec3(-1.0), Vec3(1.0)};
}  // namespace

TEST_CASE("slab test gives the entry and exit distances of a ray from outside", "[aabb]") {
  Interval i = slab(unit, Ray(Vec3(-3, 0, 0), Vec3(1, 0, 0)));
  REQUIRE_FALSE(i.empty());
  CHECK(i.lo == 2.0);
  CHECK(i.hi == Approx(4.0).epsilon(1e-15));
  CHECK(i.hi >= 4.0);  // widened, never narrowed (Ize 2013)
}

TEST_CASE("slab test handles unnormalised diagonal directions", "[aabb]") {
  Interval i = slab(unit, Ray(Vec3(-3, -3, -3), Vec3(2, 2, 2)));
  REQUIRE_FALSE(i.empty());
  CHECK(i.lo == 1.0);
  CHECK(i.hi == Approx(2.0));
}

TEST_CASE("slab test misses boxes behind the ray and beside it", "[aabb]") {
  CHECK(slab(unit, Ray(Vec3(3, 0, 0), Vec3(1, 0, 0))).empty());
  CHECK(slab(unit, Ray(Vec3(-3, 2, 0), Vec3(1, 0, 0))).empty());
  CHECK(slab(unit, Ray(Vec3(-3, 0, 0), Vec3(1, 1.01, 0))).empty());
}

TEST_CASE("slab test with +0 and -0 direction components", "[aabb]") {
  // The zero component's inverse is +inf or -inf; inside that slab the ray hits.
  for (double zero : {0.0, -0.0}) {
    Ray inside(Vec3(-3, 0.5, 0.25), Vec3(1, zero, zero));
    Interval i = slab(unit, inside);
    REQUIRE_FALSE(i.empty());
    CHECK(i.lo == 2.0);
    CHECK(i.hi == Approx(4.0));
    // Outside that slab it misses, on both sides.
    CHECK(slab(unit, Ray(Vec3(-3, 1.5, 0), Vec3(1, zero, 0))).empty());
    CHECK(slab(unit, Ray(Vec3(-3, -1.5, 0), Vec3(1, zero, 0))).empty());
  }
}

TEST_CASE("slab test counts a ray running inside a face plane as hitting the closed box",
          "[aabb]") {
  // Origin exactly on the slab plane y = 1 with a zero y component: (1 - 1) * inf is NaN
  // in a naive implementation.
  for (double zero : {0.0, -0.0}) {
    Interval i = slab(unit, Ray(Vec3(-3, 1, 0), Vec3(1, zero, 0)));
    REQUIRE_FALSE(i.empty());
    CHECK(i.lo == 2.0);
    CHECK(i.hi == Approx(4.0));
  }
}

TEST_CASE("slab test from an origin inside the box starts at tmin", "[aabb]") {
  Interval i = slab(unit, Ray(Vec3(0.5, 0, 0), Vec3(1, 0, 0)));
  REQUIRE_FALSE(i.empty());
  CHECK(i.lo == 0.0);
  CHECK(i.hi == Approx(0.5));
  Interval back = slab(unit, Ray(Vec3(0.5, 0, 0), Vec3(-1, 0, 0)));
  CHECK(back.lo == 0.0);
  CHECK(back.hi == Approx(1.5));
}

TEST_CASE("slab test is clipped to the ray's [tmin, tmax]", "[aabb]") {
  Ray r(Vec3(-3, 0, 0), Vec3(1, 0, 0));
  r.tmax = 1.5;  // ends before the box
  CHECK(slab(unit, r).empty());
  r.tmin = 4.5;  // starts after the box
  r.tmax = kInf;
  CHECK(slab(unit, r).empty());
  r.tmin = 2.5;  // starts inside, ends inside
  r.tmax = 3.0;
  Interval i = slab(unit, r);
  REQUIRE_FALSE(i.empty());
  CHECK(i.lo == 2.5);
  CHECK(i.hi == 3.0);
}

TEST_CASE("slab test with a negative direction swaps near and far", "[aabb]") {
  Interval i = slab(unit, Ray(Vec3(0, 0, 5), Vec3(0, 0, -2)));
  CHECK(i.lo == 2.0);
  CHECK(i.hi == Approx(3.0));
}

TEST_CASE("an unbounded box contains every ray", "[aabb]") {
  AABB all = AABB::everything();
  for (Vec3 d : {Vec3(1, 0, 0), Vec3(0, -0.0, 1), Vec3(0.3, -0.2, 0.9)}) {
    Interval i = slab(all, Ray(Vec3(2, 3, 4), d));
    REQUIRE_FALSE(i.empty());
    CHECK(i.lo == 0.0);
    CHECK(i.hi == kInf);
  }
}

TEST_CASE("slab test never loses a hit on shared faces of touching boxes", "[aabb]") {
  // Two boxes share the face x = 0.3; rays crossing the face at random points must
  // be inside at least one box at every sampled t (no gap from rounding).
  AABB a(Vec3(-1, -1, -1), Vec3(0.3, 1, 1)), b(Vec3(0.3, -1, -1), Vec3(1, 1, 1));
  uint32_t seed = 12345;
  auto rnd = [&] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0;
  };
  for (int k = 0; k < 10000; ++k) {
    Vec3 o(-5.0, rnd() * 1.8 - 0.9, rnd() * 1.8 - 0.9);
    Vec3 target(0.3, rnd() * 1.8 - 0.9, rnd() * 1.8 - 0.9);
    Ray r(o, target - o);
    Interval ia = slab(a, r), ib = slab(b, r);
    REQUIRE_FALSE(ia.empty());
    REQUIRE_FALSE(ib.empty());
    CHECK(ia.hi >= ib.lo);  // the two intervals meet or overlap at the shared face
  }
}

TEST_CASE("box of a transformed box holds all eight corners", "[aabb]") {
  Mat4 m = glm::translate(Mat4(1.0), Vec3(1, 2, 3));
  AABB b = transformBounds(m, unit);
  CHECK(b.lo == Vec3(0, 1, 2));
  CHECK(b.hi == Vec3(2, 3, 4));
  CHECK(unit.surfaceArea() == 24.0);
}

TEST_CASE("an unbounded box keeps its finite sides where the transform keeps the axes", "[aabb]") {
  const double inf = std::numeric_limits<double>::infinity();
  // The half-space z >= 0 and the infinite square column |x|, |y| <= 1.
  const AABB half{Vec3(-inf, -inf, 0.0), Vec3(inf)};
  const AABB column{Vec3(-1.0, -1.0, -inf), Vec3(1.0, 1.0, inf)};
  // A scale and a translation: every side stays, scaled and moved.
  Mat4 m = glm::translate(Mat4(1.0), Vec3(0, 0, 3)) * glm::scale(Mat4(1.0), Vec3(2.0));
  AABB b = transformBounds(m, half);
  CHECK(b.lo.z == 3.0);
  CHECK(b.hi.z == inf);
  CHECK(b.lo.x == -inf);
  // An exact quarter turn about x (z to -y, y to z): the half-space becomes y <= 0.
  Mat4 q(1.0);
  q[1] = Vec4(0, 0, 1, 0);   // y -> z
  q[2] = Vec4(0, -1, 0, 0);  // z -> -y
  b = transformBounds(q, half);
  CHECK(b.hi.y == 0.0);
  CHECK(b.lo.y == -inf);
  CHECK(b.lo.z == -inf);
  CHECK(b.hi.z == inf);
  // A turn about the column's own axis: bounded across it by the turned square.
  b = transformBounds(glm::rotate(Mat4(1.0), glm::radians(30.0), Vec3(0, 0, 1)), column);
  const double reach = std::cos(glm::radians(30.0)) + std::sin(glm::radians(30.0));
  CHECK(b.hi.x == Approx(reach).epsilon(1e-15));
  CHECK(b.lo.y == Approx(-reach).epsilon(1e-15));
  CHECK(b.lo.z == -inf);
  CHECK(b.hi.z == inf);
  // A turn that tilts the axis (even by a rounding, as glm's quarter turn about x has
  // 6e-17 for its cosine): unbounded where the infinite side now reaches, no NaN anywhere.
  b = transformBounds(glm::rotate(Mat4(1.0), glm::radians(-90.0), Vec3(1, 0, 0)), column);
  CHECK(b.lo.x == -1.0);
  CHECK(b.hi.x == 1.0);
  CHECK(b.lo.y == -inf);
  CHECK(b.hi.y == inf);
  CHECK(b.lo.z == -inf);
  CHECK(b.hi.z == inf);
  // A box unbounded everywhere stays so.
  b = transformBounds(m, AABB::everything());
  CHECK(b.lo == Vec3(-inf));
  CHECK(b.hi == Vec3(inf));
}
