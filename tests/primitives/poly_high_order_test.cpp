// <poly> above order 4, up to POV-Ray's MAX_ORDER of 35: surfaces whose hits are known
// exactly. A product of k disjoint spheres is a poly of order 2k whose surface is theirs
// (P < 0 inside exactly one of them), so every hit is a sphere's quadratic root; the
// "superellipsoid" x^34 + y^34 + z^34 < 1 and z^35 + x² + y² < 1 have roots along the axes
// given by real powers.
#include "primitives/offset.h"
#include "primitives/poly.h"
#include "shape_checks.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>

using namespace lucent;

namespace {

using Terms = std::map<std::array<int, 3>, double>;

Terms multiply(const Terms& a, const Terms& b) {
  Terms r;
  for (const auto& [pa, ca] : a)
    for (const auto& [pb, cb] : b) r[{pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]}] += ca * cb;
  return r;
}

// (x − cx)² + (y − cy)² + (z − cz)² − r², expanded.
Terms sphere(const Vec3& c, double r) {
  return {{{2, 0, 0}, 1.0},
          {{0, 2, 0}, 1.0},
          {{0, 0, 2}, 1.0},
          {{1, 0, 0}, -2.0 * c.x},
          {{0, 1, 0}, -2.0 * c.y},
          {{0, 0, 1}, -2.0 * c.z},
          {{0, 0, 0}, glm::dot(c, c) - r * r}};
}

// The coefficients in POV-Ray's order for `order`: x's power descending, then y's, then z's.
std::vector<double> coefficients(const Terms& t, int order) {
  std::vector<double> c;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        const auto it = t.find({i, j, k});
        c.push_back(it == t.end() ? 0.0 : it->second);
      }
  return c;
}

// The first hit of a ray on a sphere, or -1.
double sphereHit(const Ray& ray, const Vec3& c, double r) {
  const Vec3 oc = ray.o - c;
  const double b = glm::dot(oc, ray.d), q = glm::dot(oc, oc) - r * r;
  const double disc = b * b - q;
  if (disc < 0.0) return -1.0;
  const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
  return t0 > 1e-9 ? t0 : t1 > 1e-9 ? t1 : -1.0;
}

struct Lcg {
  uint32_t seed;
  double operator()() {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0 * 2.0 - 1.0;
  }
};

}  // namespace

TEST_CASE("poly: products of spheres at orders 6 and 10 hit where the spheres are",
          "[primitives][poly]") {
  const std::vector<std::pair<Vec3, double>> balls = {{Vec3(-1.6, 0.0, 0.0), 0.7},
                                                      {Vec3(0.0, 0.3, 0.2), 0.6},
                                                      {Vec3(1.5, -0.2, 0.1), 0.75},
                                                      {Vec3(0.2, 1.6, -0.3), 0.5},
                                                      {Vec3(-0.3, -1.5, 0.4), 0.55}};
  for (int count : {3, 5}) {
    Terms p = {{{0, 0, 0}, 1.0}};
    for (int b = 0; b < count; ++b) p = multiply(p, sphere(balls[b].first, balls[b].second));
    const int order = 2 * count;
    const Poly poly(order, coefficients(p, order));
    Lcg next{static_cast<uint32_t>(17 + count)};
    int hits = 0;
    for (int n = 0; n < 3000; ++n) {
      const Vec3 o(6 * next(), 6 * next(), 6 * next());
      const Vec3 aim(2 * next(), 2 * next(), 0.5 * next());
      const Ray ray(o, glm::normalize(aim - o));
      double want = -1.0;
      int which = -1;
      for (int b = 0; b < count; ++b) {
        const double t = sphereHit(ray, balls[b].first, balls[b].second);
        if (t > 0.0 && (want < 0.0 || t < want)) want = t, which = b;
      }
      bool insideAny = false;
      for (int b = 0; b < count; ++b)
        insideAny |= glm::length(o - balls[b].first) < balls[b].second;
      CHECK(poly.inside(o) == insideAny);
      Hit h;
      const bool got = poly.intersect(ray, h);
      // A ray that grazes a sphere within rounding may go either way; none of these do.
      REQUIRE(got == (want > 0.0));
      if (!got) continue;
      ++hits;
      CHECK(h.t == Approx(want).epsilon(1e-10).margin(1e-10));
      // The normal is the gradient's direction: the sphere's radial one.
      const Vec3 p0 = ray.at(h.t);
      const Vec3 radial = glm::normalize(p0 - balls[which].first);
      const Vec3 normal = glm::normalize(poly.surface(ray, h).ng);
      CHECK(std::abs(std::abs(glm::dot(normal, radial)) - 1.0) < 1e-9);
    }
    CHECK(hits > 400);
  }
}

