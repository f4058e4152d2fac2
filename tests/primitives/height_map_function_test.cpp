// A height field's grid sampled from a function (primitives/height_map_function.h): POV-Ray's
// conversion of a value to a height, and its rows (the function's y against the field's z).
#include "primitives/height_map_function.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <utility>

using namespace lucent;

namespace {

class Field final : public ScalarField {
 public:
  explicit Field(double (*f)(const Vec3&)) : f_(f) {}
  double value(const Vec3& p) const override { return f_(p); }

 private:
  double (*f_)(const Vec3&);
};

}  // namespace

TEST_CASE("function height: POV-Ray's 16 bits, truncated and wrapped, values measured on it",
          "[primitives][height_field]") {
  // Each pair measured with POV-Ray 3.7.0.10: trace() down onto height_field { function
  // 4, 4 { v } }, the hit's height times 65536.
  const std::pair<double, int> measured[] = {
      {0.5, 32767},
      {0.25, 16383},
      {1.0, 65535},
      {0.999999, 65534},
      {1.2, 13106},
      {1.5, 32766},
      {2.0, 65534},
      {3.7, 45871},
      {-0.1, 58983},
      {-0.5, 32769},
      {-1.0, 1},
      {-1.5, 32770},
      {-0.001, 65471},
      {100.7 / 65535, 100},
      {100.3 / 65535, 100},
      // Where single and double precision part: POV-Ray's is single.
      {-0.97956816113450207, 1340},
      {-0.97068736186256765, 1922},
      {-0.95469592263303693, 2970}};
  for (const auto& [v, h] : measured) {
    INFO("v = " << v);
    CHECK(heightOfFunctionValue(v) == h);
  }
  CHECK(heightOfFunctionValue(0.0) == 0);
  CHECK(heightOfFunctionValue(std::numeric_limits<double>::quiet_NaN()) == 0);
  CHECK(heightOfFunctionValue(1e12) == 0);
}

TEST_CASE("function height: the grid's rows take the function's y from 1 down to 0",
          "[primitives][height_field]") {
  const Field f([](const Vec3& p) { return 0.1 * p.x + 0.8 * p.y + (p.z != 0.0 ? 5.0 : 0.0); });
  const auto m = sampleHeightMap(f, 4, 3);
  REQUIRE(m->width == 4);
  REQUIRE(m->depth == 3);
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 4; ++i) {
      const double x = i / 3.0, y = 1.0 - k / 2.0;
      CHECK(m->at(i, k) == heightOfFunctionValue(0.1 * x + 0.8 * y));
    }
  CHECK(m->at(0, 0) > m->at(0, 2));
  CHECK_THROWS(sampleHeightMap(f, 1, 3));
}
