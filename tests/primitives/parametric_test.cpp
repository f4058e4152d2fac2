// The parametric primitive against exact references: a sphere and a plane patch given as
// (u, v) surfaces (hit distances from their closed forms), a Möbius strip against every
// solution Newton's method finds from a dense grid of starting points, the interval bound,
// precomputed intervals, the container, the guard at a ray's start, the crossings
// contract and (u, v).
#include "shape_checks.h"

#include "primitives/parametric.h"
#include "primitives/quadratic.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace lucent;
using namespace lucent::test;

namespace {

class UvField final : public ScalarField {
 public:
  explicit UvField(std::function<double(double, double)> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override { return f_(p.x, p.y); }

 private:
  std::function<double(double, double)> f_;
};

using Fn = std::function<double(double, double)>;

Parametric::Params params(Fn x, Fn y, Fn z, Vec2 lo, Vec2 hi) {
  Parametric::Params p;
  p.functions = {std::make_shared<UvField>(std::move(x)), std::make_shared<UvField>(std::move(y)),
                 std::make_shared<UvField>(std::move(z))};
  p.uvMin = lo;
  p.uvMax = hi;
  p.container.min = Vec3(-2.0);
  p.container.max = Vec3(2.0);
  return p;
}

// The unit sphere: u the angle round y, v from the north pole. Every coordinate's slope
// along u and along v is at most 1.
Parametric::Params unitSphere() {
  auto p = params([](double u, double v) { return std::cos(u) * std::sin(v); },
                  [](double, double v) { return std::cos(v); },
                  [](double u, double v) { return std::sin(u) * std::sin(v); }, Vec2(0.0),
                  Vec2(2.0 * kPi, kPi));
  p.maxGradient = 1.0;
  return p;
}

// POV-Ray's Möbius strip of the sample scene portfolio/allobjects.pov.
Parametric::Params mobius() {
  auto p =
      params([](double u, double v) { return std::cos(u) + v * std::cos(u / 2) * std::cos(u); },
             [](double u, double v) { return std::sin(u) + v * std::cos(u / 2) * std::sin(u); },
             [](double u, double v) { return v * std::sin(u / 2); }, Vec2(0.0, -0.3),
             Vec2(2.0 * kPi, 0.3));
  p.maxGradient = 1.5;  // |d/du| <= 1 + 0.3 + 0.15, |d/dv| <= 1
  return p;
}

// Every (t, u, v) with S(u, v) = o + t·d that Newton's method reaches from a grid of
// starting points on the rectangle; the nearest t above `lower`, or infinity.
double nearestByNewton(const Parametric& s, const Ray& ray, double lower) {
  const Parametric::Params& p = s.params();
  double best = kInf;
  const int nu = 160, nv = 24;
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      double u = p.uvMin.x + (p.uvMax.x - p.uvMin.x) * i / nu;
      double v = p.uvMin.y + (p.uvMax.y - p.uvMin.y) * j / nv;
      // Start t at the projection of the grid point on the ray.
      double t = glm::dot(s.point(u, v) - ray.o, ray.d) / glm::dot(ray.d, ray.d);
      bool ok = false;
      for (int k = 0; k < 30; ++k) {
        const Vec3 r = s.point(u, v) - ray.at(t);
        if (glm::length(r) < 1e-12) {
          ok = true;
          break;
        }
        const double h = 1e-7;
        const Vec3 su = (s.point(u + h, v) - s.point(u - h, v)) / (2 * h);
        const Vec3 sv = (s.point(u, v + h) - s.point(u, v - h)) / (2 * h);
        const Mat3 j3(su, sv, -ray.d);
        if (std::abs(glm::determinant(j3)) < 1e-14) break;
        const Vec3 step = glm::inverse(j3) * (-r);
        u += step.x;
        v += step.y;
        t += step.z;
      }
      if (ok && u >= p.uvMin.x && u <= p.uvMax.x && v >= p.uvMin.y && v <= p.uvMax.y && t > lower)
        best = std::min(best, t);
    }
  return best;
}

}  // namespace

TEST_CASE("parametric interval bounds a function of bounded slope on any rectangle",
          "[parametric]") {
  // Slopes: along u cos(3u)cos(2v) <= 1, along v (2/3)sin(3u)sin(2v) <= 2/3.
  auto f = [](double u, double v) { return std::sin(3 * u) * std::cos(2 * v) / 3; };
  Rng rng(7);
  for (int n = 0; n < 300; ++n) {
    const double u0 = uniform(rng, -3, 3), v0 = uniform(rng, -3, 3);
    const double du = uniform(rng, 1e-3, 2), dv = uniform(rng, 1e-3, 2);
    const double c[2][2] = {{f(u0, v0), f(u0, v0 + dv)}, {f(u0 + du, v0), f(u0 + du, v0 + dv)}};
    double low, high;
    parametricInterval(c, du, dv, 1.0, low, high);
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const double value = f(u0 + du * i / 20, v0 + dv * j / 20);
        REQUIRE(value >= low - 1e-15);
        REQUIRE(value <= high + 1e-15);
      }
  }
  // A corner where the function is undefined bounds nothing.
  const double c[2][2] = {{0.0, std::nan("")}, {0.0, 0.0}};
  double low, high;
  parametricInterval(c, 1, 1, 1, low, high);
  CHECK(low == -kInf);
  CHECK(high == kInf);
}

