#include "shape_checks.h"

#include "primitives/sphere.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("sphere: hits at the analytic distances with outward normals", "[primitives][sphere]") {
  Sphere s(Vec3(1, 2, 3), 2.0);
  // From (1, 2, 10) straight down -z: the sphere spans z in [1, 5].
  Ray ray(Vec3(1, 2, 10), Vec3(0, 0, -1));
  Hit h;
  REQUIRE(s.intersect(ray, h));
  CHECK(h.t == 5.0);
  SurfaceInfo si = s.surface(ray, h);
  CHECK(si.p == Vec3(1, 2, 5));
  CHECK(si.ng == Vec3(0, 0, 1));
  // A direction of length 2 halves t (t is never renormalised).
  Ray fast(Vec3(1, 2, 10), Vec3(0, 0, -2));
  REQUIRE(s.intersect(fast, h));
  CHECK(h.t == 2.5);
  // An off-centre ray: x = 1 + 1.2 meets z = 3 ± 1.6.
  Ray off(Vec3(2.2, 2, 10), Vec3(0, 0, -1));
  REQUIRE(s.intersect(off, h));
  CHECK_THAT(h.t, WithinRel(10.0 - 4.6, 1e-15));
  si = s.surface(off, h);
  CHECK_THAT(si.ng.x, WithinRel(0.6, 1e-15));
  CHECK_THAT(si.ng.z, WithinRel(0.8, 1e-15));
}

TEST_CASE("sphere: crossings from outside, inside and beyond", "[primitives][sphere]") {
  Sphere s(Vec3(0.0), 1.0);
  CrossingList cl;
  s.crossings(Ray(Vec3(0, 0, 3), Vec3(0, 0, -1)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_FALSE(cl.startsInside);
  CHECK(cl.items[0].hit.t == 2.0);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[1].hit.t == 4.0);
  CHECK_FALSE(cl.items[1].entering);

  cl.clear();
  s.crossings(Ray(Vec3(0, 0, 0.5), Vec3(0, 0, -1)), cl);  // starts inside
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].hit.t == 1.5);
  CHECK_FALSE(cl.items[0].entering);

  cl.clear();
  s.crossings(Ray(Vec3(0, 0, -2), Vec3(0, 0, -1)), cl);  // the sphere is behind
  CHECK_FALSE(cl.startsInside);
  CHECK(cl.items.empty());

  cl.clear();
  s.crossings(Ray(Vec3(0, 0, 3), Vec3(0, 0, -1), 2.0, 3.0), cl);  // tmin exactly on the surface
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
  CHECK(cl.items[0].hit.t == 2.0);
  Hit h;
  CHECK_FALSE(s.intersect(Ray(Vec3(0, 0, 3), Vec3(0, 0, -1), 2.0, 3.0), h));  // strict (tmin, tmax)
}

TEST_CASE("sphere: inside() is |p - c| < r on random points", "[primitives][sphere]") {
  Rng rng(1);
  Sphere s(Vec3(0.3, -0.2, 0.1), 0.7);
  for (int i = 0; i < 10000; ++i) {
    Vec3 p = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    double d = glm::length(p - Vec3(0.3, -0.2, 0.1));
    if (std::abs(d - 0.7) < 1e-12) continue;
    REQUIRE(s.inside(p) == (d < 0.7));
  }
}

TEST_CASE("sphere: (u,v) follow the documented longitude and colatitude", "[primitives][sphere]") {
  Sphere s(Vec3(0.0), 2.0);
  auto uvAt = [&](const Vec3& dir) {
    Ray ray(3.0 * dir, -dir);
    Hit h;
    REQUIRE(s.intersect(ray, h));
    SurfaceInfo si = s.surface(ray, h);
    CHECK(si.hasUV);
    return si.uv;
  };
  Vec2 uv = uvAt(Vec3(0, 0, 1));  // facing the default camera
  CHECK_THAT(uv.x, WithinAbs(0.5, 1e-15));
  CHECK_THAT(uv.y, WithinAbs(0.5, 1e-15));
  uv = uvAt(Vec3(1, 0, 0));
  CHECK_THAT(uv.x, WithinAbs(0.75, 1e-15));
  uv = uvAt(Vec3(-1, 0, 0));
  CHECK_THAT(uv.x, WithinAbs(0.25, 1e-15));
  uv = uvAt(Vec3(0, 1, 0));  // north pole: the image's top row
  CHECK_THAT(uv.y, WithinAbs(1.0, 1e-15));
  uv = uvAt(Vec3(0, -1, 0));
  CHECK_THAT(uv.y, WithinAbs(0.0, 1e-15));
  uv = uvAt(glm::normalize(Vec3(0, 1, 1)));  // 45° from the pole
  CHECK_THAT(uv.y, WithinAbs(0.75, 1e-15));
}

TEST_CASE("sphere: rays from far away and rays starting near the surface keep their digits",
          "[primitives][sphere]") {
  // A unit sphere 1e5 from the camera: the textbook quadratic loses ~10 digits of the
  // discriminant here; the distance form keeps t to a few ulps.
  Sphere s(Vec3(1e5, 0, 0), 1.0);
  Hit h;
  REQUIRE(s.intersect(Ray(Vec3(0.0), Vec3(1, 0, 0)), h));
  CHECK_THAT(h.t, WithinRel(1e5 - 1.0, 4e-16));
  // Off-centre: y = 0.6 meets x = 1e5 − 0.8.
  REQUIRE(s.intersect(Ray(Vec3(0, 0.6, 0), Vec3(1, 0, 0)), h));
  CHECK_THAT(h.t, WithinRel(1e5 - 0.8, 4e-16));
  // Starting 1e-12 inside the surface: the far root is 2 − 1e-12, the near one −1e-12.
  Sphere unit(Vec3(0.0), 1.0);
  CrossingList cl;
  unit.crossings(Ray(Vec3(-1.0 + 1e-12, 0, 0), Vec3(1, 0, 0)), cl);
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK_THAT(cl.items[0].hit.t, WithinRel(2.0 - 1e-12, 1e-11));
}
