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

TEST_CASE("torus: lines just outside and just inside its hull", "[primitives][torus]") {
  // The quartic is skipped for lines that keep clear of the hull (|y| <= r, R - r <= ρ <=
  // R + r) by more than a millionth; lines nearer than that must still get its answer.
  const double R = 1.0, r = 0.25;
  Torus t(R, r);
  double roots[4];
  for (double rel : {1e-3, 1e-5, 1e-7}) {
    // Along z, grazing the outer equator from outside (no root) and from inside (two).
    CHECK(t.lineRoots(Ray(Vec3(R + r + rel, 0, 5), Vec3(0, 0, -1)), roots) == 0);
    REQUIRE(t.lineRoots(Ray(Vec3(R + r - rel, 0, 5), Vec3(0, 0, -1)), roots) == 2);
    CHECK(roots[0] < 5.0);
    CHECK(roots[1] > 5.0);
    // Parallel to the axis through the hole, just inside the inner equator (no root) and
    // just beyond it (two).
    CHECK(t.lineRoots(Ray(Vec3(R - r - rel, 5, 0), Vec3(0, -1, 0)), roots) == 0);
    REQUIRE(t.lineRoots(Ray(Vec3(R - r + rel, 5, 0), Vec3(0, -1, 0)), roots) == 2);
    CHECK_THAT(roots[0] + roots[1], WithinRel(10.0, 1e-9));
    // Over the top, just above the slab (no root) and just within it (two).
    CHECK(t.lineRoots(Ray(Vec3(R, r + rel, 5), Vec3(0, 0, -1)), roots) == 0);
    CHECK(t.lineRoots(Ray(Vec3(R, r - rel, 5), Vec3(0, 0, -1)), roots) == 2);
  }
  // A line far from the torus in every sense, and one crossing the slab outside R + r.
  CHECK(t.lineRoots(Ray(Vec3(0, 3, 5), Vec3(0, 0, -1)), roots) == 0);
  CHECK(t.lineRoots(Ray(Vec3(1.3, 5, 0.2), Vec3(0.01, -1, 0)), roots) == 0);
}
