// Colour maps, hexagon and brick against POV-Ray 3.7's pigments (function { pigment {...} },
// float colours; tests/data/patterns/colors.csv).
#include "color_cases.h"
#include "reference_csv.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("every colour reference case has a Lucent spec", "[pattern]") {
  const auto cases = referenceCases("colors.csv");
  const auto specs = colorCases();
  for (const auto& [name, rows] : cases) {
    INFO(name);
    CHECK(specs.count(name) == 1);
  }
  CHECK(cases.size() == specs.size());
}

TEST_CASE("colour maps, hexagon and brick give POV-Ray's float colours to 1e-9", "[pattern]") {
  const auto cases = referenceCases("colors.csv");
  for (const auto& [name, colorAt] : colorCases()) {
    auto it = cases.find(name);
    REQUIRE(it != cases.end());
    double worst = 0.0;
    Vec3 where(0.0);
    for (const ReferenceRow& r : it->second) {
      const Vec3 p(fromGrid(r.values[0]), fromGrid(r.values[1]), fromGrid(r.values[2]));
      const Color c = colorAt(p);
      for (int i = 0; i < 3; ++i) {
        const double error = std::fabs(c[i] - r.values[3 + i]);
        if (!(error <= worst)) {
          worst = error;
          where = p;
        }
      }
    }
    INFO(name << ": worst error " << worst << " at " << where.x << " " << where.y << " "
              << where.z);
    CHECK(worst <= 1e-9);
  }
}

TEST_CASE("a colour map is constant beyond its ends and steps where two entries meet",
          "[pattern]") {
  const ColorMap map{{{0.25, Color(1, 0, 0)},
                      {0.5, Color(0, 1, 0)},
                      {0.5, Color(0, 0, 1)},
                      {0.75, Color(1, 1, 1)}}};
  CHECK(lookupColorMap(map, -3.0) == Color(1, 0, 0));
  CHECK(lookupColorMap(map, 0.25) == Color(1, 0, 0));
  CHECK(lookupColorMap(map, 0.5) == Color(0, 1, 0));  // POV-Ray: the first of the two
  const Color above = lookupColorMap(map, std::nextafter(0.5, 1.0));
  CHECK(above.r < 1e-6f);
  CHECK(above.g < 1e-6f);
  CHECK(above.b == 1.0f);
  CHECK(lookupColorMap(map, 0.75) == Color(1, 1, 1));
  CHECK(lookupColorMap(map, 9.0) == Color(1, 1, 1));
  const Color mid = lookupColorMap(map, 0.375);
  CHECK(mid.r == 0.5f);
  CHECK(mid.g == 0.5f);
  CHECK(mid.b == 0.0f);
}

TEST_CASE("without a colour map the colour is the grey level, clamped", "[pattern]") {
  const ColorMap none;
  CHECK(lookupColorMap(none, 0.25) == Color(0.25f));
  CHECK(lookupColorMap(none, -1.0) == Color(0.0f));
  CHECK(lookupColorMap(none, 1.00001) == Color(1.0f));
}

TEST_CASE("hexagon and brick stay defined at huge and non-finite coordinates", "[pattern]") {
  const double far[] = {1e12, -3e15, 1e300, INFINITY, -INFINITY, NAN};
  const BrickSpec b;
  for (double c : far) {
    const int h = hexagonIndex(Vec3(c, 0, -c));
    CHECK((h >= 0 && h <= 2));
    const int k = brickIndex(b, Vec3(c, c, c));
    CHECK((k == 0 || k == 1));
  }
}
