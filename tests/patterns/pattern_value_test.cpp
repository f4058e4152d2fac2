// Lucent's pattern values against POV-Ray 3.7's (function { pattern { ... } }, the pattern
// with its transform, turbulence, frequency, phase and wave; tests/data/patterns).
#include "pattern_cases.h"
#include "reference_csv.h"

#include "render/patterns/normal_perturbation.h"
#include "render/patterns/pattern_value.h"

#include <catch2/catch.hpp>

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

TEST_CASE("the 22 types, turbulence, frequency, phase and waves equal POV-Ray's to 1e-13",
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
