#include "primitives/quadratic.h"

#include <catch2/catch.hpp>

#include <random>

using namespace lucent;
using Catch::Matchers::WithinRel;

TEST_CASE("quadratic: both roots keep full precision when they differ by 20 orders", "[numeric]") {
  // (t − 1e-10)(t − 1e10) = t² − (1e10 + 1e-10)·t + 1: h = −(1e10 + 1e-10)/2.
  double t0, t1;
  double a = 1.0, h = -0.5 * (1e10 + 1e-10), c = 1.0;
  REQUIRE(solveQuadratic(a, h, c, h * h - a * c, t0, t1));
  CHECK_THAT(t0, WithinRel(1e-10, 1e-15));
  CHECK_THAT(t1, WithinRel(1e10, 1e-15));
  // The textbook formula gets the small root wrong in most digits here.
  double textbook = (-h - std::sqrt(h * h - a * c)) / a;
  CHECK(std::abs(textbook - 1e-10) / 1e-10 > 1e-7);
}

TEST_CASE("quadratic: double roots, negative leading coefficient, no roots", "[numeric]") {
  double t0, t1;
  REQUIRE(solveQuadratic(1.0, -3.0, 9.0, 0.0, t0, t1));  // (t − 3)²
  CHECK(t0 == 3.0);
  CHECK(t1 == 3.0);
  REQUIRE(solveQuadratic(-1.0, 0.5, 2.0, 0.25 + 2.0, t0, t1));  // −t² + t + 2 = −(t − 2)(t + 1)
  CHECK(t0 == -1.0);
  CHECK(t1 == 2.0);
  CHECK_FALSE(solveQuadratic(1.0, 0.0, 1.0, -1.0, t0, t1));  // t² + 1
  CHECK_FALSE(solveQuadratic(0.0, 0.0, 1.0, 0.0, t0, t1));   // 1 = 0
  REQUIRE(solveQuadratic(0.0, 1.0, -4.0, 1.0, t0, t1));      // 2t − 4 = 0
  CHECK(t0 == 2.0);
  REQUIRE(solveQuadratic(1.0, 0.0, 0.0, 0.0, t0, t1));  // t² = 0
  CHECK(t0 == 0.0);
  CHECK(t1 == 0.0);
}

TEST_CASE("quadratic: the distance form against a long double reference", "[numeric]") {
  // |f + t·d|² = r² for a unit sphere seen from up to 1e6 away: both roots to a few ulps.
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    double far = std::pow(10.0, 6.0 * (0.5 + 0.5 * u(rng)));
    Vec3 f(far * u(rng), far * u(rng), far * u(rng));
    Vec3 target(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
    Vec3 d = target - f;
    double t0 = 0.0, t1 = 0.0;
    REQUIRE(solveDistanceQuadratic(f, d, 1.0, t0, t1));
    long double a = 0, h = 0, ff = 0;
    for (int k = 0; k < 3; ++k) {
      a += (long double)d[k] * d[k];
      h += (long double)f[k] * d[k];
      ff += (long double)f[k] * f[k];
    }
    long double c = ff - 1.0L;
    long double disc = h * h - a * c;
    long double q = -(h + (h < 0 ? -1 : 1) * std::sqrt(disc));
    long double r0 = q / a, r1 = c / q;
    if (r0 > r1) std::swap(r0, r1);
    worst = std::max({worst, double(std::abs((t0 - r0) / r0)), double(std::abs((t1 - r1) / r1))});
  }
  // h² − a·c itself cancels: the long double reference keeps 11 more bits, enough to show
  // that the distance form loses at most a few.
  CHECK(worst < 1e-12);
}
