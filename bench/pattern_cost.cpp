// The cost of one evaluation of each procedural pattern (render/patterns/): patternValue,
// perturbNormal and the colour lookups, timed over a fixed set of points on one thread.
// The figures go to docs/patterns-noise.md; nothing asserts on them.
#include "primitives/noise.h"
#include "render/patterns/block_pattern.h"
#include "render/patterns/color_map.h"
#include "render/patterns/normal_perturbation.h"
#include "render/patterns/pattern_surface.h"
#include "render/patterns/pattern_value.h"

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <vector>

using namespace lucent;

namespace {

std::vector<Vec3> points(int n) {
  std::vector<Vec3> p;
  uint32_t s = 12345;
  auto next = [&] {
    s = s * 1664525u + 1013904223u;
    return (s >> 8) / 16777216.0 * 16.0 - 8.0;
  };
  for (int i = 0; i < n; ++i) p.emplace_back(next(), next(), next());
  return p;
}

// Nanoseconds per call of f over the points, the best of five passes.
template <class F>
double nanoseconds(const std::vector<Vec3>& pts, F&& f) {
  double best = 1e30;
  volatile double sink = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    const auto t0 = std::chrono::steady_clock::now();
    double acc = 0.0;
    for (const Vec3& p : pts) acc += f(p);
    const auto t1 = std::chrono::steady_clock::now();
    sink = sink + acc;
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / pts.size());
  }
  return best;
}

}  // namespace

int main() {
  const std::vector<Vec3> pts = points(200000);
  fmt::print("| pattern | value, ns | value with turbulence 0.5, ns | normal (depth 0.5), ns |\n");
  fmt::print("|---|---:|---:|---:|\n");
  for (int t = 0; t < kPatternTypeCount; ++t) {
    PatternSpec s;
    s.type = static_cast<PatternType>(t);
    s.frequency = defaultFrequency(s.type);
    // The fractals at 50 iterations over [−2, 2)³ (the points scaled by ¼), where most
    // points take more than a step; julia and magnet's Julia form with a constant near
    // their sets.
    if (isFractal(s.type)) {
      s.fractal.iterations = 50;
      s.fractal.cReal = -0.5;
      s.fractal.cImaginary = 0.5;
      s.placement.patternFromObject = glm::scale(Mat4(1.0), Vec3(0.25));
    }
    // slope reads the surface: a tilted normal, with an altitude so both parts count.
    if (s.type == PatternType::slope) s.slope.altitude = Vec3(0, 1, 0);
    PatternSurface surface{glm::normalize(Vec3(0.3, 0.8, 0.5)), Vec3(0.0)};
    const PatternSurfaceScope scope(s.type == PatternType::slope, surface);
    PatternSpec turbulent = s;
    turbulent.placement.turbulence = Vec3(0.5);
    NormalSpec n;
    n.pattern = s;
    if (!kPatternTypes[t].colour) {
      // A normal only (facets), with no value: its normal, the surface's normal turning with
      // the point as a sphere's does, and with coords (which reads the point instead).
      auto sphereNormal = [](const Vec3& p) { return glm::normalize(p + Vec3(0.01, 0.02, 0.03)); };
      const double normal =
          nanoseconds(pts, [&](const Vec3& p) { return perturbNormal(n, p, sphereNormal(p)).x; });
      fmt::print("| {} | — | — | {:.0f} |\n", kPatternTypes[t].name, normal);
      n.pattern.facets.coords = 0.4;
      const double coords =
          nanoseconds(pts, [&](const Vec3& p) { return perturbNormal(n, p, sphereNormal(p)).x; });
      fmt::print("| {} with coords 0.4 | — | — | {:.0f} |\n", kPatternTypes[t].name, coords);
      continue;
    }
    const double plain = nanoseconds(pts, [&](const Vec3& p) { return patternValue(s, p); });
    const double turb = nanoseconds(pts, [&](const Vec3& p) { return patternValue(turbulent, p); });
    const double normal =
        nanoseconds(pts, [&](const Vec3& p) { return perturbNormal(n, p, Vec3(0, 0, -1)).x; });
    fmt::print("| {} | {:.0f} | {:.0f} | {:.0f} |\n", kPatternTypes[t].name, plain, turb, normal);
  }
  // Each of the 27 tilings (the table above times tiling 1, its default).
  fmt::print("\n| tiling | value, ns |\n|---|---:|\n");
  for (int k = 1; k <= 27; ++k) {
    PatternSpec s;
    s.type = PatternType::tiling;
    s.tiling = k;
    fmt::print("| {} | {:.0f} |\n", k,
               nanoseconds(pts, [&](const Vec3& p) { return patternValue(s, p); }));
  }
  const ColorMap map{{{0.2, Color(1, 0, 0)}, {0.5, Color(0, 1, 0)}, {0.9, Color(0, 0, 1)}}};
  const HexagonSpec hex;
  const BrickSpec brick;
  fmt::print("\n| other | ns |\n|---|---:|\n");
  for (int g = 1; g <= 3; ++g)
    fmt::print("| noise, generator {} | {:.1f} |\n", g,
               nanoseconds(pts, [&](const Vec3& p) { return noise(p, g); }));
  fmt::print("| dnoise | {:.1f} |\n", nanoseconds(pts, [&](const Vec3& p) { return dnoise(p).x; }));
  fmt::print("| colour map lookup (3 entries) | {:.1f} |\n",
             nanoseconds(pts, [&](const Vec3& p) { return lookupColorMap(map, p.x * 0.1).r; }));
  // What a scene with a slope pays per hit besides the pattern: opening the surface scope.
  fmt::print("| slope's surface scope, per hit | {:.1f} |\n", nanoseconds(pts, [&](const Vec3& p) {
               PatternSurface surface{p, p};
               const PatternSurfaceScope scope(true, surface);
               return currentPatternSurface()->normal.x;
             }));
  fmt::print("| hexagon | {:.1f} |\n",
             nanoseconds(pts, [&](const Vec3& p) { return hexagonColor(hex, p).r; }));
  fmt::print("| brick | {:.1f} |\n",
             nanoseconds(pts, [&](const Vec3& p) { return brickColor(brick, p).r; }));
  return 0;
}
