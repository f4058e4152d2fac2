#include "shape_checks.h"

#include "primitives/torus.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("torus: the four crossings of a ray through the middle", "[primitives][torus]") {
  Torus t(1.0, 0.25);
  CrossingList cl;
  t.crossings(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), cl);
  REQUIRE(cl.items.size() == 4);
  const double expect[4] = {3.75, 4.25, 5.75, 6.25};
  for (int i = 0; i < 4; ++i) {
    CHECK_THAT(cl.items[i].hit.t, WithinRel(expect[i], 1e-15));
    CHECK(cl.items[i].entering == (i % 2 == 0));
  }
  Hit h;
  REQUIRE(t.intersect(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), h));
  SurfaceInfo si = t.surface(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), h);
  CHECK_THAT(si.ng.z, WithinAbs(1.0, 1e-15));
  // From inside the tube.
  cl.clear();
  t.crossings(Ray(Vec3(0, 0, 1), Vec3(0, 0, -1)), cl);
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 3);
  CHECK_THAT(cl.items[0].hit.t, WithinRel(0.25, 1e-15));
  CHECK_FALSE(cl.items[0].entering);
  // The inner wall's normal faces the hole.
  REQUIRE(t.intersect(Ray(Vec3(0, 0, 1), Vec3(0, 0, -1)), h));
  si = t.surface(Ray(Vec3(0, 0, 1), Vec3(0, 0, -1)), h);
  CHECK_THAT(si.ng.z, WithinAbs(-1.0, 1e-15));
}

TEST_CASE("torus: down the axis, through the hole, and over the top", "[primitives][torus]") {
  Torus t(1.0, 0.25);
  Hit h;
  CHECK_FALSE(t.intersect(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), h));  // the axis: through the hole
  CHECK_FALSE(t.intersect(Ray(Vec3(0.5, 5, 0.2), Vec3(0, -1, 0)), h));
  REQUIRE(t.intersect(Ray(Vec3(1, 5, 0), Vec3(0, -1, 0)), h));  // down through the tube
  CHECK_THAT(h.t, WithinRel(4.75, 1e-15));
  SurfaceInfo si = t.surface(Ray(Vec3(1, 5, 0), Vec3(0, -1, 0)), h);
  CHECK_THAT(si.ng.y, WithinAbs(1.0, 1e-15));
  // Parallel to the axis at x = 1.2: y = ±√(0.0625 − 0.04) = ±0.15.
  REQUIRE(t.intersect(Ray(Vec3(1.2, 5, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinRel(4.85, 1e-15));
}

TEST_CASE("torus: inside() against the analytic formula", "[primitives][torus]") {
  Rng rng(12);
  Torus t(0.7, 0.2);
  for (int i = 0; i < 10000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    double rho = std::sqrt(p.x * p.x + p.z * p.z);
    double d2 = (rho - 0.7) * (rho - 0.7) + p.y * p.y;
    if (std::abs(d2 - 0.04) < 1e-12) continue;
    REQUIRE(t.inside(p) == (d2 < 0.04));
  }
}
