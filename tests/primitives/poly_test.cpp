// <poly>: POV-Ray's coefficient order term by term, order 2 against the quadric, a torus
// written as a quartic against the torus, a cubic whose leading term vanishes along some
// directions, tangent rays, crossings against inside(), and a ray from far away.
#include "primitives/poly.h"
#include "primitives/quadric.h"
#include "primitives/torus.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>

using namespace lucent;

namespace {

// POV-Ray's documented quartic, a00 to a34 (source/core/shape/polynomial.cpp's comment):
// the powers of x, y and z of each coefficient in turn.
const std::array<std::array<int, 3>, 35> kPovQuarticTerms = {
    {{4, 0, 0}, {3, 1, 0}, {3, 0, 1}, {3, 0, 0}, {2, 2, 0}, {2, 1, 1}, {2, 1, 0},
     {2, 0, 2}, {2, 0, 1}, {2, 0, 0}, {1, 3, 0}, {1, 2, 1}, {1, 2, 0}, {1, 1, 2},
     {1, 1, 1}, {1, 1, 0}, {1, 0, 3}, {1, 0, 2}, {1, 0, 1}, {1, 0, 0}, {0, 4, 0},
     {0, 3, 1}, {0, 3, 0}, {0, 2, 2}, {0, 2, 1}, {0, 2, 0}, {0, 1, 3}, {0, 1, 2},
     {0, 1, 1}, {0, 1, 0}, {0, 0, 4}, {0, 0, 3}, {0, 0, 2}, {0, 0, 1}, {0, 0, 0}}};

std::vector<double> quartic(const std::map<std::array<int, 3>, double>& terms) {
  std::vector<double> c;
  for (const auto& powers : kPovQuarticTerms) {
    auto it = terms.find(powers);
    c.push_back(it == terms.end() ? 0.0 : it->second);
  }
  return c;
}

// (x² + y² + z² + R² − r²)² − 4R²(x² + z²): the torus about the y axis.
std::vector<double> torusQuartic(double R, double r) {
  const double a = R * R - r * r;
  return quartic({{{4, 0, 0}, 1},
                  {{0, 4, 0}, 1},
                  {{0, 0, 4}, 1},
                  {{2, 2, 0}, 2},
                  {{2, 0, 2}, 2},
                  {{0, 2, 2}, 2},
                  {{2, 0, 0}, 2 * a - 4 * R * R},
                  {{0, 2, 0}, 2 * a},
                  {{0, 0, 2}, 2 * a - 4 * R * R},
                  {{0, 0, 0}, a * a}});
}

struct Lcg {
  uint32_t seed;
  double operator()() {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0 * 2.0 - 1.0;
  }
};

}  // namespace

TEST_CASE("poly: the coefficients are read in POV-Ray's order", "[primitives][poly]") {
  const Vec3 p(1.5, -2.0, 3.0);
  for (size_t m = 0; m + 1 < kPovQuarticTerms.size(); ++m) {
    std::vector<double> c(35, 0.0);
    c[m] = 1.0;
    const Poly poly(4, c);
    const auto& e = kPovQuarticTerms[m];
    CHECK(poly.value(p) == Approx(std::pow(p.x, e[0]) * std::pow(p.y, e[1]) * std::pow(p.z, e[2])));
  }
  // Order 3's twenty: x³, x²y, x²z, x², xy², xyz, xy, xz², xz, x, y³, y²z, y², yz², yz, y, z³, z²,
  // z, 1.
  const std::array<std::array<int, 3>, 20> cubic = {
      {{3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 0, 0}, {1, 2, 0}, {1, 1, 1}, {1, 1, 0},
       {1, 0, 2}, {1, 0, 1}, {1, 0, 0}, {0, 3, 0}, {0, 2, 1}, {0, 2, 0}, {0, 1, 2},
       {0, 1, 1}, {0, 1, 0}, {0, 0, 3}, {0, 0, 2}, {0, 0, 1}, {0, 0, 0}}};
  for (size_t m = 0; m + 1 < cubic.size(); ++m) {
    std::vector<double> c(20, 0.0);
    c[m] = 2.0;
    c[19] = -1.0;
    const Poly poly(3, c);
    const auto& e = cubic[m];
    CHECK(poly.value(p) ==
          Approx(2.0 * std::pow(p.x, e[0]) * std::pow(p.y, e[1]) * std::pow(p.z, e[2]) - 1.0));
  }
}