TEST_CASE("parametric sphere hits at the exact sphere's distances with its normals",
          "[parametric]") {
  for (int depth : {0, 12}) {
    Parametric::Params p = unitSphere();
    p.precomputeDepth = depth;
    p.precompute = {true, true, true};
    const Parametric s(p);
    Rng rng(11 + depth);
    int hits = 0, estimates = 0;
    for (int n = 0; n < 400; ++n) {
      const Ray ray = randomRayAt(rng, AABB(Vec3(-1.0), Vec3(1.0)), 3.0);
      double t0 = 0.0, t1 = 0.0;
      const bool exact = solveDistanceQuadratic(ray.o, ray.d, 1.0, t0, t1);
      Hit h;
      const bool found = s.intersect(ray, h);
      // A graze (a chord shorter than 0.01, or a miss by less than the leaves' size) may
      // go either way: a leaf's box reaches beyond the surface.
      if (exact && (t1 - t0) * glm::length(ray.d) < 0.01) continue;
      const double closest =
          glm::length(ray.o - ray.d * (glm::dot(ray.o, ray.d) / glm::dot(ray.d, ray.d)));
      if (!exact && closest < 1.0 + 0.004) continue;
      INFO("ray " << n << " depth " << depth);
      REQUIRE(found == exact);
      if (!found) continue;
      ++hits;
      if (h.part == 1) {
        // Not refined (a glancing ray): POV-Ray's hit, the entry of a leaf's box, which lies
        // before the surface, by about accuracy / sin(angle) at most.
        ++estimates;
        CHECK(h.t <= t0 + 1e-12);
        CHECK(h.t >= t0 - 0.1);
        continue;
      }
      CHECK(h.t == Approx(t0).epsilon(0).margin(1e-9));
      const SurfaceInfo si = s.surface(ray, h);
      CHECK(std::abs(glm::dot(si.ng, glm::normalize(si.p))) == Approx(1.0).margin(1e-7));
      // (u, v): the angle round y and the angle from the pole.
      Vec2 uv;
      REQUIRE(s.povUV(si, h, uv));
      CHECK(std::cos(uv.y) == Approx(si.p.y).margin(1e-9));
      CHECK(std::cos(uv.x) * std::sin(uv.y) == Approx(si.p.x).margin(1e-9));
      REQUIRE(intersectAgreesWithCrossings(s, ray).empty());
    }
    CHECK(hits > 100);
    CHECK(estimates <= hits / 20);
  }
}

TEST_CASE("parametric sphere crossings are its first one and a ray from the surface leaves it",
          "[parametric]") {
  const Parametric s(unitSphere());
  const Ray through(Vec3(0.1, 0.2, 3.0), Vec3(0.0, 0.0, -1.0));
  CrossingList out;
  s.crossings(through, out);
  // The first crossing only, as POV-Ray's parametric gives CSG.
  REQUIRE(out.items.size() == 1);
  const double z = std::sqrt(1.0 - 0.05);
  CHECK(out.items[0].hit.t == Approx(3.0 - z).margin(1e-9));
  CHECK(out.items[0].entering);
  CHECK_FALSE(out.startsInside);
  // Beyond it (a clip asks again), the far side.
  Hit far;
  REQUIRE(s.intersect(Ray(through.o, through.d, out.items[0].hit.t + 0.01), far));
  CHECK(far.t == Approx(3.0 + z).margin(1e-9));
  // From a point of the surface: outwards nothing, inwards the far side.
  const Vec3 q = glm::normalize(Vec3(0.3, -0.5, 0.7));
  Hit h;
  CHECK_FALSE(s.intersect(Ray(q, q), h));
  REQUIRE(s.intersect(Ray(q, -q), h));
  CHECK(h.t == Approx(2.0).margin(1e-9));
  // Within 4·accuracy of where the ray starts: ignored, as POV-Ray does.
  CHECK_FALSE(s.intersect(Ray(q * 1.002, -q, 0.0, 0.003), h));
}

