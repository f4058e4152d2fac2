// POV-Ray's slope_map heights and its map search (render/patterns/normal_map.h), against an
// independent evaluation: the Hermite basis h00..h11 of the two entries around a value.
#include "render/patterns/normal_map.h"
#include "render/patterns/normal_perturbation.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;

namespace {

// The cubic Hermite spline through (0, h0) and (1, h1) with end slopes s0 and s1, written
// with the basis functions (not the powers gathered as POV-Ray writes it).
double hermite(double t, double h0, double s0, double h1, double s1) {
  const double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
  const double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
  return h00 * h0 + h10 * s0 + h01 * h1 + h11 * s1;
}

// slopemap.pov's "Now let's get fancy" map: a small triangle, a flat, a square pulse, a
// flat, a scallop and a flat again.
const std::vector<SlopeMapEntry> kFancy{
    {0.0, 0, 1}, {0.2, 1, 1}, {0.2, 1, -1}, {0.4, 0, -1}, {0.4, 0, 0}, {0.5, 0, 0},  {0.5, 1, 0},
    {0.6, 1, 0}, {0.6, 0, 0}, {0.7, 0, 0},  {0.7, 0, 3},  {0.8, 1, 0}, {0.9, 0, -3}, {0.9, 0, 0}};

// POV-Ray keeps a map's values in single precision.
double f(double v) { return static_cast<float>(v); }

}  // namespace

TEST_CASE("a slope map's height is the Hermite cubic of the entries around the value",
          "[pattern][slope-map]") {
  // Between 0.7 <0, 3> and 0.8 <1, 0>: a scallop rising steeply to a flat top.
  for (double v : {0.71, 0.73, 0.75, 0.78, 0.799}) {
    const double t = (v - f(0.7)) / (f(0.8) - f(0.7));
    INFO("value " << v);
    CHECK(slopeMapHeight(kFancy, v) == Approx(hermite(t, 0, 3, 1, 0)).epsilon(1e-14));
  }
  // Between 0.8 <1, 0> and 0.9 <0, -3>.
  for (double v : {0.81, 0.85, 0.89}) {
    const double t = (v - f(0.8)) / (f(0.9) - f(0.8));
    CHECK(slopeMapHeight(kFancy, v) == Approx(hermite(t, 1, 0, 0, -3)).epsilon(1e-14));
  }
  // The triangle's rising side, slopes 1 and 1: the straight line t (h = t exactly).
  CHECK(slopeMapHeight(kFancy, 0.1) == Approx(0.1 / f(0.2)).epsilon(1e-14));
  // The slopes are per unit of t, not of the value: 0.25 into a 0.5-wide interval with
  // slopes 1 and heights 0 and 1 is not 0.25 / 0.5 scaled by the width.
  const std::vector<SlopeMapEntry> wide{{0, 0, 0}, {0.5, 1, 0}};
  CHECK(slopeMapHeight(wide, 0.25) == Approx(hermite(0.5, 0, 0, 1, 0)).epsilon(1e-15));
  CHECK(slopeMapHeight(wide, 0.25) == Approx(0.5).epsilon(1e-15));
}

TEST_CASE("a slope map is constant beyond its ends and sharp where two entries share a value",
          "[pattern][slope-map]") {
  const std::vector<SlopeMapEntry> map{{0.2, 0.3, 1}, {0.6, 0.9, -2}};
  CHECK(slopeMapHeight(map, 0.0) == 0.3);
  CHECK(slopeMapHeight(map, 0.2) == 0.3);
  CHECK(slopeMapHeight(map, f(0.6)) == 0.9);
  // The double 0.6 lies just below the entry's single-precision value: still between the
  // entries, a hair short of the end (as in POV-Ray).
  CHECK(slopeMapHeight(map, 0.6) != 0.9);
  CHECK(slopeMapHeight(map, 0.6) == Approx(0.9).margin(1e-6));
  CHECK(slopeMapHeight(map, 1.0) == 0.9);
  CHECK(slopeMapHeight({{0.5, 0.25, 4}}, 0.1) == 0.25);  // one entry: its height everywhere
  // At 0.2 (two entries) the first of them alone: the top of the triangle, 1; just above
  // it, the falling side starting from 1.
  CHECK(slopeMapHeight(kFancy, f(0.2)) == 1.0);
  CHECK(slopeMapHeight(kFancy, 0.2001) == Approx(1.0).margin(1e-3));
  // At 0.5 the first entry with that value: height 0 (the flat), just above it 1.
  CHECK(slopeMapHeight(kFancy, f(0.5)) == 0.0);
  CHECK(slopeMapHeight(kFancy, 0.5001) == 1.0);
}

TEST_CASE("the map search takes the entries' values in single precision, as POV-Ray stores them",
          "[pattern][slope-map]") {
  const std::vector<SlopeMapEntry> map{{0.0, 0, 0}, {0.1, 1, 0}, {0.3, 0, 0}};
  // 0.1 in double lies below its float, so the double 0.1 is still between 0 and 0.1f.
  REQUIRE(0.1 < f(0.1));
  const MapSearch s = searchMap(map, 0.1);
  CHECK(s.prev == 0);
  CHECK(s.cur == 1);
  CHECK(s.t == Approx(0.1 / f(0.1)).epsilon(1e-15));
  const MapSearch at = searchMap(map, f(0.1));
  CHECK(at.prev == 1);
  CHECK(at.cur == 1);
  CHECK(searchMap(map, std::nan("")).cur == 0);  // no value: the first entry
}

TEST_CASE("a normal map blends its two entries' bent normals linearly before normalising",
          "[pattern][normal-map]") {
  NormalSpec bumps, granite;
  bumps.pattern.type = PatternType::bumps;
  bumps.depth = 0.7;
  granite.pattern.type = PatternType::granite;
  granite.depth = 0.4;
  NormalSpec map;
  map.pattern.type = PatternType::gradient;
  map.pattern.axis = Vec3(1, 0, 0);
  map.map = {{0.2, false, bumps}, {0.8, false, granite}};
  const Vec3 n = glm::normalize(Vec3(0.1, -0.3, -1.0));
  for (double x : {0.1, 0.35, 0.5, 0.77, 0.9}) {
    const Vec3 p(x, 0.4, 0.25);
    const double t = std::clamp((x - f(0.2)) / (f(0.8) - f(0.2)), 0.0, 1.0);
    const Vec3 expected =
        glm::normalize((1 - t) * perturbNormal(bumps, p, n) + t * perturbNormal(granite, p, n));
    const Vec3 got = perturbNormal(map, p, n);
    INFO("x " << x);
    CHECK(glm::length(got - expected) < 1e-14);
  }
  // A flat entry leaves the normal as it is.
  map.map[1].flat = true;
  const Vec3 got = perturbNormal(map, Vec3(0.95, 0.4, 0.25), n);
  CHECK(glm::length(got - n) < 1e-15);
}
