#include "shape_checks.h"

#include "../numeric/accuracy_harness.h"
#include "primitives/sphere.h"
#include "primitives/superellipsoid.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using LD = long double;

namespace {

// The exponents the tests sweep: nearly a box to pinched stars, and mixed.
const std::pair<double, double> kExponents[] = {
    {1.0, 1.0}, {0.05, 0.05}, {0.1, 0.1}, {0.25, 0.6}, {0.5, 0.5},   {2.0, 2.0},
    {1.0, 2.0}, {3.0, 3.0},   {0.3, 4.0}, {4.0, 0.3},  {0.01, 0.01}, {10.0, 10.0}};

LD normL(LD a, LD b, LD p) {
  LD m = std::max(a, b), s = std::min(a, b);
  if (!(s > 0)) return m;
  return m * std::pow(1 + std::pow(s / m, p), 1 / p);
}

// The equation's value (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) − 1 in long double.
LD equationL(double e, double n, const Vec3& p) {
  LD S = std::pow(std::abs((LD)p.x), 2.0L / e) + std::pow(std::abs((LD)p.y), 2.0L / e);
  return std::pow(S, (LD)e / n) + std::pow(std::abs((LD)p.z), 2.0L / n) - 1;
}

// Where a line parallel to z at (x, y) meets the surface: z = ±(1 − R^q)^(1/q), R the
// inner norm, exact in long double; negative when it misses.
LD faceZ(double e, double n, double x, double y) {
  LD R = normL(std::abs((LD)x), std::abs((LD)y), 2.0L / e);
  if (R >= 1) return -1;
  LD q = 2.0L / n;
  return std::pow(1 - std::pow(R, q), 1 / q);
}

double angle(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

TEST_CASE("superellipsoid: e = n = 1 is the unit sphere", "[primitives][superellipsoid]") {
  Superellipsoid s(1.0, 1.0);
  Sphere ball(Vec3(0.0), 1.0);
  Rng rng(31);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray ray = randomRayAt(rng, AABB{Vec3(-1.2), Vec3(1.2)});
    CrossingList a, b;
    s.crossings(ray, a);
    ball.crossings(ray, b);
    REQUIRE(a.items.size() == b.items.size());
    for (size_t k = 0; k < a.items.size(); ++k) {
      CHECK_THAT(a.items[k].hit.t, WithinRel(b.items[k].hit.t, 1e-14));
      SurfaceInfo si = s.surface(ray, a.items[k].hit);
      CHECK(angle(si.ng, glm::normalize(ray.at(a.items[k].hit.t))) < 1e-13);
      ++hits;
    }
  }
  CHECK(hits > 1000);
}

TEST_CASE("superellipsoid: the axes and the diagonal meet it where the closed form says",
          "[primitives][superellipsoid]") {
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    // N(0, 0, z) = |z| whatever the exponents: every axis meets the surface at ±1.
    Hit h;
    REQUIRE(s.intersect(Ray(Vec3(0, 0, 5), Vec3(0, 0, -2)), h));
    CHECK(h.t == 2.0);
    CHECK(s.surface(Ray(Vec3(0, 0, 5), Vec3(0, 0, -2)), h).ng == Vec3(0, 0, 1));
    REQUIRE(s.intersect(Ray(Vec3(-3, 0, 0), Vec3(1, 0, 0)), h));
    CHECK(h.t == 2.0);
    CHECK(s.surface(Ray(Vec3(-3, 0, 0), Vec3(1, 0, 0)), h).ng == Vec3(-1, 0, 0));
    REQUIRE(s.intersect(Ray(Vec3(0, 4, 0), Vec3(0, -1, 0)), h));
    CHECK(h.t == 3.0);
    // The diagonal: N(s, s, s) = s·(2^(e/n) + 1)^(n/2).
    const LD star = std::pow(std::pow(2.0L, (LD)e / n) + 1, -(LD)n / 2);
    Ray diag(Vec3(2.0), Vec3(-1.0));
    REQUIRE(s.intersect(diag, h));
    CHECK_THAT(h.t, WithinRel(double(2 - star), 1e-14));
    // There the normal is the equation's gradient, by symmetry (g, g, h).
    const LD a = 2.0L / e, b = (LD)e / n, c = 2.0L / n;
    LD gxy = b * std::pow(2 * std::pow(star, a), b - 1) * a * std::pow(star, a - 1);
    LD gz = c * std::pow(star, c - 1);
    Vec3 expect = glm::normalize(Vec3(double(gxy), double(gxy), double(gz)));
    CHECK(angle(s.surface(diag, h).ng, expect) < 1e-13);
  }
}

