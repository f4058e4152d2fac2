#include "primitives/polynomial.h"

#include <catch2/catch.hpp>

using namespace lucent;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
// Coefficients of Π (x − r_i) and the magnitudes behind them.
void fromRoots(const double* r, int n, double* c, double* cAbs) {
  for (int i = 0; i <= n; ++i) c[i] = cAbs[i] = 0.0;
  c[0] = cAbs[0] = 1.0;
  for (int k = 0; k < n; ++k) {
    for (int i = k + 1; i >= 1; --i) {
      c[i] = c[i - 1] - r[k] * c[i];
      cAbs[i] = cAbs[i - 1] + std::abs(r[k]) * cAbs[i];
    }
    c[0] = -r[k] * c[0];
    cAbs[0] = std::abs(r[k]) * cAbs[0];
  }
}
}  // namespace

TEST_CASE("polynomial: four simple roots of a quartic", "[numeric]") {
  const double roots[4] = {-1.5, 0.25, 1.0, 3.0};
  double c[5], cAbs[5];
  fromRoots(roots, 4, c, cAbs);
  // fromRoots builds the monic polynomial with c[n] = 1 at the top.
  CHECK(c[4] == 1.0);
  PolynomialRoot out[4];
  REQUIRE(polynomialRoots(c, cAbs, 4, -10.0, 10.0, out) == 4);
  for (int i = 0; i < 4; ++i) {
    CHECK_THAT(out[i].x, WithinAbs(roots[i], 1e-14));
    CHECK_FALSE(out[i].touching);
  }
  // Only the roots inside the interval.
  REQUIRE(polynomialRoots(c, cAbs, 4, 0.0, 2.0, out) == 2);
  CHECK_THAT(out[0].x, WithinAbs(0.25, 1e-15));
}

TEST_CASE("polynomial: a double root is found once, as touching", "[numeric]") {
  const double roots[4] = {-2.0, 0.5, 0.5, 2.0};
  double c[5], cAbs[5];
  fromRoots(roots, 4, c, cAbs);
  PolynomialRoot out[4];
  int n = polynomialRoots(c, cAbs, 4, -10.0, 10.0, out);
  REQUIRE(n == 3);
  CHECK_THAT(out[0].x, WithinAbs(-2.0, 1e-14));
  CHECK_THAT(out[1].x, WithinAbs(0.5, 1e-14));  // the critical point: accurate, not √ε
  CHECK(out[1].touching);
  CHECK_THAT(out[2].x, WithinAbs(2.0, 1e-14));
}

TEST_CASE("polynomial: no real roots, and lower degrees", "[numeric]") {
  const double c4[5] = {2.0, 0.0, -1.0, 0.0, 1.0};  // x⁴ − x² + 2 > 0
  const double a4[5] = {2.0, 0.0, 1.0, 0.0, 1.0};
  PolynomialRoot out[4];
  CHECK(polynomialRoots(c4, a4, 4, -10.0, 10.0, out) == 0);
  const double c2[3] = {-2.0, 0.0, 1.0};  // x² − 2
  const double a2[3] = {2.0, 0.0, 1.0};
  REQUIRE(polynomialRoots(c2, a2, 2, -10.0, 10.0, out) == 2);
  CHECK_THAT(out[1].x, WithinRel(std::sqrt(2.0), 1e-15));
  const double c3[4] = {-6.0, 11.0, -6.0, 1.0};  // (x−1)(x−2)(x−3)
  const double a3[4] = {6.0, 11.0, 6.0, 1.0};
  REQUIRE(polynomialRoots(c3, a3, 3, -10.0, 10.0, out) == 3);
  CHECK_THAT(out[2].x, WithinRel(3.0, 1e-15));
}

TEST_CASE("polynomial: degrees 5 and 6, simple, close and double roots", "[numeric]") {
  const double r6[6] = {-0.9, -0.1, 0.2, 0.21, 0.7, 1.3};
  double c[7], cAbs[7];
  fromRoots(r6, 6, c, cAbs);
  PolynomialRoot out[6];
  REQUIRE(polynomialRoots(c, cAbs, 6, -2.0, 2.0, out) == 6);
  for (int i = 0; i < 6; ++i) {
    CHECK_THAT(out[i].x, WithinAbs(r6[i], 1e-13));
    CHECK_FALSE(out[i].touching);
  }
  const double r5[5] = {-3.0, -1.0, 0.0625, 0.5, 4.0};
  fromRoots(r5, 5, c, cAbs);
  REQUIRE(polynomialRoots(c, cAbs, 5, -10.0, 10.0, out) == 5);
  for (int i = 0; i < 5; ++i) CHECK_THAT(out[i].x, WithinAbs(r5[i], 1e-13));
  // A double root among four simple ones (a ray tangent to a lathe's silhouette).
  const double d6[6] = {-1.0, 0.0, 0.375, 0.375, 0.75, 1.0};
  fromRoots(d6, 6, c, cAbs);
  REQUIRE(polynomialRoots(c, cAbs, 6, -2.0, 2.0, out) == 5);
  CHECK_THAT(out[2].x, WithinAbs(0.375, 1e-13));
  CHECK(out[2].touching);
  CHECK_THAT(out[4].x, WithinAbs(1.0, 1e-13));
  // x⁶ + 1 has no real root.
  const double none[7] = {1, 0, 0, 0, 0, 0, 1};
  CHECK(polynomialRoots(none, none, 6, -10.0, 10.0, out) == 0);
}
