#include "primitives/watertight_filter.h"
#include "primitives/watertight.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace lucent;

namespace {

// For every group of up to four triangles: a lane the pre-test clears is a triangle the
// exact test misses. Returns how many lanes it cleared (so a test can require that it
// does filter).
int checkGroups(const Ray& ray, const std::vector<std::array<Vec3, 3>>& tris) {
  const ShearedRay sr(ray);
  int cleared = 0;
  for (size_t s = 0; s < tris.size(); s += 4) {
    const int n = int(std::min<size_t>(4, tris.size() - s));
    const Vec3* corners[4][3];
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) corners[i][k] = &tris[s + i][k];
    const int mask = watertightCandidates(sr, corners, n);
    REQUIRE((mask >> n) == 0);
    for (int i = 0; i < n; ++i) {
      if (mask & (1 << i)) continue;
      ++cleared;
      TriangleIntersection ti;
      const auto& t = tris[s + i];
      INFO("triangle " << s + i);
      CHECK_FALSE(intersectTriangle(sr, t[0], t[1], t[2], ti));
    }
  }
  return cleared;
}

}  // namespace

TEST_CASE("watertight pre-test: never clears a triangle the exact test hits (random)",
          "[primitives][watertight]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int cleared = 0, hits = 0;
  for (int round = 0; round < 2000; ++round) {
    Ray ray(Vec3(u(rng), u(rng), u(rng)) * 3.0, Vec3(u(rng), u(rng), u(rng)));
    std::vector<std::array<Vec3, 3>> tris;
    const int count = 1 + round % 9;
    for (int i = 0; i < count; ++i) {
      // Small triangles near points of the ray, so that some are hit and some missed.
      Vec3 c = ray.at(2.0 * u(rng)) + 0.05 * Vec3(u(rng), u(rng), u(rng));
      tris.push_back({c + 0.1 * Vec3(u(rng), u(rng), u(rng)),
                      c + 0.1 * Vec3(u(rng), u(rng), u(rng)),
                      c + 0.1 * Vec3(u(rng), u(rng), u(rng))});
      TriangleIntersection ti;
      hits +=
          intersectTriangle(ShearedRay(ray), tris.back()[0], tris.back()[1], tris.back()[2], ti);
    }
    cleared += checkGroups(ray, tris);
  }
  CHECK(hits > 1000);
  CHECK(cleared > 1000);  // it does reject most misses
}

TEST_CASE("watertight pre-test: rays exactly through shared edges and vertices",
          "[primitives][watertight]") {
  // A fan of triangles around the origin in the plane z = 0, and rays through its centre,
  // through points of its edges and along them: the cases the exact test settles with its
  // exactly signed edge functions and tie-break, which the pre-test must leave to it.
  std::vector<std::array<Vec3, 3>> fan;
  const int k = 7;
  for (int i = 0; i < k; ++i) {
    double a0 = 2.0 * M_PI * i / k, a1 = 2.0 * M_PI * (i + 1) / k;
    fan.push_back(
        {Vec3(0.0), Vec3(std::cos(a0), std::sin(a0), 0.0), Vec3(std::cos(a1), std::sin(a1), 0.0)});
  }
  const Vec3 dirs[] = {Vec3(0, 0, -1), Vec3(0.3, -0.2, -1), Vec3(1, 0, 0), Vec3(1, 1e-17, 0),
                       Vec3(-0.5, 0.25, 1)};
  int exactHits = 0;
  for (const Vec3& d : dirs) {
    for (const auto& tri : fan) {
      // Through the centre, the edges' midpoints and a corner.
      for (const Vec3& p : {Vec3(0.0), 0.5 * tri[1], 0.5 * (tri[1] + tri[2]), tri[2]}) {
        Ray ray(p - 2.0 * d, d);
        checkGroups(ray, fan);
        for (const auto& t : fan) {
          TriangleIntersection ti;
          exactHits += intersectTriangle(ShearedRay(ray), t[0], t[1], t[2], ti);
        }
      }
    }
  }
  CHECK(exactHits > 0);
}

TEST_CASE("watertight pre-test: a zero direction clears every lane", "[primitives][watertight]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const Vec3* corners[4][3] = {{&a, &b, &c}, {&a, &b, &c}, {&a, &b, &c}, {&a, &b, &c}};
  CHECK(watertightCandidates(ShearedRay(Ray(Vec3(0.2, 0.2, 1), Vec3(0.0))), corners, 4) == 0);
  CHECK(watertightCandidates(ShearedRay(Ray(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1))), corners, 3) ==
        0b111);
}