TEST_CASE("superellipsoid: rays parallel to z meet the faces at the exact height",
          "[primitives][superellipsoid]") {
  // z = (1 − R^q)^(1/q): exact in long double. Near the box's edges at small exponents
  // the face is flat to within 1e-30 and still crossed where the formula says.
  Rng rng(32);
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
      double x = uniform(rng, -1.0, 1.0), y = uniform(rng, -1.0, 1.0);
      LD z = faceZ(e, n, x, y);
      Ray ray(Vec3(x, y, 3.0), Vec3(0, 0, -0.5));
      CrossingList cl;
      s.crossings(ray, cl);
      if (z < 1e-6) continue;  // outside the shadow, or a grazing root of no precision
      INFO("x = " << x << ", y = " << y);
      REQUIRE(cl.items.size() == 2);
      // Only where the ray is clear of grazing (the normal's z at least 0.1): a relative
      // change ε of the data moves a root by ε/cos.
      if (std::abs(s.surface(ray, cl.items[0].hit).ng.z) < 0.1) continue;
      CHECK_THAT(cl.items[0].hit.t, WithinRel(double((3 - z) * 2), 1e-14));
      CHECK_THAT(cl.items[1].hit.t, WithinRel(double((3 + z) * 2), 1e-14));
      ++checked;
    }
    CHECK(checked > (e >= 4 ? 0 : 50));  // e = 10: a thin star, seldom hit
  }
}

TEST_CASE("superellipsoid: random rays against the long-double reference",
          "[primitives][superellipsoid]") {
  Rng rng(33);
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    auto ref = accuracy::refSuperellipsoid(e, n);
    int compared = 0;
    for (int i = 0; i < 120; ++i) {
      Ray ray = randomRayAt(rng, AABB{Vec3(-1.1), Vec3(1.1)});
      ray.tmin = -kInf;
      std::vector<accuracy::LRoot> roots;
      ref->lineRoots(accuracy::LRay(ray), roots);
      // Only rays whose every root is clear of grazing (the count is well conditioned).
      bool clear = true;
      LD dl = std::sqrt(glm::dot(accuracy::toL(ray.d), accuracy::toL(ray.d)));
      for (auto& r : roots)
        if (!r.normalDefined || std::abs(glm::dot(r.n, accuracy::toL(ray.d))) / dl < 0.05)
          clear = false;
      if (!clear) continue;
      CrossingList cl;
      s.crossings(ray, cl);
      REQUIRE(cl.items.size() == roots.size());
      for (size_t k = 0; k < roots.size(); ++k) {
        CHECK(std::abs(cl.items[k].hit.t - (double)roots[k].t) <=
              1e-13 * std::abs((double)roots[k].t));
        Vec3 ng = s.surface(ray, cl.items[k].hit).ng;
        Vec3 rn((double)roots[k].n.x, (double)roots[k].n.y, (double)roots[k].n.z);
        CHECK(angle(ng, rn) < 1e-11);
        ++compared;
      }
    }
    CHECK(compared > (e >= 4 ? 0 : 40));
  }
}

TEST_CASE("superellipsoid: crossings alternate and agree with inside()",
          "[primitives][superellipsoid]") {
  Rng rng(34);
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    for (int i = 0; i < 500; ++i) {
      Ray ray = randomRayAt(rng, AABB{Vec3(-1.0), Vec3(1.0)}, uniform(rng, 0.2, 3.0));
      CrossingList cl;
      s.crossings(ray, cl);
      REQUIRE(crossingsViolation(s, ray, cl).empty());
      REQUIRE(intersectAgreesWithCrossings(s, ray).empty());
      CHECK(cl.startsInside == s.inside(ray.o));
      // Between consecutive crossings the inside test follows them.
      bool in = cl.startsInside;
      double last = ray.tmin;
      for (const Crossing& c : cl.items) {
        if (c.hit.t - last > 1e-9) CHECK(s.inside(ray.at(0.5 * (last + c.hit.t))) == in);
        in = c.entering;
        last = c.hit.t;
      }
    }
  }
}

