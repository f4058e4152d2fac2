// POV-Ray 3.7's pavements against POV-Ray itself: tests/data/patterns/pavements.csv holds the
// colour of `pigment { pavement ... color_map { [0 rgb 0] [1 rgb 1] } }` for every arrangement
// of every number of sides and tiles (60 points each with the default corners, 3 points each
// of every exterior, interior and form), and two placed cases, from make_references.sh;
// Lucent's colour through the same map must be the same float.
#include "pattern_cases.h"
#include "reference_csv.h"

#include "render/patterns/color_map.h"
#include "render/patterns/pattern_value.h"
#include "render/patterns/pavement.h"
#include "scenegraph/pavement.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

PatternSpec pavement(int sides, int tiles, int number, int exterior = 0, int interior = 0,
                     int form = 0) {
  PatternSpec s = spec(PatternType::pavement);
  s.pavement = {sides, tiles, number, exterior, interior, form};
  return s;
}

std::map<std::string, PatternSpec> pavementCases() {
  std::map<std::string, PatternSpec> cases;
  for (int sides : {3, 4, 6})
    for (int tiles = 1; tiles <= 6; ++tiles)
      for (int n = 1; n <= pavementCount(sides, tiles); ++n) {
        const std::string base =
            "s" + std::to_string(sides) + "_t" + std::to_string(tiles) + "_p" + std::to_string(n);
        cases[base] = pavement(sides, tiles, n);
        for (int e = 0; e <= 2; ++e)
          for (int i = 0; i <= 2; ++i)
            for (int f = 0; f <= 3; ++f)
              cases[base + "_e" + std::to_string(e) + "_i" + std::to_string(i) + "_f" +
                    std::to_string(f)] = pavement(sides, tiles, n, e, i, f);
      }
  cases["pavement_placed"] = placed(
      pavement(4, 5, 8, 0, 2), then(then(inverseScale(Vec3(0.7)), inverseRotate(Vec3(10, 30, 0))),
                                    inverseTranslate(Vec3(0.3, 0, -1))));
  cases["pavement_waved"] =
      turbulent(waved(tuned(pavement(6, 4, 2, 0, 0, 2), 2, 0.1), WaveShape::sine), Vec3(0.3));
  return cases;
}

const ColorMap kGrey{{{0.0, Color(0, 0, 0)}, {1.0, Color(1, 1, 1)}}};

}  // namespace

TEST_CASE("POV-Ray's counts of pavement arrangements", "[pattern][pavement]") {
  const int counts[3][6] = {{1, 1, 1, 3, 4, 12}, {1, 1, 2, 5, 12, 35}, {1, 1, 3, 7, 22, 0}};
  const int sides[3] = {3, 4, 6};
  for (int k = 0; k < 3; ++k)
    for (int t = 1; t <= 6; ++t) {
      CHECK(pavementCount(sides[k], t) == counts[k][t - 1]);
      CHECK(pavementArrangements(sides[k], t) == counts[k][t - 1]);
    }
  CHECK(pavementCount(5, 1) == 0);
  CHECK(pavementCount(4, 7) == 0);
}

TEST_CASE("every pavement reference case has a Lucent spec", "[pattern][pavement]") {
  const auto cases = referenceCases("pavements.csv");
  const auto specs = pavementCases();
  for (const auto& [name, rows] : cases) {
    INFO(name);
    CHECK(specs.count(name) == 1);
    CHECK(rows.size() >= 3);
  }
  CHECK(cases.size() == specs.size());
}

TEST_CASE("every pavement gives POV-Ray's values (as its float grey) at every point",
          "[pattern][pavement]") {
  const auto cases = referenceCases("pavements.csv");
  int failed = 0;
  for (const auto& [name, s] : pavementCases()) {
    auto it = cases.find(name);
    REQUIRE(it != cases.end());
    for (const ReferenceRow& r : it->second) {
      const Vec3 p(fromGrid(r.values[0]), fromGrid(r.values[1]), fromGrid(r.values[2]));
      const double error = std::fabs(patternColor(s, kGrey, p).r - r.values[3]);
      if (error <= 1e-9) continue;
      if (++failed <= 20)
        FAIL_CHECK(name << " at " << p.x << " " << p.z << ": Lucent " << patternColor(s, kGrey, p).r
                        << ", POV-Ray " << r.values[3]);
    }
  }
  CHECK(failed == 0);
}
