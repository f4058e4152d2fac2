// export-pov's slope: POV-Ray's slope block with the vector (or point_at), the slope range
// and the altitude with its range, as Lucent holds them (the exporter keeps coordinates).
#include "povray/pov_patterns.h"

#include <catch2/catch.hpp>

using namespace lucent;

TEST_CASE("export-pov writes slope as POV-Ray's slope block", "[povray][patterns]") {
  PatternSpec s;
  s.type = PatternType::slope;
  s.slope.direction = Vec3(0, -3, 0);
  s.slope.high = 0.5;
  CHECK(patternKeyword(s) == "slope { <0, -3, 0>, 0, 0.5 }");
  s.slope.altitude = Vec3(0, 1, 0);
  s.slope.altitudeLow = 0.005;
  s.slope.altitudeHigh = 0.4;
  CHECK(patternKeyword(s) == "slope { <0, -3, 0>, 0, 0.5 altitude <0, 1, 0>, 0.005, 0.4 }");
  SlopeParams at;
  at.pointAt = true;
  at.direction = Vec3(1, 2, 3);
  s.slope = at;
  CHECK(patternKeyword(s) == "slope { point_at <1, 2, 3>, 0, 0 }");
}
