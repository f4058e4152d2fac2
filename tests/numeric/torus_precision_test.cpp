// The torus's hard cases against references computed in long double (x87 extended, 64-bit
// significand): tangent rays, rays through the hole and along the axis, rays from far away,
// and tori scaled by 1e-4 and 1e4. Set LUCENT_PRINT_ACCURACY=1 to print the measured
// worst relative errors (docs/accuracy.md quotes them).
#include "primitives/torus.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace lucent;

namespace {

using LD = long double;

// The torus's small factor (ρ − R)² + y² − r² along the ray, in long double.
LD g1(double R, double r, const Ray& ray, LD t) {
  LD x = ray.o.x + t * (LD)ray.d.x, y = ray.o.y + t * (LD)ray.d.y, z = ray.o.z + t * (LD)ray.d.z;
  LD rho = std::sqrt(x * x + z * z);
  return (rho - R) * (rho - R) + y * y - (LD)r * r;
}

// The root of g1 in [a, b] (a sign change), by bisection to the last long double bit.
LD bisect(double R, double r, const Ray& ray, LD a, LD b) {
  LD fa = g1(R, r, ray, a);
  for (int i = 0; i < 200; ++i) {
    LD m = 0.5L * (a + b);
    if (m == a || m == b) break;
    LD fm = g1(R, r, ray, m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5L * (a + b);
}

// Reference roots: g1's sign changes on a fine sampling of the bounding chord, bisected.
std::vector<LD> referenceRoots(double R, double r, const Ray& ray) {
  std::vector<LD> roots;
  LD dd = (LD)ray.d.x * ray.d.x + (LD)ray.d.y * ray.d.y + (LD)ray.d.z * ray.d.z;
  LD tc = -((LD)ray.o.x * ray.d.x + (LD)ray.o.y * ray.d.y + (LD)ray.o.z * ray.d.z) / dd;
  LD half = 1.5L * (R + r) / std::sqrt(dd);
  const int n = 6000;
  LD prevT = tc - half, prev = g1(R, r, ray, prevT);
  for (int i = 1; i <= n; ++i) {
    LD t = tc - half + 2 * half * i / n;
    LD f = g1(R, r, ray, t);
    if ((f < 0) != (prev < 0)) roots.push_back(bisect(R, r, ray, prevT, t));
    prevT = t;
    prev = f;
  }
  return roots;
}

struct Worst {
  double rel = 0.0;
  void add(double t, LD ref) { rel = std::max(rel, double(std::abs((t - ref) / ref))); }
};

void report(const char* what, const Worst& w) {
  if (std::getenv("LUCENT_PRINT_ACCURACY"))
    std::printf("torus accuracy, %s: max relative t error %.3g\n", what, w.rel);
}

// Compares every root the torus reports with the reference ones.
void compare(const Torus& t, double R, double r, const Ray& ray, Worst& w) {
  double roots[4];
  int n = t.lineRoots(ray, roots);
  std::vector<LD> ref = referenceRoots(R, r, ray);
  INFO("ray o=(" << ray.o.x << "," << ray.o.y << "," << ray.o.z << ") d=(" << ray.d.x << ","
                 << ray.d.y << "," << ray.d.z << ")");
  REQUIRE(size_t(n) == ref.size());
  for (int i = 0; i < n; ++i) w.add(roots[i], ref[i]);
}

}  // namespace

TEST_CASE("torus precision: random rays from near and far", "[numeric][torus]") {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Worst near, far;
  for (int i = 0; i < 1500; ++i) {
    const double R = 1.0, r = i % 2 ? 0.25 : 0.05;
    Torus t(R, r);
    Vec3 target(1.2 * u(rng), r * u(rng), 1.2 * u(rng));
    Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    double dist = i % 3 == 0 ? 1e5 : 4.0;
    Ray ray(target - dist * dir, dir * (1.0 + 0.5 * u(rng)));
    compare(t, R, r, ray, dist > 10 ? far : near);
  }
  report("random rays from distance 4", near);
  report("random rays from distance 1e5", far);
  CHECK(near.rel < 4e-15);
  // From 1e5 away t ≈ 1e5: its last bit is 1.5e-11, the torus's size is 1; the hit point
  // is known to about 1e5·ε absolute, i.e. t to ~ε relative.
  CHECK(far.rel < 4e-15);
}

TEST_CASE("torus precision: rays through the hole and parallel to the axis", "[numeric][torus]") {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 1.0, r = 0.3;
  Torus t(R, r);
  Worst hole, axis;
  int holeHits = 0;
  for (int i = 0; i < 800; ++i) {
    // Through the hole: from above, through a point of the disc ρ < R − r, tilted enough
    // that many meet the inner wall.
    Vec3 through(0.6 * u(rng), 0.0, 0.6 * u(rng));
    if (std::sqrt(through.x * through.x + through.z * through.z) > 0.65) continue;
    Vec3 dir = glm::normalize(Vec3(1.5 * u(rng), -1.0, 1.5 * u(rng)));
    double roots[4];
    holeHits += t.lineRoots(Ray(through - 3.0 * dir, dir), roots) > 0;
    compare(t, R, r, Ray(through - 3.0 * dir, dir), hole);
    // Parallel to the axis at a random distance ρ from it (hits the tube iff |ρ − R| < r).
    double rho = 1.5 * std::abs(u(rng));
    double phi = kPi * u(rng);
    compare(t, R, r, Ray(Vec3(rho * std::cos(phi), 3.0, rho * std::sin(phi)), Vec3(0, -1, 0)),
            axis);
  }
  // Exactly on the axis: no hit, in both directions.
  double roots[4];
  CHECK(t.lineRoots(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), roots) == 0);
  CHECK(t.lineRoots(Ray(Vec3(0, -5, 0), Vec3(0, 2, 0)), roots) == 0);
  CHECK(holeHits > 100);
  report("rays through the hole", hole);
  report("rays parallel to the axis", axis);
  CHECK(hole.rel < 4e-15);
  CHECK(axis.rel < 4e-15);
}

TEST_CASE("torus precision: tangent rays touch at the analytic point", "[numeric][torus]") {
  // Horizontal rays in the plane y = r touch the top circle ρ = R, y = r: the quartic has a
  // double root there, where ((ρ² − R²)²) vanishes to second order. The touching point is
  // found as the minimum of the quartic, so t is accurate although the root is double.
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 1.0, r = 0.25;
  Torus t(R, r);
  Worst top, outer;
  int touched = 0, tried = 0;
  for (int i = 0; i < 2000; ++i) {
    // The line z = b (|b| < R) at height r: touches at x = ±√(R² − b²).
    double b = 0.95 * u(rng);
    Ray ray(Vec3(-3.0, r, b), Vec3(1.0 + 0.5 * std::abs(u(rng)), 0, 0));
    LD xs = std::sqrt((LD)R * R - (LD)b * b);
    LD ref0 = (-xs + 3.0L) / ray.d.x, ref1 = (xs + 3.0L) / ray.d.x;
    double roots[4];
    int n = t.lineRoots(ray, roots);
    ++tried;
    if (n == 4) {
      ++touched;
      top.add(roots[0], ref0);
      top.add(roots[1], ref0);
      top.add(roots[2], ref1);
      top.add(roots[3], ref1);
    }
    // The outer equator: rays in y = 0 at distance R + r from the axis touch at one point.
    double phi = kPi * u(rng);
    Vec3 n0(std::cos(phi), 0, std::sin(phi)), tan(-std::sin(phi), 0, std::cos(phi));
    Ray eq((R + r) * n0 - 2.0 * tan, tan);
    int m = t.lineRoots(eq, roots);
    if (m == 2) {
      outer.add(roots[0], 2.0L);
      outer.add(roots[1], 2.0L);
    }
    CHECK((m == 0 || m == 2));
  }
  report("tangent rays over the top circle", top);
  report("tangent rays at the outer equator", outer);
  // Touching within rounding may be reported or not; most must be, and where they are the
  // point is accurate to far better than the √ε of a naive double-root solve.
  CHECK(touched > tried / 2);
  CHECK(top.rel < 1e-12);
  CHECK(outer.rel < 1e-12);
}

TEST_CASE("torus precision: tori scaled by 1e-4 and 1e4", "[numeric][torus]") {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double s : {1e-4, 1e4}) {
    const double R = 1.0 * s, r = 0.2 * s;
    Torus t(R, r);
    Worst w;
    for (int i = 0; i < 400; ++i) {
      Vec3 target(1.2 * s * u(rng), r * u(rng), 1.2 * s * u(rng));
      Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
      compare(t, R, r, Ray(target - 4.0 * s * dir, dir), w);
    }
    report(s < 1 ? "torus scaled 1e-4" : "torus scaled 1e4", w);
    CHECK(w.rel < 4e-15);
  }
}
