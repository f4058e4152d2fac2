#include "shape_checks.h"

#include "primitives/triangle.h"
#include "primitives/watertight.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("triangle: distance, barycentrics and the counter-clockwise normal",
          "[primitives][triangle]") {
  Triangle tri(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 0));
  Ray ray(Vec3(1, 0.5, 3), Vec3(0, 0, -1.5));
  Hit h;
  REQUIRE(tri.intersect(ray, h));
  CHECK(h.t == 2.0);
  CHECK_THAT(h.b1, WithinAbs(0.25, 1e-15));  // weight of b: x/4
  CHECK_THAT(h.b2, WithinAbs(0.25, 1e-15));  // weight of c: y/2
  SurfaceInfo si = tri.surface(ray, h);
  CHECK(si.ng == Vec3(0, 0, 1));
  CHECK_FALSE(si.hasUV);
  CHECK_THAT(si.p.x, WithinAbs(1.0, 1e-15));
  CHECK_THAT(si.p.y, WithinAbs(0.5, 1e-15));
  CHECK(si.p.z == 0.0);
  // The back side is hit too (a surface has two sides).
  REQUIRE(tri.intersect(Ray(Vec3(1, 0.5, -3), Vec3(0, 0, 1)), h));
  CHECK(h.t == 3.0);
  CHECK_FALSE(tri.intersect(Ray(Vec3(3, 1.5, 3), Vec3(0, 0, -1)), h));  // beyond the hypotenuse
  CHECK_FALSE(tri.intersect(Ray(Vec3(1, 0.5, 3), Vec3(1, 0, 0)), h));   // parallel
}

TEST_CASE("triangle: vertex normals are interpolated and renormalised", "[primitives][triangle]") {
  std::array<Vec3, 3> n = {glm::normalize(Vec3(-1, 0, 1)), glm::normalize(Vec3(1, 0, 1)),
                           Vec3(0, 0, 1)};
  Triangle tri(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), n);
  Ray ray(Vec3(1, 0, 1), Vec3(0, 0, -1));   // midpoint of a–b: normal (0, 0, 1)
  Ray r2(Vec3(0.5, 0, 1), Vec3(0, 0, -1));  // a quarter along a–b
  Hit h;
  REQUIRE(tri.intersect(ray, h));
  SurfaceInfo si = tri.surface(ray, h);
  CHECK_THAT(si.ns.x, WithinAbs(0.0, 1e-15));
  CHECK_THAT(si.ns.z, WithinAbs(1.0, 1e-15));
  REQUIRE(tri.intersect(r2, h));
  si = tri.surface(r2, h);
  Vec3 expect = glm::normalize(0.75 * n[0] + 0.25 * n[1]);
  CHECK_THAT(si.ns.x, WithinAbs(expect.x, 1e-15));
  CHECK_THAT(si.ns.z, WithinAbs(expect.z, 1e-15));
  CHECK(si.ng == Vec3(0, 0, 1));
  // Normals given against the winding: the geometric normal turns to their side.
  std::array<Vec3, 3> down = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
  Triangle flipped(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), down);
  REQUIRE(flipped.intersect(ray, h));
  si = flipped.surface(ray, h);
  CHECK(si.ng == Vec3(0, 0, -1));
  CHECK(si.ns == Vec3(0, 0, -1));
}

TEST_CASE("triangle: degenerate triangles never hit and never give NaN", "[primitives][triangle]") {
  const Triangle degenerate[] = {
      Triangle(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)),              // collinear
      Triangle(Vec3(0.1, 0.2, 0.3), Vec3(0.1, 0.2, 0.3), Vec3(1, 0, 0)),  // two equal corners
      Triangle(Vec3(1.0), Vec3(1.0), Vec3(1.0)),                          // a point
      Triangle(Vec3(0, 0, 0), Vec3(1e-3, 1e-3, 0), Vec3(3e-3, 3e-3, 0)),  // collinear, scaled
  };
  Rng rng(8);
  for (const Triangle& tri : degenerate) {
    for (int i = 0; i < 2000; ++i) {
      Ray ray(randomInBox(rng, Vec3(-2.0), Vec3(2.0)), randomUnit(rng));
      if (i % 4 == 0) ray.d = Vec3(0, 0, 1);  // zero components
      Hit h;
      REQUIRE_FALSE(tri.intersect(ray, h));
      CrossingList cl;
      tri.crossings(ray, cl);
      REQUIRE(cl.items.empty());
    }
    // Straight through a point of the first triangle's segment, (1, 1, 1) at t = 0.5.
    Hit h;
    CHECK_FALSE(tri.intersect(Ray(Vec3(1.5, 0.5, 1), Vec3(-1, 1, 0)), h));
  }
}

