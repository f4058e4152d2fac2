#include "shape_checks.h"

#include "../support/ovus_reference.h"
#include "primitives/ovus.h"
#include "primitives/sphere.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

using LD = long double;
using LV = OvusReference::LV;

LV toL(const Vec3& v) { return LV(v.x, v.y, v.z); }

// The radii of the tests: POV-Ray's two forms (bottom larger; top larger, below twice the
// bottom), equal radii, a nearly spherical top, and a small top far below the bottom's size.
const double kRadii[][2] = {{1.0, 0.5}, {1.0, 0.9}, {0.8, 0.8}, {1.0, 1.5}, {1.0, 1.9}, {2.0, 0.3}};

}  // namespace

TEST_CASE("ovus: the arc, its centre and its seams are POV-Ray's parser's in both its forms",
          "[primitives][ovus]") {
  for (const auto& r : kRadii) {
    const Ovus::Geometry g = Ovus::geometryOf(r[0], r[1]);
    const OvusReference ref(r[0], r[1]);
    INFO("radii " << r[0] << " " << r[1]);
    REQUIRE(g.lemon);
    CHECK_THAT(g.connecting, WithinRel((double)ref.C, 1e-15));
    CHECK_THAT(g.vertical, WithinAbs((double)ref.V, 1e-14));
    CHECK_THAT(g.horizontal, WithinAbs((double)ref.H, 1e-14));
    CHECK_THAT(g.bottomSeam, WithinAbs((double)ref.bottomSeam, 1e-14));
    CHECK_THAT(g.topSeam, WithinAbs((double)ref.topSeam, 1e-14));
    // Each seam lies on its sphere and on the arc: the same distance from the axis.
    auto arcRho = [&](LD y) {
      return std::sqrt(ref.C * ref.C - (y - ref.V) * (y - ref.V)) - ref.H;
    };
    const LD yb = ref.bottomSeam, yt = ref.topSeam;
    CHECK_THAT((double)arcRho(yb), WithinAbs((double)std::sqrt(ref.rb * ref.rb - yb * yb), 1e-12));
    CHECK_THAT(
        (double)arcRho(yt),
        WithinAbs((double)std::sqrt(ref.rt * ref.rt - (yt - ref.rb) * (yt - ref.rb)), 1e-12));
  }
  // A top radius of twice the bottom one or more: POV-Ray's sphere, no arc.
  CHECK(Ovus::geometryOf(0.5, 1.0).sphereOnly);
  CHECK_FALSE(Ovus::geometryOf(0.5, 0.999).sphereOnly);
  // A top radius of 0: the bottom sphere alone (the seams meet at its top).
  CHECK_FALSE(Ovus::geometryOf(1.0, 0.0).lemon);
}

TEST_CASE("ovus: rays across each piece meet its circle exactly", "[primitives][ovus]") {
  const Ovus ovus(1.0, 0.5);
  const OvusReference ref(1.0, 0.5);
  // Down the axis: the top sphere's pole at y = 1.5, out through the bottom's at y = -1.
  const Ray down(Vec3(0, 5, 0), Vec3(0, -2, 0));
  Hit h;
  REQUIRE(ovus.intersect(down, h));
  CHECK_THAT(h.t * 2, WithinAbs(3.5, 1e-15));
  CHECK(ovus.surface(down, h).ng == Vec3(0, 1, 0));
  CrossingList cl;
  ovus.crossings(down, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[1].hit.t * 2, WithinAbs(6.0, 1e-15));
  // Across the bottom sphere below its seam (0.125), the top sphere above its (1.375), and
  // the arc between them: ρ = √(C² − (y − V)²) − H.
  struct Case {
    double y, rho;
  };
  const Case cases[] = {
      {-0.5, std::sqrt(0.75)},
      {1.45, std::sqrt(0.25 - 0.45 * 0.45)},
      {0.6, (double)(std::sqrt(ref.C * ref.C - (0.6L - ref.V) * (0.6L - ref.V)) - ref.H)},
      {1.2, (double)(std::sqrt(ref.C * ref.C - (1.2L - ref.V) * (1.2L - ref.V)) - ref.H)}};
  for (const Case& c : cases) {
    INFO("y " << c.y);
    const Ray across(Vec3(-4, c.y, 0), Vec3(1, 0, 0));
    REQUIRE(ovus.intersect(across, h));
    CHECK_THAT(h.t, WithinAbs(4 - c.rho, 2e-15));
    const SurfaceInfo si = ovus.surface(across, h);
    const LV n = ref.normal(c.y < ref.bottomSeam ? 0 : c.y > ref.topSeam ? 1 : 2, toL(si.p));
    CHECK(glm::dot(si.ng, Vec3(n.x, n.y, n.z)) > 1 - 1e-15);
    // From another side: the same distance (a solid of revolution).
    const Ray other(Vec3(0, c.y, 4), Vec3(0, 0, -3));
    REQUIRE(ovus.intersect(other, h));
    CHECK_THAT(h.t * 3, WithinAbs(4 - c.rho, 2e-15));
  }
}

