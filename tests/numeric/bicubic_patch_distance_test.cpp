// How far a bicubic patch's hits lie from the exact Bézier surface (docs/accuracy.md,
// "Bicubic patches"): POV-Ray's patch, and so Lucent's, is the triangles of its
// subdivision. The reference is the surface evaluated here in long double from the
// Bernstein form (not through the subdivision): each hit's nearest surface point found by
// Gauss-Newton from the hit's interpolated (u, v). The tests assert the interpolation
// bound (1/2)(Muu hu² + 2 Muv hu hv + Mvv hv²), from the control points' second
// differences, and that halving the parts divides the distance by about four.
// LUCENT_PRINT_ACCURACY=1 prints the table.
#include "primitives/bicubic_patch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace lucent;

namespace {

using LD = long double;
struct LV {
  LD x = 0, y = 0, z = 0;
};
LV operator+(LV a, LV b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
LV operator-(LV a, LV b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
LV operator*(LD s, LV a) { return {s * a.x, s * a.y, s * a.z}; }
LD dot(LV a, LV b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The surface and its first and second derivatives at (u, v), from the Bernstein form.
struct Jet {
  LV s, su, sv;
};
Jet evaluate(const PatchPoints& p, LD u, LD v) {
  auto basis = [](LD t, LD b[4], LD d[4]) {
    const LD r = 1 - t;
    b[0] = r * r * r, b[1] = 3 * t * r * r, b[2] = 3 * t * t * r, b[3] = t * t * t;
    d[0] = -3 * r * r, d[1] = 3 * r * r - 6 * t * r, d[2] = 6 * t * r - 3 * t * t, d[3] = 3 * t * t;
  };
  LD bu[4], du[4], bv[4], dv[4];
  basis(u, bu, du);
  basis(v, bv, dv);
  Jet j;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const Vec3& q = p[static_cast<size_t>(4 * a + b)];
      const LV c{q.x, q.y, q.z};
      j.s = j.s + (bu[a] * bv[b]) * c;
      j.su = j.su + (du[a] * bv[b]) * c;
      j.sv = j.sv + (bu[a] * dv[b]) * c;
    }
  return j;
}

// The distance from x to the surface near (u, v): Gauss-Newton on |S(u, v) − x|², kept in
// the unit square.
LD distanceToSurface(const PatchPoints& p, LV x, LD u, LD v) {
  for (int it = 0; it < 30; ++it) {
    const Jet j = evaluate(p, u, v);
    const LV r = j.s - x;
    const LD a = dot(j.su, j.su), b = dot(j.su, j.sv), c = dot(j.sv, j.sv);
    const LD gu = dot(j.su, r), gv = dot(j.sv, r);
    const LD det = a * c - b * b;
    if (!(det > 0)) break;
    u = std::clamp(u - (c * gu - b * gv) / det, LD(0), LD(1));
    v = std::clamp(v - (a * gv - b * gu) / det, LD(0), LD(1));
  }
  const LV r = evaluate(p, u, v).s - x;
  return std::sqrt(dot(r, r));
}

// Bounds of |Suu|, |Suv| and |Svv| from the control points' differences.
std::array<double, 3> secondDerivativeBounds(const PatchPoints& p) {
  auto at = [&](int i, int j) { return p[static_cast<size_t>(4 * i + j)]; };
  double uu = 0, uv = 0, vv = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (i < 2) uu = std::max(uu, 6 * glm::length(at(i + 2, j) - 2.0 * at(i + 1, j) + at(i, j)));
      if (j < 2) vv = std::max(vv, 6 * glm::length(at(i, j + 2) - 2.0 * at(i, j + 1) + at(i, j)));
      if (i < 3 && j < 3)
        uv = std::max(uv,
                      9 * glm::length(at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j)));
    }
  return {uu, uv, vv};
}

// POV-Ray's bezier.pov sample: a sheet over [0, 3]² bent up and down at its corners.
PatchPoints bentSheet() {
  PatchPoints p{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const bool corner = (i == 0 || i == 3) && (j == 0 || j == 3);
      p[static_cast<size_t>(4 * i + j)] = Vec3(j, i, corner ? (j == 0 ? 2.0 : -2.0) : 0.0);
    }
  return p;
}

struct Row {
  int steps = 0;
  int hits = 0;
  double max = 0, median = 0, bound = 0;
};

Row measure(const PatchPoints& p, int steps, int rays) {
  const BicubicPatch patch(p, 0.0, steps, steps);
  std::mt19937_64 rng(4242 + static_cast<unsigned>(steps));
  std::uniform_real_distribution<double> across(0.05, 2.95);
  std::vector<double> d;
  for (int k = 0; k < rays; ++k) {
    // From in front of the sheet, slanted, towards a point of the square.
    const Vec3 target(across(rng), across(rng), 0.0);
    const Vec3 o = target + Vec3(across(rng) - 1.5, across(rng) - 1.5, 6.0);
    const Ray ray(o, target - o);
    Hit h;
    if (!patch.intersect(ray, h)) continue;
    const SurfaceInfo s = patch.surface(ray, h);
    const LV x{s.p.x, s.p.y, s.p.z};
    d.push_back(static_cast<double>(distanceToSurface(p, x, s.uv.y, s.uv.x)));
  }
  Row r;
  r.steps = steps;
  r.hits = static_cast<int>(d.size());
  std::sort(d.begin(), d.end());
  if (!d.empty()) r.max = d.back(), r.median = d[d.size() / 2];
  const auto m = secondDerivativeBounds(p);
  const double h = std::ldexp(1.0, -steps);
  r.bound = 0.5 * (m[0] + 2 * m[1] + m[2]) * h * h;
  return r;
}

}  // namespace

TEST_CASE("bicubic patch: hits lie within the interpolation bound of the exact surface",
          "[numeric][accuracy][bicubic]") {
  const PatchPoints sheet = bentSheet();
  std::vector<Row> rows;
  for (int steps = 1; steps <= 6; ++steps) rows.push_back(measure(sheet, steps, 4000));
  if (std::getenv("LUCENT_PRINT_ACCURACY")) {
    std::printf("| u-steps = v-steps | hits | distance: max | distance: median | bound |\n");
    for (const Row& r : rows)
      std::printf("| %d | %d | %.2g | %.2g | %.2g |\n", r.steps, r.hits, r.max, r.median, r.bound);
  }
  for (size_t k = 0; k < rows.size(); ++k) {
    INFO("steps " << rows[k].steps);
    CHECK(rows[k].hits > 3000);
    CHECK(rows[k].max <= rows[k].bound);
    CHECK(rows[k].max > 0.0);
    // Quadratic convergence: each halving divides the distance by about four.
    if (k > 0) CHECK(rows[k].max < 0.35 * rows[k - 1].max);
  }
}
