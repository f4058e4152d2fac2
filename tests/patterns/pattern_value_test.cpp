// Lucent's pattern values against POV-Ray 3.7's (function { pattern { ... } }, the pattern
// with its transform, turbulence, frequency, phase and wave; tests/data/patterns).
#include "pattern_cases.h"
#include "reference_csv.h"

#include "render/patterns/normal_perturbation.h"
#include "render/patterns/pattern_value.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

double worstError(const PatternSpec& spec, const std::vector<ReferenceRow>& rows, Vec3* where) {
  double worst = 0.0;
  for (const ReferenceRow& r : rows) {
    const Vec3 p(fromGrid(r.values[0]), fromGrid(r.values[1]), fromGrid(r.values[2]));
    const double error = std::fabs(patternValue(spec, p) - r.values[3]);
    if (!(error <= worst)) {
      worst = error;
      *where = p;
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("every reference case has a Lucent spec and every spec a reference", "[pattern]") {
  const auto cases = referenceCases("patterns.csv");
  const auto specs = patternCases();
  for (const auto& [name, rows] : cases) {
    INFO(name);
    CHECK(specs.count(name) == 1);
    CHECK(rows.size() == 100);
  }
  CHECK(cases.size() == specs.size());
}

TEST_CASE("the types, turbulence, frequency, phase and waves equal POV-Ray's to 1e-13",
          "[pattern]") {
  const auto cases = referenceCases("patterns.csv");
  for (const auto& [name, s] : patternCases()) {
    auto it = cases.find(name);
    REQUIRE(it != cases.end());
    Vec3 where(0.0);
    const double worst = worstError(s, it->second, &where);
    INFO(name << ": worst error " << worst << " at " << where.x << " " << where.y << " "
              << where.z);
    CHECK(worst <= 1e-13);
  }
}

TEST_CASE("pattern values stay within POV-Ray's range [0, 1.00001]", "[pattern]") {
  for (const auto& [name, s] : patternCases())
    for (int i = 0; i < 200; ++i) {
      const Vec3 p(0.731 * i - 70.0, 0.377 * i - 30.0, -0.519 * i + 50.0);
      const double v = patternValue(s, p);
      INFO(name << " at " << p.x << " " << p.y << " " << p.z);
      CHECK(v >= 0.0);
      CHECK(v <= 1.00001);
    }
}

TEST_CASE("pattern values and normals are defined at huge and non-finite points", "[pattern]") {
  const double far[] = {3e9, -1e15, 1e300, -1e300, INFINITY, NAN};
  for (int t = 0; t < kPatternTypeCount; ++t) {
    PatternSpec s;
    s.type = static_cast<PatternType>(t);
    s.placement.turbulence = Vec3(0.4);
    NormalSpec n;
    n.pattern = s;
    for (double a : far) {
      const Vec3 p(a, 0.5, -a);
      INFO("type " << t << " at " << a);
      const double v = patternValue(s, p);
      CHECK(v >= 0.0);
      CHECK(v <= 1.00001);
      CHECK(isFinite(perturbNormal(n, p, Vec3(0, 0, -1))));
    }
  }
}

TEST_CASE("quilted's offset takes POV-Ray's FLOOR, one below floor at negative integers",
          "[pattern]") {
  // POV-Ray's FLOOR(x) = x >= 0 ? floor(x) : -floor(-x) - 1: at x = -1 it is -2, so the
  // offset from the cube's centre is -1 - (-2) - 0.5 = +0.5, where floor would give -0.5.
  CHECK(povFloor(-1.0) == -2.0);
  CHECK(povFloor(-0.25) == -1.0);
  CHECK(povFloor(2.0) == 2.0);
  const QuiltedParams q;  // controls 1 and 1: k(t) = (1 - (1 - t)³)·1.154700538
  const Vec3 v = quiltedOffset(Vec3(-1.0, 0.25, 2.0), q);
  const double t = std::sqrt(0.5 * 0.5 + 0.25 * 0.25 + 0.5 * 0.5);
  const double k = (t * t * t + 3 * t * (1 - t) * (1 - t) + 3 * t * t * (1 - t)) * 1.154700538;
  CHECK(v.x == Approx(0.5 * k).epsilon(1e-15));
  CHECK(v.y == Approx(-0.25 * k).epsilon(1e-15));
  CHECK(v.z == Approx(-0.5 * k).epsilon(1e-15));
}

TEST_CASE("spherical, cylindrical and boxed are 1 minus a distance, clipped to 0 beyond 1",
          "[pattern]") {
  // POV-Ray's CLIP_DENSITY of |p|, of the distance to the y axis and of the largest |coordinate|.
  auto clip = [](double r) { return r > 1.0 ? 0.0 : 1.0 - r; };
  const Vec3 points[] = {Vec3(0.0),
                         Vec3(0.3, -0.4, 0.2),
                         Vec3(0.6, 5, -0.7),
                         Vec3(0.3, 0.95, -0.2),
                         Vec3(-0.5, 0.1, 0.5),
                         Vec3(1, 0, 0),
                         Vec3(0.2, -0.9, 0.1)};
  for (const Vec3& p : points) {
    INFO(p.x << " " << p.y << " " << p.z);
    PatternSpec s;
    s.type = PatternType::spherical;
    CHECK(patternValue(s, p) == Approx(clip(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z))));
    s.type = PatternType::cylindrical;
    CHECK(patternValue(s, p) == Approx(clip(std::hypot(p.x, p.z))));
    s.type = PatternType::boxed;
    CHECK(patternValue(s, p) ==
          Approx(clip(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}))));
  }
}

TEST_CASE("cells gives each unit cube POV-Ray's value, the cube chosen below p + 1e-10",
          "[pattern]") {
  // Printed by POV-Ray 3.7 (function { pattern { cells } }): the cube of (0.5, 0.5, 0.5) at
  // its far corner, just below x = 1 within 1e-10 (the next cube), and 4096 cubes away.
  PatternSpec s;
  s.type = PatternType::cells;
  const double inner = 0.71181891532614827, next = 0.68127137050032616;
  CHECK(patternValue(s, Vec3(0.5, 0.5, 0.5)) == inner);
  CHECK(patternValue(s, Vec3(0.99, 0.01, 0.99)) == inner);
  CHECK(patternValue(s, Vec3(1 - 1e-9, 0, 0)) == inner);
  CHECK(patternValue(s, Vec3(-1e-11, 0, 0)) == inner);
  CHECK(patternValue(s, Vec3(1, 0, 0)) == next);
  CHECK(patternValue(s, Vec3(1 - 1e-11, 0, 0)) == next);
  CHECK(patternValue(s, Vec3(4096.5, 0.5, 0.5)) == inner);
  CHECK(patternValue(s, Vec3(-0.5, 0.5, 0.5)) == 0.56695487583056092);
  CHECK(patternValue(s, Vec3(-1, 2, 3)) == 0.53998210094869137);
  CHECK(patternValue(s, Vec3(0.3, -0.4, 0.2)) == 0.09653274621814489);
  CHECK(patternValue(s, Vec3(0.6, 5, -0.7)) == 0.97483614366501570);
}