TEST_CASE("poly: order 34 and 35 surfaces hit at their exact roots", "[primitives][poly]") {
  // x^34 + y^34 + z^34 − 1: a rounded cube; along x at height y the hit is at
  // x = −(1 − y^34)^(1/34).
  const Poly cube(
      34, coefficients({{{34, 0, 0}, 1.0}, {{0, 34, 0}, 1.0}, {{0, 0, 34}, 1.0}, {{0, 0, 0}, -1.0}},
                       34));
  for (double y : {0.0, 0.5, 0.9, 0.98}) {
    const Ray ray(Vec3(-3.0, y, 0.0), Vec3(1, 0, 0));
    Hit h;
    REQUIRE(cube.intersect(ray, h));
    CHECK(h.t == Approx(3.0 - std::pow(1.0 - std::pow(y, 34.0), 1.0 / 34.0)).epsilon(1e-12));
    CrossingList list;
    cube.crossings(ray, list);
    REQUIRE(list.items.size() == 2);
    CHECK(list.items[1].hit.t == Approx(3.0 + std::pow(1.0 - std::pow(y, 34.0), 1.0 / 34.0)));
  }
  CHECK(cube.inside(Vec3(0.97, 0.97, 0.0)));  // 2·0.97^34 = 0.71
  CHECK(!cube.inside(Vec3(1.01, 0.0, 0.0)));
  // z^35 + x² + y² − 1, an odd order: along z at radius ρ the one crossing is at
  // z = (1 − ρ²)^(1/35), the solid below it.
  const Poly odd(
      35,
      coefficients({{{0, 0, 35}, 1.0}, {{2, 0, 0}, 1.0}, {{0, 2, 0}, 1.0}, {{0, 0, 0}, -1.0}}, 35));
  for (double rho : {0.0, 0.6, 0.95}) {
    const Ray down(Vec3(rho, 0.0, 4.0), Vec3(0, 0, -1));
    Hit h;
    REQUIRE(odd.intersect(down, h));
    CHECK(h.t == Approx(4.0 - std::pow(1.0 - rho * rho, 1.0 / 35.0)).epsilon(1e-12));
    CHECK(glm::normalize(odd.surface(down, h).ng).z > 0.0);  // out of the solid: up
    CHECK(odd.inside(Vec3(rho, 0.0, 0.5)));
  }
  // Beyond radius 1 the line stays outside down to z = −(ρ² − 1)^(1/35), then enters.
  const Ray down(Vec3(1.5, 0.0, 4.0), Vec3(0, 0, -1));
  Hit h;
  REQUIRE(odd.intersect(down, h));
  CHECK(h.t == Approx(4.0 + std::pow(1.25, 1.0 / 35.0)).epsilon(1e-12));
}

namespace {

// POV-Ray's Twin_Glob and Glob_5 (shapesq.inc) and the rounded cube of order 8.
std::vector<std::pair<std::string, Poly>> shapesAboveFour() {
  return {
      {"Twin_Glob",
       Poly(6, coefficients(
                   {{{6, 0, 0}, 4.0}, {{4, 0, 0}, -4.0}, {{0, 2, 0}, 1.0}, {{0, 0, 2}, 1.0}}, 6))},
      {"Glob_5",
       Poly(5, coefficients(
                   {{{5, 0, 0}, -0.5}, {{4, 0, 0}, -0.5}, {{0, 2, 0}, 1.0}, {{0, 0, 2}, 1.0}}, 5))},
      {"cube of order 8",
       Poly(8, coefficients(
                   {{{8, 0, 0}, 1.0}, {{0, 8, 0}, 1.0}, {{0, 0, 8}, 1.0}, {{0, 0, 0}, -1.0}}, 8))}};
}

}  // namespace