TEST_CASE("superellipsoid: inside() against the equation", "[primitives][superellipsoid]") {
  Rng rng(35);
  for (auto [e, n] : kExponents) {
    Superellipsoid s(e, n);
    for (int i = 0; i < 2000; ++i) {
      Vec3 p = randomInBox(rng, Vec3(-1.05), Vec3(1.05));
      LD f = equationL(e, n, p);
      if (std::abs(f) < 1e-10) continue;
      REQUIRE(s.inside(p) == (f < 0));
    }
  }
}

TEST_CASE("superellipsoid: normals against the equation's gradient",
          "[primitives][superellipsoid]") {
  Rng rng(36);
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    const LD a = 2.0L / e, b = (LD)e / n, c = 2.0L / n;
    int checked = 0;
    for (int i = 0; i < 500; ++i) {
      Ray ray = randomRayAt(rng, AABB{Vec3(-1.0), Vec3(1.0)});
      Hit h;
      if (!s.intersect(ray, h)) continue;
      SurfaceInfo si = s.surface(ray, h);
      REQUIRE(std::abs(glm::length(si.ng) - 1.0) < 1e-15);
      Vec3 p = si.p;
      LD X = std::abs((LD)p.x), Y = std::abs((LD)p.y), Z = std::abs((LD)p.z);
      if (X == 0 || Y == 0 || Z == 0) continue;
      LD S = std::pow(X, a) + std::pow(Y, a);
      LD k = b * std::pow(S, b - 1) * a;
      LD g[3] = {std::copysign(k * std::pow(X, a - 1), (LD)p.x),
                 std::copysign(k * std::pow(Y, a - 1), (LD)p.y),
                 std::copysign(c * std::pow(Z, c - 1), (LD)p.z)};
      LD len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      Vec3 expect(double(g[0] / len), double(g[1] / len), double(g[2] / len));
      // Away from the creases of exponents above 2, where the gradient blows up.
      if (!std::isfinite((double)len)) continue;
      CHECK(angle(si.ng, expect) < 1e-11);
      CHECK(glm::dot(si.ng, ray.d) < 0.0);  // outward, met from outside
      ++checked;
    }
    CHECK(checked > (e >= 4 ? 0 : 50));
  }
}

TEST_CASE("superellipsoid: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][superellipsoid]") {
  Rng rng(37);
  for (auto [e, n] : kExponents) {
    INFO("e = " << e << ", n = " << n);
    Superellipsoid s(e, n);
    for (int i = 0; i < 300; ++i) {
      Ray ray = randomRayAt(rng, AABB{Vec3(-1.0), Vec3(1.0)});
      Hit h;
      if (!s.intersect(ray, h)) continue;
      SurfaceInfo si = s.surface(ray, h);
      // Just past the error box along the normal: outside, and a ray leaving outward
      // (within the tangent half-space) starts outside and first meets nothing nearer.
      Vec3 off = si.p + si.ng * (glm::dot(glm::abs(si.ng), si.pError) * 2.0);
      CHECK_FALSE(s.inside(off));
      Vec3 inward = si.p - si.ng * (glm::dot(glm::abs(si.ng), si.pError) * 2.0);
      CHECK(s.inside(inward));
    }
  }
}

TEST_CASE("superellipsoid: exponents outside [0.01, 10] are refused",
          "[primitives][superellipsoid]") {
  CHECK_THROWS_AS(Superellipsoid(0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(Superellipsoid(1.0, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(Superellipsoid(std::nan(""), 1.0), std::invalid_argument);
  CHECK_THROWS_AS(Superellipsoid(1.0, kInf), std::invalid_argument);
  CHECK_THROWS_AS(Superellipsoid(0.005, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(Superellipsoid(1.0, 10.5), std::invalid_argument);
  CHECK_NOTHROW(Superellipsoid(0.01, 10.0));
}
