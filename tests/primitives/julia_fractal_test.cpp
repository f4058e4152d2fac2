// julia-fractal against an independent evaluation: the escape test written with
// std::complex duplex pairs (hypercomplex) and the quaternion product (quaternions), points
// along rays iterated to find where the test changes, the hit held to that place; the
// inside test; POV-Ray's normal against the gradient of |q_N|²; POV-Ray's errors.
#include "primitives/julia_fractal.h"
#include "shape_checks.h"

#include <catch2/catch.hpp>

#include <complex>
#include <functional>
#include <tuple>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

using C = std::complex<double>;

Vec4 quaternionProduct(const Vec4& a, const Vec4& b) {  // (x; y, z, w) = real; i, j, k
  const Vec3 u(a.y, a.z, a.w), v(b.y, b.z, b.w);
  const Vec3 im = a.x * v + b.x * u + glm::cross(u, v);
  return {a.x * b.x - glm::dot(u, v), im.x, im.y, im.z};
}

// A hypercomplex number as its duplex pair (x − w) + i(y + z), (x + w) + i(y − z).
Vec4 hypercomplexMap(const Vec4& q, const std::function<C(C)>& f) {
  const C a = f(C(q.x - q.w, q.y + q.z)), b = f(C(q.x + q.w, q.y - q.z));
  return {0.5 * (a.real() + b.real()), 0.5 * (a.imag() + b.imag()), 0.5 * (a.imag() - b.imag()),
          0.5 * (b.real() - a.real())};
}

struct Reference {
  JuliaParams p;
  std::function<Vec4(const Vec4&)> f;  // without + c
  double exitValue;

  Vec4 at(const Vec3& x) const {
    const Vec4 s = p.slice / glm::length(p.slice);
    return {x.x, x.y, x.z, (p.distance - s.x * x.x - s.y * x.y - s.z * x.z) / s.w};
  }
  // The orbit's last point, or none when it escapes.
  bool inside(const Vec3& x, Vec4* last = nullptr) const {
    Vec4 q = at(x);
    for (int i = 0; i < p.maxIteration; ++i) {
      if (glm::dot(q, q) > exitValue) return false;
      q = f(q) + p.c;
    }
    if (last) *last = q;
    return true;
  }
};

Reference quaternionSqr() {
  JuliaParams p;
  p.c = Vec4(-0.083, 0.0, -0.83, -0.025);
  p.maxIteration = 8;
  p.precision = 40;
  const double r = std::min(2.0, 1.0 + glm::length(p.c) + 1e-7);
  return {p, [](const Vec4& q) { return quaternionProduct(q, q); }, r * r + 1e-7};
}

Reference quaternionCube() {
  JuliaParams p;
  p.c = Vec4(-0.03, 0.5, -0.2, -0.5);
  p.function = JuliaFunction::Cube;
  p.maxIteration = 8;
  p.precision = 40;
  p.slice = Vec4(0.2, 0.0, 0.3, 1.0);
  p.distance = 0.1;
  const double r = std::min(2.0, 1.0 + glm::length(p.c) + 1e-7);
  return {p, [](const Vec4& q) { return quaternionProduct(q, quaternionProduct(q, q)); },
          r * r + 1e-7};
}

Reference hypercomplex(JuliaFunction fn, const std::function<C(C)>& f, Vec4 c, int n) {
  JuliaParams p;
  p.c = c;
  p.algebra = JuliaAlgebra::Hypercomplex;
  p.function = fn;
  p.maxIteration = n;
  p.precision = 40;
  return {p, [f](const Vec4& q) { return hypercomplexMap(q, f); }, 16.0};
}

// The first t along the ray (from its sphere entry, in steps of 1e-3) where the reference
// test changes, bisected to 1e-12; -1 when none.
double firstChange(const Reference& ref, const Ray& ray, double radius) {
  const Vec3 d = glm::normalize(ray.d);
  const double b = glm::dot(ray.o, d), c = glm::dot(ray.o, ray.o) - radius * radius;
  const double disc = b * b - c;
  if (disc <= 0.0) return -1.0;
  double s = std::max(-b - std::sqrt(disc), 0.0);
  const double end = -b + std::sqrt(disc);
  const bool start = ref.inside(ray.o + s * d);
  for (; s < end; s += 1e-3) {
    if (ref.inside(ray.o + (s + 1e-3) * d) == start) continue;
    double lo = s, hi = s + 1e-3;
    while (hi - lo > 1e-12) {
      const double mid = 0.5 * (lo + hi);
      (ref.inside(ray.o + mid * d) == start ? lo : hi) = mid;
    }
    return hi / glm::length(ray.d);
  }
  return -1.0;
}

