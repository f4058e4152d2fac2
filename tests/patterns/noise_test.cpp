// Lucent's noise against POV-Ray 3.7's own (f_noise_generator; tests/data/patterns).
#include "reference_csv.h"

#include "primitives/noise.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("noise of all three generators equals POV-Ray's to 1e-15", "[pattern]") {
  const auto rows = readReference("noise.csv", false);
  REQUIRE(rows.size() == 400);
  double worst[3] = {0, 0, 0};
  for (const ReferenceRow& r : rows) {
    const Vec3 p(fromGrid(r.values[0]), fromGrid(r.values[1]), fromGrid(r.values[2]));
    for (int g = 1; g <= 3; ++g) {
      const double error = std::fabs(noise(p, g) - r.values[2 + g]);
      worst[g - 1] = std::max(worst[g - 1], error);
      INFO("generator " << g << " at " << p.x << " " << p.y << " " << p.z);
      REQUIRE(error <= 1e-15);
    }
  }
  INFO("worst errors " << worst[0] << " " << worst[1] << " " << worst[2]);
  CHECK(worst[0] <= 1e-15);
}

TEST_CASE("noise stays in [0, 1] and is defined at huge and non-finite coordinates", "[pattern]") {
  const double far[] = {1e12, -3e15, 1e300, INFINITY, -INFINITY, NAN};
  for (double c : far)
    for (int g = 1; g <= 3; ++g) {
      const double v = noise(Vec3(c, 0.5, -c), g);
      CHECK(v >= 0.0);
      CHECK(v <= 1.0);
      const Vec3 d = dnoise(Vec3(0.25, c, 1.5));
      CHECK(std::isfinite(d.x + d.y + d.z));
    }
}

TEST_CASE("dnoise is smooth: its components change little over a small step", "[pattern]") {
  for (int i = 0; i < 100; ++i) {
    const Vec3 p(0.37 * i - 11.0, 0.21 * i, -0.13 * i + 2.0);
    const Vec3 a = dnoise(p), b = dnoise(p + Vec3(1e-6, -1e-6, 1e-6));
    CHECK(std::fabs(a.x - b.x) < 1e-4);
    CHECK(std::fabs(a.y - b.y) < 1e-4);
    CHECK(std::fabs(a.z - b.z) < 1e-4);
  }
}
