// crackle keeps the neighbours of the last cube it was asked about (render/patterns/
// crackle.cpp): a value must not depend on which cube was asked about before it.
#include "render/patterns/crackle.h"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace lucent;

TEST_CASE("crackle: a value does not depend on the points asked about before it",
          "[patterns][crackle]") {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 400; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    points.push_back(p);
    points.push_back(p + Vec3(1e-3, 0.0, 0.0));  // most often in the same cube
  }
  for (const bool solid : {false, true}) {
    CrackleParams params;
    params.solid = solid;
    std::vector<double> forward;
    for (const Vec3& p : points) forward.push_back(crackleValue(p, params, 2));
    // Backwards, and each point after a far one: every value again, to the bit.
    for (size_t i = points.size(); i-- > 0;) {
      INFO("point " << i << (solid ? " solid" : ""));
      CHECK(crackleValue(points[i], params, 2) == forward[i]);
      crackleValue(points[i] + Vec3(17.5, -9.25, 4.0), params, 2);
      CHECK(crackleValue(points[i], params, 2) == forward[i]);
    }
  }
}
