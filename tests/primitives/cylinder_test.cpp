#include "shape_checks.h"

#include "primitives/cylinder.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("cylinder: side and caps at analytic distances, outward normals",
          "[primitives][cylinder]") {
  Cylinder c(Vec3(0, -1, 0), Vec3(0, 3, 0), 2.0, false);
  Hit h;
  Ray side(Vec3(0, 0, 10), Vec3(0, 0, -1));
  REQUIRE(c.intersect(side, h));
  CHECK(h.t == 8.0);
  CHECK(h.part == 0);
  SurfaceInfo si = c.surface(side, h);
  CHECK_THAT(si.ng.z, WithinAbs(1.0, 1e-15));
  CHECK_THAT(si.p.z, WithinAbs(2.0, 1e-15));
  Ray top(Vec3(1, 10, 0), Vec3(0, -1, 0));
  REQUIRE(c.intersect(top, h));
  CHECK_THAT(h.t, WithinRel(7.0, 1e-15));
  CHECK(h.part == 2);
  si = c.surface(top, h);
  CHECK_THAT(si.ng.y, WithinAbs(1.0, 1e-15));
  CHECK_THAT(si.p.y, WithinAbs(3.0, 1e-15));
  Ray bottom(Vec3(1, -10, 0.5), Vec3(0, 1, 0));
  REQUIRE(c.intersect(bottom, h));
  CHECK_THAT(h.t, WithinRel(9.0, 1e-15));
  CHECK(h.part == 1);
  si = c.surface(bottom, h);
  CHECK_THAT(si.ng.y, WithinAbs(-1.0, 1e-15));
  // A slanted ray: from (5, 2.5, 0) towards (-1, 0, 0)+... meets the side x = 2 at t = 3.
  Ray slant(Vec3(5, 2.5, 0), Vec3(-1, 0, 0));
  REQUIRE(c.intersect(slant, h));
  CHECK_THAT(h.t, WithinRel(3.0, 1e-15));
  // An oblique axis: base (0,0,0), cap (1,1,1)·2/√3 (height 2), radius 0.5. A ray along the
  // axis from outside hits the base disc at distance 1.
  Vec3 a = glm::normalize(Vec3(1, 1, 1));
  Cylinder oblique(Vec3(0.0), 2.0 * a, 0.5, false);
  Ray along(-a, a);
  REQUIRE(oblique.intersect(along, h));
  CHECK_THAT(h.t, WithinRel(1.0, 1e-15));
  CHECK(h.part == 1);
  CrossingList cl;
  oblique.crossings(along, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[1].hit.t, WithinRel(3.0, 1e-15));
}

TEST_CASE("cylinder: crossings from outside, inside and beyond", "[primitives][cylinder]") {
  Cylinder c(Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, false);
  CrossingList cl;
  c.crossings(Ray(Vec3(0, 1, 0), Vec3(1, 0, 0)), cl);
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].hit.t == 1.0);
  CHECK_FALSE(cl.items[0].entering);
  cl.clear();
  c.crossings(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), cl);  // down the axis, through both caps
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == 3.0);
  CHECK(cl.items[0].hit.part == 2);
  CHECK(cl.items[1].hit.t == 5.0);
  CHECK(cl.items[1].hit.part == 1);
  cl.clear();
  c.crossings(Ray(Vec3(0, 1, 5), Vec3(0, 0, 1)), cl);  // beyond
  CHECK_FALSE(cl.startsInside);
  CHECK(cl.items.empty());
}

TEST_CASE("open cylinder: no caps, no volume, both walls are hits", "[primitives][cylinder]") {
  Cylinder c(Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, true);
  CHECK_FALSE(c.isSolid());
  Hit h;
  CHECK_FALSE(c.intersect(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), h));  // through the open ends
  CHECK_FALSE(c.inside(Vec3(0, 1, 0)));
  CrossingList cl;
  c.crossings(Ray(Vec3(0, 1, 5), Vec3(0, 0, -1)), cl);
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == 4.0);
  CHECK(cl.items[1].hit.t == 6.0);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[1].entering);
  // A ray that enters through the open end and leaves through the wall.
  REQUIRE(c.intersect(Ray(Vec3(0, 2.5, 0), Vec3(1, -1, 0)), h));
  CHECK_THAT(h.t, WithinRel(1.0, 1e-15));
}

TEST_CASE("cylinder: inside() against the analytic formula", "[primitives][cylinder]") {
  Rng rng(5);
  Cylinder c(Vec3(0, -0.5, 0), Vec3(0, 0.5, 0), 0.75, false);
  for (int i = 0; i < 10000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    double r2 = p.x * p.x + p.z * p.z;
    if (std::abs(r2 - 0.5625) < 1e-12 || std::abs(std::abs(p.y) - 0.5) < 1e-12) continue;
    REQUIRE(c.inside(p) == (r2 < 0.5625 && std::abs(p.y) < 0.5));
  }
}