TEST_CASE("poly: order 2 is the quadric with the same coefficients, hit for hit",
          "[primitives][poly]") {
  // A hyperboloid of one sheet with mixed and linear terms: x², xy, xz, x, y², yz, y, z², z, 1.
  const std::vector<double> c = {1.0, 0.4, 0.0, -0.3, -0.5, 0.2, 0.1, 1.5, 0.0, -0.6};
  const Poly poly(2, c);
  const Quadric quadric(
      {Vec3(c[0], c[4], c[7]), Vec3(c[1], c[2], c[5]), Vec3(c[3], c[6], c[8]), c[9]});
  Lcg next{11};
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 o(5 * next(), 5 * next(), 5 * next());
    const Ray ray(o, glm::normalize(Vec3(next(), next(), next()) - o));
    Hit hp, hq;
    const bool a = poly.intersect(ray, hp), b = quadric.intersect(ray, hq);
    REQUIRE(a == b);
    CHECK(poly.inside(o) == quadric.inside(o));
    if (!a) continue;
    ++hits;
    CHECK(hp.t == Approx(hq.t).epsilon(1e-12).margin(1e-12));
    CHECK(glm::length(poly.surface(ray, hp).ng - quadric.surface(ray, hq).ng) < 1e-9);
  }
  CHECK(hits > 1000);
  // An ellipsoid of order 2 has the quadric's exact box; a cubic none.
  const Poly ellipsoid(2, {0.25, 0, 0, 0, 1, 0, 0, 1, 0, -1});
  CHECK(ellipsoid.bounds().lo.x == Approx(-2.0).margin(1e-8));
  CHECK(ellipsoid.bounds().hi.z == Approx(1.0).margin(1e-8));
  std::vector<double> cubic(20, 0.0);
  cubic[0] = 1.0;
  CHECK(std::isinf(Poly(3, cubic).bounds().hi.x));
}

TEST_CASE("poly: a torus written as a quartic is the torus", "[primitives][poly]") {
  const Poly poly(4, torusQuartic(1.0, 0.3));
  const Torus torus(1.0, 0.3);
  Lcg next{5};
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 o(3 * next(), 3 * next(), 3 * next());
    const Ray ray(o, glm::normalize(Vec3(1.3 * next(), 0.4 * next(), 1.3 * next()) - o));
    Hit hp, ht;
    const bool a = poly.intersect(ray, hp), b = torus.intersect(ray, ht);
    // Rays that only graze the tube may be decided either way within rounding.
    if (a != b) {
      Hit h = a ? hp : ht;
      const Vec3 q = ray.at(h.t);
      const double dTube = std::abs(std::hypot(std::hypot(q.x, q.z) - 1.0, q.y) - 0.3);
      CHECK(dTube < 1e-7);
      continue;
    }
    CHECK(poly.inside(o) == torus.inside(o));
    if (!a) continue;
    ++hits;
    CHECK(hp.t == Approx(ht.t).epsilon(1e-10).margin(1e-10));
    CHECK(glm::length(poly.surface(ray, hp).ng - torus.surface(ray, ht).ng) < 1e-8);
  }
  CHECK(hits > 800);
}

TEST_CASE("poly: crossings alternate and agree with inside()", "[primitives][poly]") {
  // The tangle cube: x⁴ − 5x² + y⁴ − 5y² + z⁴ − 5z² + 11.8, up to eight crossings per line.
  const Poly poly(4, quartic({{{4, 0, 0}, 1},
                              {{2, 0, 0}, -5},
                              {{0, 4, 0}, 1},
                              {{0, 2, 0}, -5},
                              {{0, 0, 4}, 1},
                              {{0, 0, 2}, -5},
                              {{0, 0, 0}, 11.8}}));
  Lcg next{3};
  int many = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o(4 * next(), 4 * next(), 4 * next());
    Ray ray(o, glm::normalize(Vec3(2 * next(), 2 * next(), 2 * next()) - o));
    ray.tmin = 0.0;
    ray.tmax = 20.0;
    CrossingList list;
    poly.crossings(ray, list);
    CHECK(list.startsInside == poly.inside(o));
    bool inside = list.startsInside;
    double last = -1.0;
    for (const Crossing& c : list.items) {
      CHECK(c.hit.t >= last);
      CHECK(c.entering != inside);
      inside = c.entering;
      last = c.hit.t;
      CHECK(std::abs(poly.value(ray.at(c.hit.t))) < 1e-9);
    }
    if (list.items.size() >= 4) ++many;
    // Between crossings the state is what inside() says.
    for (size_t k = 0; k + 1 < list.items.size(); ++k) {
      const double mid = 0.5 * (list.items[k].hit.t + list.items[k + 1].hit.t);
      if (list.items[k + 1].hit.t - list.items[k].hit.t > 1e-6)
        CHECK(poly.inside(ray.at(mid)) == list.items[k].entering);
    }
  }
  CHECK(many > 100);
}