// Rays from outside towards points near the middle: each hit lies where the reference's
// test changes (inside at the hit, outside 3e-7 before it), and is the first change the
// reference finds unless the march (or the reference's sampling) stepped over a thin part.
void requireHitsWhereTheTestChanges(const Reference& ref) {
  JuliaFractal shape(ref.p);
  Rng rng(41);
  int hits = 0, first = 0, missed = 0;
  const int rays = 200;
  for (int i = 0; i < rays; ++i) {
    const Vec3 o = 3.0 * randomUnit(rng);
    const Vec3 target = randomInBox(rng, Vec3(-0.4), Vec3(0.4));
    const Ray ray(o, (target - o) * uniform(rng, 0.5, 2.0));
    const double expected = firstChange(ref, ray, shape.map().radius());
    Hit h;
    if (!shape.intersect(ray, h)) {
      missed += expected > 0.0;
      continue;
    }
    ++hits;
    const Vec3 d = glm::normalize(ray.d);
    CHECK(h.part == 1);  // entering: the rays start outside the bounding sphere
    CHECK(ref.inside(ray.at(h.t)));
    CHECK_FALSE(ref.inside(ray.at(h.t) - 3e-7 * d));
    if (expected > 0.0 && std::abs(h.t - expected) * glm::length(ray.d) <= 2e-7) ++first;
  }
  INFO(hits << " hits of " << rays << " rays, " << first << " at the first change, " << missed
            << " missed");
  CHECK(hits > 50);
  CHECK(first >= hits * 9 / 10);
  CHECK(missed <= rays / 20);
}

void requireSameInside(const Reference& ref) {
  JuliaFractal shape(ref.p);
  Rng rng(7);
  int in = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p = randomInBox(rng, Vec3(-1.5), Vec3(1.5));
    const bool expected = ref.inside(p);
    in += expected;
    CHECK(shape.inside(p) == expected);
  }
  CHECK(in > 200);
}

}  // namespace

TEST_CASE("julia-fractal quaternion sqr: hits where the escape test changes",
          "[primitives][julia]") {
  requireHitsWhereTheTestChanges(quaternionSqr());
  requireSameInside(quaternionSqr());
}

TEST_CASE("julia-fractal quaternion cube on a slice: hits where the escape test changes",
          "[primitives][julia]") {
  requireHitsWhereTheTestChanges(quaternionCube());
  requireSameInside(quaternionCube());
}

TEST_CASE("julia-fractal hypercomplex sqr and reciprocal: hits where the test changes",
          "[primitives][julia]") {
  const Vec4 c(0.2, 0.1, 0.59, -0.2);
  requireHitsWhereTheTestChanges(hypercomplex(
      JuliaFunction::Sqr, [](C z) { return z * z; }, c, 7));
  requireSameInside(hypercomplex(
      JuliaFunction::Sqr, [](C z) { return z * z; }, c, 7));
  // POV-Ray's cube iterates q² (its own step aside): the same set.
  requireSameInside(hypercomplex(
      JuliaFunction::Cube, [](C z) { return z * z; }, c, 7));
  const Reference reciprocal = hypercomplex(
      JuliaFunction::Reciprocal, [](C z) { return 1.0 / z; }, Vec4(-0.6, 0.2, 0.1, 0.1), 6);
  requireSameInside(reciprocal);
}