TEST_CASE("ovus: first hits, crossings and normals against a long-double reference",
          "[primitives][ovus]") {
  for (const auto& r : kRadii) {
    const Ovus ovus(r[0], r[1]);
    const OvusReference ref(r[0], r[1]);
    Rng rng(uint64_t(1000 * r[0] + 100 * r[1]));
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
      const Ray ray = randomRayAt(rng, ovus.bounds(), 2.0);
      INFO("radii " << r[0] << " " << r[1] << " ray " << i);
      REQUIRE(intersectAgreesWithCrossings(ovus, ray) == "");
      LD tIn = 0, tOut = 0;
      int pIn = 0, pOut = 0;
      const bool refHit = ref.span(toL(ray.o), toL(ray.d), tIn, tOut, pIn, pOut);
      CrossingList cl;
      ovus.crossings(ray, cl);
      if (!refHit) {
        CHECK(cl.items.empty());
        continue;
      }
      ++hits;
      REQUIRE(cl.items.size() == 2);
      const double scale = glm::length(ray.d);
      CHECK_THAT(cl.items[0].hit.t * scale, WithinAbs((double)(tIn * scale), 1e-13));
      CHECK_THAT(cl.items[1].hit.t * scale, WithinAbs((double)(tOut * scale), 1e-13));
      for (int k = 0; k < 2; ++k) {
        const SurfaceInfo si = ovus.surface(ray, cl.items[k].hit);
        const LV n = ref.normal(k == 0 ? pIn : pOut, toL(si.p));
        CHECK(glm::dot(si.ng, Vec3(n.x, n.y, n.z)) > 1 - 1e-13);
        // The reprojected point lies on the reference's piece.
        CHECK(std::abs((double)ref.gauge(k == 0 ? pIn : pOut, toL(si.p))) < 1e-14);
      }
    }
    CHECK(hits > 100);
  }
}

TEST_CASE("ovus: inside is POV-Ray's test, and alternates as the crossings say",
          "[primitives][ovus]") {
  for (const auto& r : kRadii) {
    const Ovus ovus(r[0], r[1]);
    const OvusReference ref(r[0], r[1]);
    Rng rng(7);
    const AABB b = ovus.bounds();
    int in = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec3 p = randomInBox(rng, b.lo - Vec3(0.1), b.hi + Vec3(0.1));
      bool near = false;
      for (int k = 0; k < 3; ++k)
        near |= ref.active(k) && std::abs((double)ref.gauge(k, toL(p))) < 1e-9;
      if (near) continue;
      CHECK(ovus.inside(p) == ref.inside(toL(p)));
      in += ovus.inside(p);
    }
    CHECK(in > 200);
    for (int i = 0; i < 200; ++i) {
      const Ray ray = randomRayAt(rng, b, 2.0);
      CrossingList cl;
      ovus.crossings(ray, cl);
      REQUIRE(crossingsViolation(ovus, ray, cl) == "");
      if (cl.items.size() == 2 && cl.items[1].hit.t - cl.items[0].hit.t > 1e-6) {
        CHECK(ovus.inside(ray.at(0.5 * (cl.items[0].hit.t + cl.items[1].hit.t))));
        CHECK_FALSE(ovus.inside(ray.at(cl.items[0].hit.t - 1e-6)));
      }
    }
  }
}

