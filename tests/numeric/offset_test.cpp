#include "primitives/offset.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace lucent;

TEST_CASE("offsetRayOrigin: moves past the error box on the side of w", "[numeric][offset]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    double scale = std::pow(10.0, 5.0 * u(rng));
    Vec3 p = scale * Vec3(u(rng), u(rng), u(rng));
    Vec3 err = gamma(7) * glm::abs(p) * (1.0 + u(rng));
    Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    Vec3 w = Vec3(u(rng), u(rng), u(rng));
    Vec3 po = offsetRayOrigin(p, err, n, w);
    double side = glm::dot(w, n) < 0.0 ? -1.0 : 1.0;
    // Every corner of the error box lies strictly behind the plane through po with normal n
    // (on the far side from w): no point p could really be is ahead of the new origin.
    // In long double, where po − p is exact, so the check itself does not round.
    long double moved = 0.0L, farthestCorner = 0.0L;
    for (int k = 0; k < 3; ++k) {
      moved += side * (long double)n[k] * ((long double)po[k] - (long double)p[k]);
      farthestCorner += std::abs((long double)n[k]) * err[k];
    }
    REQUIRE(moved > farthestCorner);
  }
}

TEST_CASE("offsetRayOrigin: an exact point still moves off its surface", "[numeric][offset]") {
  // A box face: pError is 0 along the normal; the origin must still leave the face plane.
  Vec3 po =
      offsetRayOrigin(Vec3(1, 0.5, 0.25), Vec3(0, 1e-16, 1e-16), Vec3(1, 0, 0), Vec3(1, 1, 0));
  CHECK(po.x > 1.0);
  CHECK(po.x == std::nextafter(1.0, 2.0));
  po = offsetRayOrigin(Vec3(1, 0.5, 0.25), Vec3(0.0), Vec3(1, 0, 0), Vec3(-1, 0, 0));
  CHECK(po.x == std::nextafter(1.0, 0.0));
  CHECK(po.y == 0.5);
}

TEST_CASE("nextUp and nextDown step like std::nextafter", "[numeric][offset]") {
  const double lim = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  std::vector<double> values = {0.0,
                                -0.0,
                                tiny,
                                -tiny,
                                1.0,
                                -1.0,
                                lim,
                                -lim,
                                1e-310,
                                -1e-310,
                                1e5,
                                -1e5,
                                0.1,
                                -0.3,
                                kInf,
                                -kInf,
                                std::numeric_limits<double>::min(),
                                -std::numeric_limits<double>::min()};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i) values.push_back(std::ldexp(u(rng), int(rng() % 2000) - 1000));
  for (double v : values) {
    INFO(v);
    const double up = std::nextafter(v, kInf), down = std::nextafter(v, -kInf);
    // Bit for bit (0 and −0 differ in bits but not in value: compare the sign too).
    CHECK(nextUp(v) == up);
    CHECK(std::signbit(nextUp(v)) == std::signbit(up));
    CHECK(nextDown(v) == down);
    CHECK(std::signbit(nextDown(v)) == std::signbit(down));
  }
  CHECK(std::isnan(nextUp(std::nan(""))));
  CHECK(std::isnan(nextDown(std::nan(""))));
}
