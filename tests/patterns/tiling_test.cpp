// POV-Ray 3.7's tilings against POV-Ray itself: tests/data/patterns/tilings.csv holds the
// colour of `pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } }` at 300 points of each
// of the 27 tilings (and at far, near, placed, waved and turbulent points), from
// make_references.sh; Lucent's colour through the same map must be the same float.
#include "pattern_cases.h"
#include "reference_csv.h"

#include "render/patterns/color_map.h"
#include "render/patterns/pattern_value.h"
#include "render/patterns/tiling.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

PatternSpec tiling(int n) {
  PatternSpec s = spec(PatternType::tiling);
  s.tiling = n;
  return s;
}

std::map<std::string, PatternSpec> tilingCases() {
  std::map<std::string, PatternSpec> cases;
  for (int n = 1; n <= kTilingCount; ++n) cases["tiling" + std::to_string(n)] = tiling(n);
  for (int n : {2, 13, 21, 25, 26, 27}) cases["tiling_far" + std::to_string(n)] = tiling(n);
  cases["tiling_near25"] = tiling(25);
  cases["tiling_near27"] = tiling(27);
  cases["tiling_placed"] =
      placed(tiling(9), then(then(inverseScale(Vec3(0.7)), inverseRotate(Vec3(10, 30, 0))),
                             inverseTranslate(Vec3(0.3, 0, -1))));
  cases["tiling_wave"] = waved(tuned(tiling(7), 2, 0.1), WaveShape::sine);
  cases["tiling_turbulence"] = turbulent(tiling(17), Vec3(0.3));
  cases["tiling_byte"] = tiling(2);  // POV-Ray's tiling 258.7: the number as a byte
  return cases;
}

const ColorMap kGrey{{{0.0, Color(0, 0, 0)}, {1.0, Color(1, 1, 1)}}};

}  // namespace

TEST_CASE("every tiling reference case has a Lucent spec", "[pattern][tiling]") {
  const auto cases = referenceCases("tilings.csv");
  const auto specs = tilingCases();
  for (const auto& [name, rows] : cases) {
    INFO(name);
    CHECK(specs.count(name) == 1);
    CHECK(rows.size() >= 100);
  }
  CHECK(cases.size() == specs.size());
}

TEST_CASE("the 27 tilings give POV-Ray's values (as its float grey) at every point",
          "[pattern][tiling]") {
  const auto cases = referenceCases("tilings.csv");
  for (const auto& [name, s] : tilingCases()) {
    auto it = cases.find(name);
    REQUIRE(it != cases.end());
    double worst = 0.0;
    Vec3 where(0.0);
    for (const ReferenceRow& r : it->second) {
      const Vec3 p(fromGrid(r.values[0]), fromGrid(r.values[1]), fromGrid(r.values[2]));
      const double error = std::fabs(patternColor(s, kGrey, p).r - r.values[3]);
      if (!(error <= worst)) {
        worst = error;
        where = p;
      }
    }
    INFO(name << ": worst error " << worst << " at " << where.x << " " << where.y << " "
              << where.z);
    CHECK(worst <= 1e-9);
  }
}