TEST_CASE("poly: a cubic whose leading term vanishes along the ray", "[primitives][poly]") {
  // y − x³ + 3xz² (the monkey saddle y = x³ − 3xz²): along y it is linear, along z at x = 0
  // constant, along x a true cubic.
  std::vector<double> c(20, 0.0);
  c[0] = -1.0;  // x³
  c[7] = 3.0;   // xz²
  c[15] = 1.0;  // y
  const Poly poly(3, c);
  Hit h;
  CHECK(poly.intersect(Ray(Vec3(0.3, -5.0, 0.0), Vec3(0, 1, 0)), h));
  CHECK(h.t == Approx(5.0 + 0.027).epsilon(1e-14));
  CHECK(!poly.intersect(Ray(Vec3(0.0, 0.5, -5.0), Vec3(0, 0, 1)), h));
  CHECK(poly.intersect(Ray(Vec3(-5.0, 0.5, 0.0), Vec3(1, 0, 0)), h));
  CHECK(h.t == Approx(5.0 + std::cbrt(0.5)).epsilon(1e-14));
  CrossingList list;
  Ray along(Vec3(0.0, 0.5, -5.0), Vec3(0, 0, 1));
  poly.crossings(along, list);
  CHECK(list.items.empty());
  CHECK(!list.startsInside);  // P = 0.5 > 0 all along
}

TEST_CASE("poly: a tangent ray touches without crossing", "[primitives][poly]") {
  // The quartic cylinder x⁴ + z⁴ < 1: the line x = 1 along y touches it everywhere; the line
  // z = 1 along x touches it at x = 0 only (x⁴ = 0 there: a quadruple root).
  const Poly poly(4, quartic({{{4, 0, 0}, 1}, {{0, 0, 4}, 1}, {{0, 0, 0}, -1}}));
  Hit h;
  CHECK(!poly.intersect(Ray(Vec3(-3.0, 0.2, 1.0), Vec3(1, 0, 0)), h));
  CHECK(poly.intersect(Ray(Vec3(-3.0, 0.2, 0.999), Vec3(1, 0, 0)), h));
  const double x = std::pow(1.0 - std::pow(0.999, 4.0), 0.25);
  CHECK(h.t == Approx(3.0 - x).epsilon(1e-9));
}

TEST_CASE("poly: a ray from far away keeps its accuracy", "[primitives][poly]") {
  const Poly poly(4, torusQuartic(1.0, 0.25));
  const Vec3 target(1.0, 0.0, 0.0);  // the tube's centre on +x: the hit is at x = 1.25
  for (double far : {1e3, 1e5, 1e7}) {
    const Ray ray(Vec3(far, 0.0, 0.0), Vec3(-1, 0, 0));
    Hit h;
    REQUIRE(poly.intersect(ray, h));
    CHECK(std::abs(ray.at(h.t).x - 1.25) < 1e-12 * far);
    (void)target;
  }
}

TEST_CASE("poly: bad orders and coefficient lists are refused", "[primitives][poly]") {
  CHECK_THROWS_AS(Poly(36, std::vector<double>(8436, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(Poly(5, std::vector<double>(35, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(Poly(1, std::vector<double>(4, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(Poly(3, std::vector<double>(19, 1.0)), std::invalid_argument);
  std::vector<double> c(20, 0.0);
  c[19] = 1.0;
  CHECK_THROWS_AS(Poly(3, c), std::invalid_argument);  // only a constant
  c[0] = std::nan("");
  CHECK_THROWS_AS(Poly(3, c), std::invalid_argument);
}
