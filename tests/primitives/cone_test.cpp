#include "shape_checks.h"

#include "primitives/cone.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("cone: side hits at analytic distances with slanted outward normals",
          "[primitives][cone]") {
  // Base radius 1 at y = 0, apex at y = 2: radius 0.5 at y = 1.
  Cone c(Vec3(0, 0, 0), 1.0, Vec3(0, 2, 0), 0.0, false);
  Hit h;
  Ray ray(Vec3(0, 1, 5), Vec3(0, 0, -1));
  REQUIRE(c.intersect(ray, h));
  CHECK_THAT(h.t, WithinRel(4.5, 1e-15));
  CHECK(h.part == 0);
  SurfaceInfo si = c.surface(ray, h);
  // The side's normal leans up by the slope: (0, 1, 2)/√5 in the yz-plane.
  CHECK_THAT(si.ng.y, WithinRel(1.0 / std::sqrt(5.0), 1e-14));
  CHECK_THAT(si.ng.z, WithinRel(2.0 / std::sqrt(5.0), 1e-14));
  // Up the axis from below: the base disc at t = 5.
  Ray up(Vec3(0, -5, 0), Vec3(0, 1, 0));
  REQUIRE(c.intersect(up, h));
  CHECK(h.t == 5.0);
  CHECK(h.part == 1);
  si = c.surface(up, h);
  CHECK_THAT(si.ng.y, WithinAbs(-1.0, 1e-15));
  CrossingList cl;
  c.crossings(up, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[1].hit.t, WithinRel(7.0, 1e-15));  // out through the apex
  // The mirrored nappe above the apex is not part of the cone.
  CHECK_FALSE(c.intersect(Ray(Vec3(0, 3, 5), Vec3(0, 0, -1)), h));
}

TEST_CASE("cone: truncated, apex at the base, and open", "[primitives][cone]") {
  Cone t(Vec3(0, 0, 0), 0.5, Vec3(0, 2, 0), 1.0, false);  // widening upwards
  Hit h;
  REQUIRE(t.intersect(Ray(Vec3(0, 1, 5), Vec3(0, 0, -1)), h));
  CHECK_THAT(h.t, WithinRel(4.25, 1e-15));
  REQUIRE(t.intersect(Ray(Vec3(0.9, 5, 0), Vec3(0, -1, 0)), h));  // the cap disc (r = 1)
  CHECK(h.t == 3.0);
  CHECK(h.part == 2);
  CHECK_FALSE(t.intersect(Ray(Vec3(0.9, -5, 0), Vec3(0, 1, 0), 0.0, 5.0), h));

  Cone apexBase(Vec3(0, 0, 0), 0.0, Vec3(0, 0, 2), 1.0, false);
  REQUIRE(apexBase.intersect(Ray(Vec3(0, 5, 1), Vec3(0, -1, 0)), h));  // radius 0.5 at z = 1
  CHECK_THAT(h.t, WithinRel(4.5, 1e-15));

  Cone open(Vec3(0, 0, 0), 1.0, Vec3(0, 1, 0), 0.5, true);
  CHECK_FALSE(open.isSolid());
  CHECK_FALSE(open.intersect(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), h));  // through both ends
  CrossingList cl;
  open.crossings(Ray(Vec3(0, 0.5, 5), Vec3(0, 0, -1)), cl);  // radius 0.75 at y = 0.5
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinRel(4.25, 1e-15));
  CHECK_THAT(cl.items[1].hit.t, WithinRel(5.75, 1e-15));
  CHECK(cl.items[1].entering);
}

TEST_CASE("cone: inside() against the analytic formula", "[primitives][cone]") {
  Rng rng(6);
  Cone c(Vec3(0, -1, 0), 0.2, Vec3(0, 1, 0), 0.9, false);
  for (int i = 0; i < 10000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    double r = 0.2 + 0.35 * (p.y + 1.0);
    double rho = std::sqrt(p.x * p.x + p.z * p.z);
    if (std::abs(rho - r) < 1e-12) continue;
    REQUIRE(c.inside(p) == (rho < r && p.y > -1.0 && p.y < 1.0));
  }
}

TEST_CASE("cone: equal radii behave like a cylinder", "[primitives][cone]") {
  Cone c(Vec3(0, 0, 0), 1.0, Vec3(0, 2, 0), 1.0, false);
  Hit h;
  REQUIRE(c.intersect(Ray(Vec3(0, 1, 5), Vec3(0, 0, -1)), h));
  CHECK(h.t == 4.0);
  REQUIRE(c.intersect(Ray(Vec3(0, 1, 0), Vec3(0, 0, -1)), h));  // from inside
  CHECK(h.t == 1.0);
}