TEST_CASE("triangle: rays with zero direction components", "[primitives][triangle]") {
  Triangle tri(Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(0, 1, 2));
  Hit h;
  REQUIRE(tri.intersect(Ray(Vec3(0, 0, 0), Vec3(0, 0, 1)), h));
  CHECK(h.t == 2.0);
  REQUIRE(tri.intersect(Ray(Vec3(0, 0, 5), Vec3(0, 0, -0.5)), h));
  CHECK(h.t == 6.0);
  // In the triangle's plane: parallel, no hit and no NaN.
  CHECK_FALSE(tri.intersect(Ray(Vec3(-5, 0, 2), Vec3(1, 0, 0)), h));
  // Along y only, through an oblique triangle.
  Triangle oblique(Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, 2, 1));
  REQUIRE(oblique.intersect(Ray(Vec3(0, -3, 0), Vec3(0, 1, 0)), h));
  CHECK_THAT(h.t, WithinRel(4.0, 1e-15));
}

namespace {

// A random point on the grid of multiples of 1/1024 in [-2, 2]³: sums, differences and
// small dyadic multiples of such points are exact in double, so a ray can be aimed
// exactly through a chosen point of an edge or at a vertex.
Vec3 gridPoint(Rng& rng) {
  std::uniform_int_distribution<int> k(-2048, 2048);
  return Vec3(k(rng), k(rng), k(rng)) / 1024.0;
}

}  // namespace

TEST_CASE("triangle: a ray exactly through a shared edge hits one or both, never neither",
          "[primitives][triangle]") {
  Rng rng(9);
  int rays = 0, both = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3 p = gridPoint(rng), q = gridPoint(rng), a = gridPoint(rng), b = gridPoint(rng);
    Triangle left(p, q, a), right(q, p, b);  // consistently wound across p–q
    // The point p + (k/8)·(q − p) is exact; so is the direction from a grid origin to it.
    double s = std::uniform_int_distribution<int>(1, 7)(rng) / 8.0;
    Vec3 onEdge = p + s * (q - p);
    Vec3 o = gridPoint(rng);
    Ray ray(o, onEdge - o);
    REQUIRE(ray.at(1.0) == onEdge);
    Vec3 n0 = glm::cross(q - p, a - p), n1 = glm::cross(p - q, b - q);
    Vec3 dn = glm::normalize(ray.d);
    if (glm::length(n0) < 1e-3 || glm::length(n1) < 1e-3 || glm::length(q - p) < 1e-3) continue;
    double f0 = glm::dot(dn, glm::normalize(n0)), f1 = glm::dot(dn, glm::normalize(n1));
    // Only where the ray sees both triangles from the same side do they cover both sides
    // of the edge as seen along the ray (otherwise the pair folds towards the viewer and a
    // ray may pass the edge outside both); grazing rays are left out.
    if (std::abs(f0) < 1e-3 || std::abs(f1) < 1e-3 || (f0 > 0) != (f1 > 0)) continue;
    ++rays;
    Hit h0, h1;
    bool x0 = left.intersect(ray, h0), x1 = right.intersect(ray, h1);
    INFO("ray " << i);
    REQUIRE((x0 || x1));
    if (x0 && x1) {
      ++both;
      // Both hits lie on the edge, each t a weighted mean of the same two corners.
      REQUIRE_THAT(h0.t, WithinRel(h1.t, 1e-14));
    }
    REQUIRE_THAT(x0 ? h0.t : h1.t, WithinRel(1.0, 1e-12));
  }
  CHECK(rays > 5000);
  CHECK(both < rays);  // most such rays are decided by the edge function's sign
}