TEST_CASE("poly above order 4: the crossings contract, and rays leaving never re-hit",
          "[primitives][poly]") {
  // The checks every registered shape passes (contract_test, self_intersection_test), here
  // for orders 5, 6 and 8: random rays at the box [-1, 1]³, and from each hit a mirror ray,
  // a ray into the solid and one out of it, offset by the hit's error bound alone.
  test::Rng rng(4343);
  const AABB aim(Vec3(-1.0), Vec3(1.0));
  for (const auto& [name, poly] : shapesAboveFour()) {
    INFO(name);
    int hits = 0, secondaries = 0, rehits = 0, wrongStart = 0;
    std::string violation;
    for (int i = 0; i < 3000; ++i) {
      const Ray primary = test::randomRayAt(rng, aim);
      const std::string v = test::intersectAgreesWithCrossings(poly, primary);
      if (!v.empty() && violation.empty()) violation = v;
      Hit h;
      if (!poly.intersect(primary, h)) continue;
      const SurfaceInfo si = poly.surface(primary, h);
      const Vec3 d = glm::normalize(primary.d);
      if (std::abs(glm::dot(d, si.ng)) < 0.05) continue;
      ++hits;
      const Vec3 facing = glm::dot(d, si.ng) < 0.0 ? si.ng : -si.ng;
      for (const Vec3& w : {d - 2.0 * glm::dot(d, facing) * facing, d,
                            glm::normalize(si.ng + 0.7 * test::randomUnit(rng))}) {
        if (std::abs(glm::dot(w, si.ng)) < 0.05) continue;
        ++secondaries;
        const bool outward = glm::dot(w, si.ng) > 0.0;
        const Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w);
        Hit again;
        if (poly.intersect(ray, again) && again.t < 1e-6) ++rehits;
        CrossingList list;
        poly.crossings(ray, list);
        if (list.startsInside == outward) ++wrongStart;
      }
    }
    CHECK(violation.empty());
    CHECK(hits > 300);
    CHECK(secondaries > 2 * hits);
    CHECK(rehits == 0);
    CHECK(wrongStart == 0);
  }
}

TEST_CASE("poly: a line almost square to the top power keeps its roots near the origin",
          "[primitives][poly]") {
  // Twin_Glob met by a line whose x moves 0.012 per unit: the line polynomial's x⁶ term is
  // 1.3e-11, so the roots' Cauchy bound is 1.6e11 while the two crossings lie within half a
  // unit. The reference: bisection on P along the line in long double.
  const Poly poly(
      6,
      coefficients({{{6, 0, 0}, 4.0}, {{4, 0, 0}, -4.0}, {{0, 2, 0}, 1.0}, {{0, 0, 2}, 1.0}}, 6));
  const Vec3 o(-0.5076919, -0.3851853, -0.2175339);  // 0.001 inside the lower lobe
  const Vec3 d = glm::normalize(Vec3(0.0121044, 0.881708, -0.471639));
  auto P = [&](long double t) {
    const long double x = o.x + t * d.x, y = o.y + t * d.y, z = o.z + t * d.z;
    const long double x2 = x * x, x4 = x2 * x2;
    return 4 * x4 * x2 - 4 * x4 + y * y + z * z;
  };
  auto bisect = [&](long double a, long double b) {
    const bool aNeg = P(a) < 0;
    for (int i = 0; i < 200; ++i) {
      const long double m = 0.5L * (a + b);
      ((P(m) < 0) == aNeg ? a : b) = m;
    }
    return static_cast<double>(0.5L * (a + b));
  };
  REQUIRE(P(0) < 0);
  REQUIRE(P(1) > 0);
  const double exit = bisect(0, 1);
  CrossingList list;
  Ray ray(o, d);
  ray.tmin = -1.0;
  poly.crossings(ray, list);
  CHECK(!list.startsInside);
  REQUIRE(list.items.size() == 2);
  CHECK(list.items[0].entering);
  CHECK(list.items[0].hit.t == Approx(bisect(-1, 0)).epsilon(1e-12));
  CHECK(list.items[1].hit.t == Approx(exit).epsilon(1e-12));
  Hit h;
  REQUIRE(poly.intersect(Ray(o, d), h));
  CHECK(h.t == Approx(exit).epsilon(1e-12));
}
