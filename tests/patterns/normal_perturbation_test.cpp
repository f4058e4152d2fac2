// Perturbed normals against POV-Ray 3.7's renders (tests/data/patterns/normals.csv: a plane
// facing the camera lit by three coloured parallel lights, 16-bit channels = N·L).
#include "normal_cases.h"
#include "reference_csv.h"

#include "render/patterns/normal_perturbation.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

// The render of make_references.sh: 16×16 pixels over the square of side 4 centred at
// (0.375, -1.25) on the plane z = 0, whose normal -z faces the camera.
Vec3 pixelPoint(double i, double j) {
  return Vec3(0.375 + 4.0 * ((i + 0.5) / 16.0 - 0.5), -1.25 + 4.0 * (0.5 - (j + 0.5) / 16.0), 0.0);
}

// The red, green and blue lights' directions (towards the lights).
const Vec3 kLights[3] = {Vec3(0, 0, -1), glm::normalize(Vec3(1, 0, -1)),
                         glm::normalize(Vec3(0, 1, -1))};

}  // namespace

TEST_CASE("every normal reference case has a Lucent spec", "[pattern]") {
  const auto cases = referenceCases("normals.csv");
  const auto specs = normalCases();
  for (const auto& [name, rows] : cases) {
    INFO(name);
    CHECK(specs.count(name) == 1);
    CHECK(rows.size() == 256);
  }
  CHECK(cases.size() == specs.size());
}

TEST_CASE("perturbed normals light a plane as POV-Ray's do, to 16-bit quantisation", "[pattern]") {
  const auto cases = referenceCases("normals.csv");
  for (const auto& [name, s] : normalCases()) {
    auto it = cases.find(name);
    REQUIRE(it != cases.end());
    double worst = 0.0;  // in 1/65535 steps
    Vec3 where(0.0);
    for (const ReferenceRow& r : it->second) {
      const Vec3 p = pixelPoint(r.values[0], r.values[1]);
      const Vec3 n = perturbNormal(s, p, Vec3(0, 0, -1));
      CHECK(std::fabs(glm::length(n) - 1.0) < 1e-15);
      for (int c = 0; c < 3; ++c) {
        const double expected = std::max(0.0, glm::dot(n, kLights[c])) * 65535.0;
        const double error = std::fabs(expected - r.values[2 + c]);
        if (!(error <= worst)) {
          worst = error;
          where = p;
        }
      }
    }
    INFO(name << ": worst error " << worst << "/65535 at " << where.x << " " << where.y);
    CHECK(worst <= 0.51);
  }
}

TEST_CASE("zero depth leaves the normal as it was, in every transform", "[pattern]") {
  NormalSpec n;
  n.depth = 0.0;
  n.pattern.placement.patternFromObject = inverseScale(Vec3(0.5, 2, 3));
  for (PatternType t : {PatternType::bumps, PatternType::granite, PatternType::ripples}) {
    n.pattern.type = t;
    const Vec3 r = perturbNormal(n, Vec3(0.3, -1.2, 2.5), Vec3(0, 0.6, 0.8));
    CHECK(r.x == Approx(0.0).margin(1e-15));
    CHECK(r.y == Approx(0.6).epsilon(1e-15));
    CHECK(r.z == Approx(0.8).epsilon(1e-15));
  }
}