TEST_CASE("parametric plane patch keeps to its rectangle and its container", "[parametric]") {
  auto p = params([](double u, double) { return u; }, [](double, double v) { return v; },
                  [](double, double) { return 0.25; }, Vec2(-1.0), Vec2(1.0));
  p.container.min = Vec3(-2.0, -0.5, -2.0);  // cuts the patch at y = ±0.5
  p.container.max = Vec3(2.0, 0.5, 2.0);
  const Parametric s(p);
  Hit h;
  REQUIRE(s.intersect(Ray(Vec3(0.3, 0.4, 3.0), Vec3(0.0, 0.0, -2.0)), h));
  CHECK(h.t == Approx(1.375).margin(1e-12));
  const Ray ray(Vec3(0.3, 0.4, 3.0), Vec3(0.0, 0.0, -2.0));
  const SurfaceInfo si = s.surface(ray, h);
  CHECK(std::abs(si.ng.z) == Approx(1.0));
  CHECK(si.uv.x == Approx(0.65));
  CHECK(si.uv.y == Approx(0.7));
  Vec2 uv;
  REQUIRE(s.povUV(si, h, uv));
  CHECK(uv.x == Approx(0.3));
  CHECK(uv.y == Approx(0.4));
  // Beyond the rectangle, and beyond the container.
  CHECK_FALSE(s.intersect(Ray(Vec3(1.2, 0.0, 3.0), Vec3(0.0, 0.0, -1.0)), h));
  CHECK_FALSE(s.intersect(Ray(Vec3(0.0, 0.7, 3.0), Vec3(0.0, 0.0, -1.0)), h));
  // A slanted ray.
  const Ray slant(Vec3(-0.9, 0.1, 2.0), Vec3(0.5, 0.05, -1.0));
  REQUIRE(s.intersect(slant, h));
  CHECK(h.t == Approx(1.75).margin(1e-10));
  CHECK(s.bounds().lo.y == -0.5);
}

TEST_CASE("parametric Moebius strip finds the nearest of every solution", "[parametric]") {
  for (int depth : {0, 10}) {
    Parametric::Params p = mobius();
    p.precomputeDepth = depth;
    p.precompute = {true, true, true};
    const Parametric s(p);
    Rng rng(3 + depth);
    int hits = 0, estimates = 0;
    for (int n = 0; n < 120; ++n) {
      const Ray ray = randomRayAt(rng, AABB(Vec3(-1.3, -1.3, -0.3), Vec3(1.3, 1.3, 0.3)), 2.0);
      double c0 = 0.0, c1 = 0.0;
      // The container's entry, for the guard.
      const Vec3 inv = 1.0 / ray.d;
      const Vec3 a = (Vec3(-2.0) - ray.o) * inv, b = (Vec3(2.0) - ray.o) * inv;
      const Vec3 lo = glm::min(a, b), hi = glm::max(a, b);
      c0 = std::max({lo.x, lo.y, lo.z});
      c1 = std::min({hi.x, hi.y, hi.z});
      REQUIRE(c0 < c1);
      const double lower = c0 + 4.0 * p.accuracy / glm::length(ray.d);
      const double reference = nearestByNewton(s, ray, lower);
      Hit h;
      const bool found = s.intersect(ray, h);
      INFO("ray " << n << " depth " << depth << " reference " << reference);
      if (!found) {
        // Only a graze may be missed: then the reference's hit is at a tangent.
        CHECK(reference == kInf);
        continue;
      }
      ++hits;
      REQUIRE(reference < kInf);
      if (h.part == 1) {  // a glancing ray's leaf entry, before the surface
        ++estimates;
        CHECK(h.t <= reference + 1e-12);
        CHECK(h.t >= reference - 0.1);
      } else {
        CHECK(h.t == Approx(reference).epsilon(0).margin(1e-7));
        CHECK(glm::length(s.point(h.b1, h.b2) - ray.at(h.t)) < 1e-8);
      }
      REQUIRE(crossingsViolation(s, ray,
                                 [&] {
                                   CrossingList cl;
                                   s.crossings(ray, cl);
                                   return cl;
                                 }())
                  .empty());
    }
    CHECK(hits > 30);
    CHECK(estimates <= hits / 10);
  }
}

TEST_CASE("parametric refuses what it cannot search", "[parametric]") {
  auto make = [](std::function<void(Parametric::Params&)> change) {
    Parametric::Params p = unitSphere();
    change(p);
    return Parametric(p);
  };
  CHECK_THROWS_AS(make([](auto& p) { p.functions[1] = nullptr; }), std::invalid_argument);
  CHECK_THROWS_AS(make([](auto& p) { p.uvMax.x = p.uvMin.x; }), std::invalid_argument);
  CHECK_THROWS_AS(make([](auto& p) { p.accuracy = 0.0; }), std::invalid_argument);
  CHECK_THROWS_AS(make([](auto& p) { p.maxGradient = -1.0; }), std::invalid_argument);
  CHECK_THROWS_AS(make([](auto& p) { p.precomputeDepth = 21; }), std::invalid_argument);
  CHECK_THROWS_AS(make([](auto& p) { p.container.max.z = -3.0; }), std::invalid_argument);
}