TEST_CASE("julia-fractal hypercomplex functions: POV-Ray 3.7's inside test from (x, y, y)",
          "[primitives][julia]") {
  const Vec4 c(0.4, 0.3, 0.1, 0.05);
  const std::pair<JuliaFunction, std::function<C(C)>> functions[] = {
      {JuliaFunction::Ln, [](C z) { return std::log(z); }},
      {JuliaFunction::Sin, [](C z) { return std::sin(z); }},
      {JuliaFunction::Cos, [](C z) { return std::cos(z); }},
      {JuliaFunction::Sinh, [](C z) { return std::sinh(z); }},
      {JuliaFunction::Tan, [](C z) { return std::tan(z); }},
      {JuliaFunction::Tanh, [](C z) { return std::tanh(z); }},
      {JuliaFunction::Asinh, [](C z) { return std::log(z + std::sqrt(z * z + 1.0)); }},
      {JuliaFunction::Acosh, [](C z) { return std::log(z + std::sqrt(z * z - 1.0)); }},
      {JuliaFunction::Atanh, [](C z) { return 0.5 * std::log((1.0 + z) / (1.0 - z)); }}};
  // exp and cosh with a c whose real fixed point attracts (their sets are empty at c).
  std::vector<std::tuple<JuliaFunction, std::function<C(C)>, Vec4>> cases = {
      {JuliaFunction::Exp, [](C z) { return std::exp(z); }, Vec4(-2.0, 0.1, 0.05, 0.0)},
      {JuliaFunction::Cosh, [](C z) { return std::cosh(z); }, Vec4(-1.5, 0.1, 0.05, 0.0)}};
  for (const auto& [fn, f] : functions) cases.emplace_back(fn, f, c);
  Rng rng(3);
  for (const auto& [fn, f, cc] : cases) {
    const Reference ref = hypercomplex(fn, f, cc, 6);
    JuliaFractal shape(ref.p);
    int agree = 0, in = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      const Vec3 p = randomInBox(rng, Vec3(-3.0), Vec3(3.0));
      const bool expected = ref.inside(Vec3(p.x, p.y, p.y));
      in += expected;
      agree += shape.inside(p) == expected;
    }
    INFO("function " << static_cast<int>(fn) << ": " << in << " inside");
    // std::complex's branch cuts may differ from POV-Ray's formulas on the cut lines only.
    CHECK(agree >= n - 2);
    CHECK(in > 20);
  }
}

TEST_CASE("julia-fractal normals: the gradient of |q_N|² where the slice is w = 0",
          "[primitives][julia]") {
  for (const Reference& ref : {quaternionSqr(), hypercomplex(
                                                    JuliaFunction::Sqr, [](C z) { return z * z; },
                                                    Vec4(0.2, 0.1, 0.59, -0.2), 7)}) {
    JuliaFractal shape(ref.p);
    Rng rng(11);
    int checked = 0;
    for (int i = 0; i < 300 && checked < 40; ++i) {
      const Vec3 o = 3.0 * randomUnit(rng);
      const Ray ray(o, randomInBox(rng, Vec3(-0.3), Vec3(0.3)) - o);
      Hit h;
      if (!shape.intersect(ray, h)) continue;
      const Vec3 p = ray.at(h.t);
      auto potential = [&](const Vec3& x) {
        Vec4 q(0.0);
        REQUIRE(ref.inside(x, &q));
        return glm::dot(q, q);
      };
      const double e = 1e-8;
      Vec3 g;
      bool allInside = true;
      for (int k = 0; k < 3; ++k) {
        Vec3 a = p, b = p;
        a[k] -= e;
        b[k] += e;
        allInside &= ref.inside(a) && ref.inside(b);
        if (!allInside) break;
        g[k] = (potential(b) - potential(a)) / (2.0 * e);
      }
      if (!allInside) continue;
      ++checked;
      const SurfaceInfo s = shape.surface(ray, h);
      const Vec3 expected = glm::normalize(glm::dot(g, ray.d) < 0.0 ? g : -g);
      CHECK(glm::dot(s.ns, expected) > 0.9999);
      CHECK(glm::dot(s.ng, ray.d) < 0.0);  // an entering hit faces the ray
    }
    CHECK(checked >= 20);
  }
}

TEST_CASE("julia-fractal bounds: POV-Ray's sphere of radius min(2, 1 + |c|) or 4",
          "[primitives][julia]") {
  JuliaParams p;
  p.c = Vec4(0.1, 0.2, 0.0, 0.2);
  CHECK(JuliaFractal(p).map().radius() == Approx(1.3 + 1e-7));
  p.c = Vec4(1.0, 1.0, 0.0, 0.0);
  CHECK(JuliaFractal(p).map().radius() == 2.0);
  p.algebra = JuliaAlgebra::Hypercomplex;
  CHECK(JuliaFractal(p).map().radius() == 4.0);
  CHECK(JuliaFractal(p).bounds().hi == Vec3(4.0));
}

TEST_CASE("julia-fractal refuses what POV-Ray refuses", "[primitives][julia]") {
  JuliaParams p;
  p.function = JuliaFunction::Exp;
  CHECK_THROWS_WITH(JuliaFractal(p), Catch::Contains("sqr and cube only"));
  p = JuliaParams{};
  p.slice = Vec4(1.0, 0.0, 0.0, 0.0);
  CHECK_THROWS_WITH(JuliaFractal(p), Catch::Contains("t component is zero"));
  p.slice = Vec4(0.0);
  CHECK_THROWS_WITH(JuliaFractal(p), Catch::Contains("zero"));
}
