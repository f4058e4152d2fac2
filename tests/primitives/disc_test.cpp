#include "shape_checks.h"

#include "primitives/disc.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

TEST_CASE("disc: hits between the hole and the rim, from both sides", "[primitives][disc]") {
  Disc d(Vec3(1, 2, 3), Vec3(0, 1, 0), 1.0, 0.5);
  CHECK_FALSE(d.isSolid());
  Hit h;
  REQUIRE(d.intersect(Ray(Vec3(1.75, 5, 3), Vec3(0, -1, 0)), h));
  CHECK(h.t == 3.0);
  SurfaceInfo si = d.surface(Ray(Vec3(1.75, 5, 3), Vec3(0, -1, 0)), h);
  CHECK(si.ng == Vec3(0, 1, 0));
  CHECK(si.p.y == 2.0);
  REQUIRE(d.intersect(Ray(Vec3(1.75, -5, 3), Vec3(0, 2, 0)), h));  // from below
  CHECK(h.t == 3.5);
  CHECK_FALSE(d.intersect(Ray(Vec3(1.25, 5, 3), Vec3(0, -1, 0)), h));  // the hole
  CHECK_FALSE(d.intersect(Ray(Vec3(2.25, 5, 3), Vec3(0, -1, 0)), h));  // beyond the rim
  CHECK(d.intersect(Ray(Vec3(2.0, 5, 3), Vec3(0, -1, 0)), h));         // on the rim
  CHECK(d.intersect(Ray(Vec3(1.5, 5, 3), Vec3(0, -1, 0)), h));         // on the hole's rim
  CHECK_FALSE(d.intersect(Ray(Vec3(1.5, 5, 3), Vec3(1, 0, 0)), h));    // parallel
  CrossingList cl;
  d.crossings(Ray(Vec3(1.75, 5, 3), Vec3(0, -1, 0)), cl);
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
}

TEST_CASE("disc: bounds are tight and (u,v) are measured from the centre", "[primitives][disc]") {
  Disc tilted(Vec3(0.0), glm::normalize(Vec3(1, 1, 0)), 2.0, 0.0);
  AABB b = tilted.bounds();
  CHECK_THAT(b.hi.x, WithinAbs(std::sqrt(2.0), 1e-15));
  CHECK_THAT(b.hi.z, WithinAbs(2.0, 1e-15));
  Disc flat(Vec3(1, 0, 1), Vec3(0, 1, 0), 2.0, 0.0);
  Ray ray(Vec3(1.5, 1, 0.25), Vec3(0, -1, 0));
  Hit h;
  REQUIRE(flat.intersect(ray, h));
  SurfaceInfo si = flat.surface(ray, h);
  CHECK(si.hasUV);
  CHECK_THAT(si.uv.x, WithinAbs(0.5, 1e-15));   // x − cx
  CHECK_THAT(si.uv.y, WithinAbs(0.75, 1e-15));  // −(z − cz)
}
