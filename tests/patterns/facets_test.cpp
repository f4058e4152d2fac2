// POV-Ray 3.7's facets normal (normal.cpp, facets) against its rule worked out here
// independently: crackle's random point of every unit cube (floor + three consecutive
// values of the default-seeded Mersenne twister at the cube's hash), the nearest one to
// the scaled normal (or, with coords, the scaled point) found among the cubes POV-Ray
// searches (those of the 5x5x5 block around its cube with at most one coordinate two
// away, scanned here in a different order, ties aside), then the normal replaced by it,
// or bent by the noise gradient there.
#include "primitives/noise.h"
#include "render/patterns/normal_perturbation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <random>

using namespace lucent;

namespace {

double randomAt(int i) {
  std::mt19937 twister;
  twister.discard(static_cast<unsigned long long>(i));
  return static_cast<double>(twister()) / 4294967296.0;
}

Vec3 cubePoint(int x, int y, int z) {
  const int seed = latticeHash(x, y, z);
  return Vec3(x + randomAt(seed), y + randomAt(seed + 1), z + randomAt(seed + 2));
}

// The nearest cube point to t under `distance` among the cubes POV-Ray searches.
Vec3 nearestPoint(const Vec3& t, const std::function<double(const Vec3&)>& distance) {
  const int fx = static_cast<int>(std::floor(t.x - 1e-10));
  const int fy = static_cast<int>(std::floor(t.y - 1e-10));
  const int fz = static_cast<int>(std::floor(t.z - 1e-10));
  Vec3 best(0.0);
  double bestD = INFINITY;
  for (int z = 2; z >= -2; --z)
    for (int y = 2; y >= -2; --y)
      for (int x = 2; x >= -2; --x) {
        if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) > 1) continue;
        const Vec3 c = cubePoint(fx + x, fy + y, fz + z);
        const double d = distance(c - t);
        if (d < bestD) {
          bestD = d;
          best = c;
        }
      }
  return best;
}

double euclidean(const Vec3& d) { return glm::dot(d, d); }

NormalSpec facetsSpec(double size, double coords = 0.0, double metric = 2.0) {
  NormalSpec n;
  n.pattern.type = PatternType::facets;
  n.pattern.facets = {size, coords, metric};
  return n;
}

void checkNear(const Vec3& got, const Vec3& want) {
  INFO(got.x << " " << got.y << " " << got.z << " want " << want.x << " " << want.y << " "
             << want.z);
  CHECK(got.x == Approx(want.x).margin(1e-12));
  CHECK(got.y == Approx(want.y).margin(1e-12));
  CHECK(got.z == Approx(want.z).margin(1e-12));
}

}  // namespace

TEST_CASE("facets replaces the normal by the random point nearest the normal over size",
          "[pattern][facets]") {
  for (const double size : {0.1, 0.25, 0.05}) {
    for (const Vec3 n : {Vec3(0.3, 0.8, -0.2), Vec3(-0.7, -0.1, 0.4), Vec3(0.0, 0.0, 1.0),
                         Vec3(0.6, -0.6, 0.52)}) {
      const Vec3 unit = glm::normalize(n);
      const Vec3 want = glm::normalize(nearestPoint(unit / size, euclidean));
      // The point does not matter, nor does the depth (POV-Ray's amount is unused).
      checkNear(perturbNormal(facetsSpec(size), Vec3(4.0, -2.0, 7.0), n), want);
      NormalSpec deep = facetsSpec(size);
      deep.depth = 3.0;
      checkNear(perturbNormal(deep, Vec3(-1.0, 0.5, 0.0), n), want);
    }
  }
}

TEST_CASE("facets are flat: normals near each other share one facet's normal",
          "[pattern][facets]") {
  const Vec3 a = glm::normalize(Vec3(0.3, 0.8, -0.2));
  const Vec3 b = glm::normalize(a + Vec3(0.001, -0.0005, 0.0008));
  REQUIRE(nearestPoint(a / 0.1, euclidean) == nearestPoint(b / 0.1, euclidean));
  CHECK(perturbNormal(facetsSpec(0.1), Vec3(0.0), a) ==
        perturbNormal(facetsSpec(0.1), Vec3(0.0), b));
  // The bent normal is not the surface's: the facet tilts it.
  CHECK(glm::length(perturbNormal(facetsSpec(0.1), Vec3(0.0), a) - a) > 1e-3);
}

TEST_CASE("facets with coords bend the normal by the noise gradient at the nearest point",
          "[pattern][facets]") {
  for (const double coords : {0.4, -1.5}) {
    for (const Vec3 p : {Vec3(0.37, 1.21, -0.66), Vec3(-3.1, 0.05, 2.2)}) {
      const Vec3 n = glm::normalize(Vec3(0.2, 0.9, 0.3));
      const Vec3 q = nearestPoint(p / 0.5, euclidean);
      const Vec3 g = dnoise(q);
      const Vec3 want = glm::normalize(n + coords * (g - glm::dot(g, n) * n));
      checkNear(perturbNormal(facetsSpec(0.5, coords), p, n), want);
    }
  }
}

TEST_CASE("facets' metric 1 sums the signed differences and others the powers",
          "[pattern][facets]") {
  const Vec3 n = glm::normalize(Vec3(-0.45, 0.7, 0.55));
  const Vec3 t = n / 0.2;
  auto signedSum = [](const Vec3& d) { return d.x + d.y + d.z; };
  checkNear(perturbNormal(facetsSpec(0.2, 0.0, 1.0), Vec3(0.0), n),
            glm::normalize(nearestPoint(t, signedSum)));
  auto cubes = [](const Vec3& d) {
    return std::pow(std::fabs(d.x), 3.0) + std::pow(std::fabs(d.y), 3.0) +
           std::pow(std::fabs(d.z), 3.0);
  };
  checkNear(perturbNormal(facetsSpec(0.2, 0.0, 3.0), Vec3(0.0), n),
            glm::normalize(nearestPoint(t, cubes)));
  // The signed sum favours the lowest points searched: not the Euclidean choice here.
  CHECK(nearestPoint(t, signedSum) != nearestPoint(t, euclidean));
}

TEST_CASE("facets' size below 1e-6 acts as 1e-6", "[pattern][facets]") {
  const Vec3 n = glm::normalize(Vec3(0.1, 0.2, 0.9));
  const Vec3 want = glm::normalize(nearestPoint(n * 1e6, euclidean));
  checkNear(perturbNormal(facetsSpec(0.0), Vec3(0.0), n), want);
  checkNear(perturbNormal(facetsSpec(-2.0), Vec3(0.0), n), want);
}