TEST_CASE("triangle: a ray exactly through a vertex shared by a fan hits the fan",
          "[primitives][triangle]") {
  // Six triangles around a centre c, corners on the exact grid; rays from grid points
  // through c must hit at least one of them, all at t = 1.
  Rng rng(10);
  int rays = 0;
  for (int i = 0; i < 3000; ++i) {
    Vec3 c = gridPoint(rng);
    std::vector<Vec3> ring;
    for (int k = 0; k < 6; ++k) {
      double ang = k * kPi / 3.0;
      ring.push_back(c + Vec3(std::round(1024 * std::cos(ang)), std::round(1024 * std::sin(ang)),
                              (k % 2) * 100.0) /
                             1024.0);
    }
    Vec3 o = c + gridPoint(rng);
    if (o.z - c.z < 0.25) continue;  // from above, clear of the fan's slight folds
    ++rays;
    Ray ray(o, c - o);
    int hits = 0;
    for (int k = 0; k < 6; ++k) {
      Triangle tri(c, ring[k], ring[(k + 1) % 6]);
      Hit h;
      if (tri.intersect(ray, h)) {
        ++hits;
        REQUIRE_THAT(h.t, WithinRel(1.0, 1e-13));
      }
    }
    INFO("ray " << i);
    REQUIRE(hits >= 1);
  }
  CHECK(rays > 500);
}

TEST_CASE("watertight: the determinant's sign tells the side of the counter-clockwise normal",
          "[primitives][triangle][numeric]") {
  Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);  // normal +z
  TriangleIntersection ti;
  REQUIRE(intersectTriangle(ShearedRay(Ray(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1))), a, b, c, ti));
  CHECK(ti.facing == 1);  // against the normal: the front
  REQUIRE(intersectTriangle(ShearedRay(Ray(Vec3(0.2, 0.2, -1), Vec3(0, 0, 1))), a, b, c, ti));
  CHECK(ti.facing == -1);
  // Every dominant axis and sign of the direction.
  Rng rng(11);
  for (int i = 0; i < 5000; ++i) {
    Vec3 p0 = randomInBox(rng, Vec3(-1.0), Vec3(1.0)), p1 = randomInBox(rng, Vec3(-1.0), Vec3(1.0)),
         p2 = randomInBox(rng, Vec3(-1.0), Vec3(1.0));
    Vec3 target = 0.2 * p0 + 0.3 * p1 + 0.5 * p2;
    Vec3 o = target + 2.0 * randomUnit(rng);
    Vec3 n = glm::cross(p1 - p0, p2 - p0);
    if (std::abs(glm::dot(glm::normalize(target - o), glm::normalize(n))) < 1e-6) continue;
    REQUIRE(intersectTriangle(ShearedRay(Ray(o, target - o)), p0, p1, p2, ti));
    REQUIRE(ti.facing == (glm::dot(target - o, n) < 0.0 ? 1 : -1));
    REQUIRE_THAT(ti.t, WithinRel(1.0, 1e-9));
    REQUIRE_THAT(ti.b1, WithinAbs(0.3, 1e-9));
    REQUIRE_THAT(ti.b2, WithinAbs(0.5, 1e-9));
  }
}

TEST_CASE("watertight: passing tmin changes no answer of a caller that rejects t <= tmin",
          "[primitives][triangle][watertight]") {
  // Rays that start on (or within rounding of) the triangle they are tested against, as
  // shadow rays do, and rays from afar: with and without tmin, the hits beyond tmin agree.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  int onTriangle = 0, beyond = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng)), p2(u(rng), u(rng), u(rng));
    if (isDegenerateTriangle(p0, p1, p2)) continue;
    double b1 = w(rng), b2 = w(rng) * (1.0 - b1);
    const Vec3 onIt = p0 + b1 * (p1 - p0) + b2 * (p2 - p0);
    const bool fromAfar = i % 4 == 0;
    const Vec3 d(u(rng), u(rng), u(rng));
    const Ray ray(fromAfar ? onIt - 3.0 * d : onIt, d);
    const ShearedRay sr(ray);
    for (double tmin : {0.0, 1e-300, 1e-12, 1e-4, 1.0}) {
      TriangleIntersection a, b;
      const bool plain = intersectTriangle(sr, p0, p1, p2, a) && tmin < a.t;
      const bool given = intersectTriangle(sr, p0, p1, p2, b, tmin) && tmin < b.t;
      REQUIRE(plain == given);
      if (plain) REQUIRE(a.t == b.t);
      beyond += plain;
    }
    TriangleIntersection a;
    onTriangle += !fromAfar && intersectTriangle(sr, p0, p1, p2, a) && std::abs(a.t) < 1e-12;
  }
  CHECK(onTriangle > 1000);  // the case the shortcut is for does occur
  CHECK(beyond > 1000);
}