TEST_CASE("ovus: the box holds the surface and touches it", "[primitives][ovus]") {
  for (const auto& r : kRadii) {
    const Ovus ovus(r[0], r[1]);
    const AABB b = ovus.bounds();
    CHECK(b.lo.y == -r[0]);
    CHECK(b.hi.y == r[0] + r[1]);
    // The widest point along x: a ray down at the box's side misses, one just inside hits
    // somewhere on its way (the widest circle is the box's).
    Rng rng(3);
    double widest = 0.0;
    for (int i = 0; i < 3000; ++i) {
      const Ray ray = randomRayAt(rng, b, 2.0);
      Hit h;
      if (!ovus.intersect(ray, h)) continue;
      const Vec3 p = ovus.surface(ray, h).p;
      CHECK(glm::all(glm::lessThanEqual(b.lo, p + Vec3(1e-12))));
      CHECK(glm::all(glm::lessThanEqual(p - Vec3(1e-12), b.hi)));
      widest = std::max(widest, std::hypot(p.x, p.z));
    }
    CHECK(widest > 0.97 * b.hi.x);
  }
}

TEST_CASE("ovus: a top radius of twice the bottom one or more is its top sphere",
          "[primitives][ovus]") {
  const Ovus ovus(0.5, 1.2);
  const Sphere sphere(Vec3(0, 0.5, 0), 1.2);
  Rng rng(11);
  for (int i = 0; i < 200; ++i) {
    const Ray ray = randomRayAt(rng, sphere.bounds(), 2.0);
    Hit a, b;
    REQUIRE(ovus.intersect(ray, a) == sphere.intersect(ray, b));
    if (a.found()) CHECK(a.t == b.t);
  }
  CHECK(ovus.bounds().lo.y == 0.5 - 1.2);
  // A bottom radius of 0: the top sphere about the origin.
  const Ovus ball(0.0, 1.0);
  Hit h;
  REQUIRE(ball.intersect(Ray(Vec3(0, 3, 0), Vec3(0, -1, 0)), h));
  CHECK(h.t == 2.0);
}

TEST_CASE("ovus: POV-Ray's (u, v), a sphere's about (0, top radius / 2, 0)", "[primitives][ovus]") {
  const Ovus ovus(1.0, 0.5);
  auto uvAlong = [&](const Ray& ray) {
    Hit h;
    REQUIRE(ovus.intersect(ray, h));
    const SurfaceInfo si = ovus.surface(ray, h);
    Vec2 uv;
    REQUIRE(ovus.povUV(si, h, uv));
    return uv;
  };
  // The top pole: straight above the centre, v = 1.
  Vec2 uv = uvAlong(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)));
  CHECK_THAT(uv.y, WithinAbs(1.0, 1e-15));
  // Level with the centre at +x: u = 0, v = 1/2; at Lucent's −z (POV-Ray's +z): u = 1/4.
  uv = uvAlong(Ray(Vec3(5, 0.25, 0), Vec3(-1, 0, 0)));
  CHECK_THAT(uv.x, WithinAbs(0.0, 1e-15));
  CHECK_THAT(uv.y, WithinAbs(0.5, 1e-15));
  uv = uvAlong(Ray(Vec3(0, 0.25, -5), Vec3(0, 0, 1)));
  CHECK_THAT(uv.x, WithinAbs(0.25, 1e-15));
  // Below the centre on the bottom sphere at y = −0.5: v = 1/2 + asin((y − c)/|p − c|)/π.
  const double x = std::sqrt(0.75), dy = -0.75;
  uv = uvAlong(Ray(Vec3(-5, -0.5, 0), Vec3(1, 0, 0)));
  CHECK_THAT(uv.x, WithinAbs(0.5, 1e-15));
  CHECK_THAT(uv.y, WithinAbs(0.5 + std::asin(dy / std::hypot(x, dy)) / kPi, 1e-14));
}

TEST_CASE("ovus: radii below 0, both 0 or not finite are refused", "[primitives][ovus]") {
  CHECK_THROWS(Ovus(-1.0, 0.5));
  CHECK_THROWS(Ovus(1.0, -0.5));
  CHECK_THROWS(Ovus(0.0, 0.0));
  CHECK_THROWS(Ovus(NAN, 0.5));
  CHECK_THROWS(Ovus(1.0, INFINITY));
  CHECK_NOTHROW(Ovus(1.0, 0.0));
  CHECK_NOTHROW(Ovus(0.0, 1.0));
}
