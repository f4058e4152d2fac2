#include "shape_checks.h"

#include "../support/sweep_spline_weights.h"
#include "primitives/offset.h"
#include "primitives/sphere_sweep.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

namespace {

using LD = long double;
using S = std::vector<SweepSphere>;

const S kWiggle = {{Vec3(-1, -0.6, 0), 0.1},  {Vec3(-0.6, 0, 0), 0.3},
                   {Vec3(0, 0.4, 0.2), 0.2},  {Vec3(0.6, -0.1, 0), 0.35},
                   {Vec3(1, 0.5, -0.3), 0.1}, {Vec3(1.3, 0.2, 0.4), 0.25}};

// An independent reference in long double: the ball at u of each segment from the
// textbook forms of the splines (Hermite with Catmull-Rom tangents; the B-spline's basis
// functions; linear interpolation), and along a ray the first point of the union of the
// balls: the least entry t0(u) over u, by dense sampling refined by golden-section search.
struct Reference {
  SweepSpline spline;
  S p;

  size_t segments() const { return spline == SweepSpline::Linear ? p.size() - 1 : p.size() - 3; }

  void ball(size_t i, LD u, LD c[3], LD& r) const {
    LD w[4];
    size_t first = i;
    test::sweepSplineWeights(spline, u, w);
    c[0] = c[1] = c[2] = 0;
    r = 0;
    for (size_t k = 0; k < 4; ++k) {
      if (w[k] == 0) continue;
      const SweepSphere& s = p[first + k];
      for (int a = 0; a < 3; ++a) c[a] += w[k] * (LD)s.center[a];
      r += w[k] * (LD)s.radius;
    }
  }

  // Least of f over [0, 1] per segment: 2000 samples, then golden section about the best.
  LD minimise(const std::function<LD(size_t, LD)>& f, size_t& segOut, LD& uOut) const {
    LD best = INFINITY;
    for (size_t i = 0; i < segments(); ++i) {
      const int n = 2000;
      int bk = -1;
      LD bv = INFINITY;
      for (int k = 0; k <= n; ++k) {
        const LD v = f(i, (LD)k / n);
        if (v < bv) {
          bv = v;
          bk = k;
        }
      }
      if (bk < 0) continue;
      LD a = std::max<LD>(0, (LD)(bk - 1) / n), b = std::min<LD>(1, (LD)(bk + 1) / n);
      const LD g = (std::sqrt((LD)5) - 1) / 2;
      for (int it = 0; it < 200; ++it) {
        const LD x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (f(i, x1) < f(i, x2)) b = x2;
        else a = x1;
      }
      for (LD u : {a, (LD)(bk) / n}) {
        const LD v = f(i, u);
        if (v < best) {
          best = v;
          segOut = i;
          uOut = u;
        }
      }
    }
    return best;
  }

  // The first entry along o + t·d (d unit, o outside): min t0(u).
  LD firstHit(const Vec3& o, const Vec3& d, size_t& seg, LD& u) const {
    return minimise(
        [&](size_t i, LD x) -> LD {
          LD c[3], r;
          ball(i, x, c, r);
          LD m = 0, qq = 0;
          for (int a = 0; a < 3; ++a) {
            const LD q = c[a] - (LD)o[a];
            m += q * (LD)d[a];
            qq += q * q;
          }
          const LD D = r * r - (qq - m * m);
          return D < 0 ? INFINITY : m - std::sqrt(D);
        },
        seg, u);
  }

  // min over u of |p − c(u)| − |r(u)|: negative inside.
  LD gauge(const Vec3& p) const {
    size_t seg;
    LD u;
    return minimise(
        [&](size_t i, LD x) -> LD {
          LD c[3], r;
          ball(i, x, c, r);
          LD qq = 0;
          for (int a = 0; a < 3; ++a) qq += (c[a] - (LD)p[a]) * (c[a] - (LD)p[a]);
          return std::sqrt(qq) - std::abs(r);
        },
        seg, u);
  }
};

void checkAgainstReference(SweepSpline spline, const S& spheres, uint64_t seed) {
  const SphereSweep sweep(spline, spheres);
  const Reference ref{spline, spheres};
  Rng rng(seed);
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray = randomRayAt(rng, sweep.bounds(), 2.0);
    const double len = glm::length(ray.d);
    const Vec3 d = ray.d / len;
    size_t seg = 0;
    LD u = 0;
    const LD tRef = ref.firstHit(ray.o, d, seg, u);
    Hit h;
    const bool hit = sweep.intersect(ray, h);
    INFO("ray " << i);
    REQUIRE(intersectAgreesWithCrossings(sweep, ray) == "");
    if (!std::isfinite((double)tRef)) {
      // A miss; a grazing touch within the reference's sampling is excused.
      if (hit) CHECK(ref.gauge(ray.at(h.t)) > -1e-9);
      continue;
    }
    REQUIRE(hit);
    ++hits;
    CHECK_THAT(h.t * len, WithinAbs((double)tRef, 1e-12));
    // The normal: the reference ball's outward direction at the hit.
    const SurfaceInfo si = sweep.surface(ray, h);
    LD c[3], r;
    ref.ball(seg, u, c, r);
    Vec3 n((double)((LD)si.p.x - c[0]), (double)((LD)si.p.y - c[1]), (double)((LD)si.p.z - c[2]));
    n = glm::normalize(n);
    CHECK(glm::dot(n, si.ng) > 1.0 - 1e-12);
  }
  CHECK(hits > 100);
}

}  // namespace

TEST_CASE("sphere-sweep: a linear capsule is a cylinder with round ends", "[primitives][sweep]") {
  const SphereSweep s(SweepSpline::Linear, {{Vec3(0, 0, 0), 0.5}, {Vec3(1, 0, 0), 0.5}});
  Hit h;
  REQUIRE(s.intersect(Ray(Vec3(0.5, 5, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(4.5, 1e-15));
  CHECK(s.surface(Ray(Vec3(0.5, 5, 0), Vec3(0, -1, 0)), h).ng == Vec3(0, 1, 0));
  CrossingList cl;
  s.crossings(Ray(Vec3(-5, 0, 0), Vec3(1, 0, 0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(4.5, 1e-15));
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(6.5, 1e-15));
  CHECK(s.inside(Vec3(0.5, 0.49, 0)));
  CHECK_FALSE(s.inside(Vec3(0.5, 0.51, 0)));
  CHECK(s.inside(Vec3(1.3, 0.3, 0.2)));  // in the end ball: 0.3² + 0.3² + 0.2² < 0.25
}

TEST_CASE("sphere-sweep: a linear segment of two radii is the tangent cone's frustum",
          "[primitives][sweep]") {
  // Balls r0 = 1 at the origin and r1 = 0.5 at x = 3: the tangent cone's apex lies at
  // A = r0·L/(r0 − r1) = 6, its half-angle α has sin α = r0/A, and at x = 1.5 its radius is
  // (A − 1.5)·tan α.
  const SphereSweep s(SweepSpline::Linear, {{Vec3(0, 0, 0), 1.0}, {Vec3(3, 0, 0), 0.5}});
  const double A = 6.0, sinA = 1.0 / 6.0, tanA = sinA / std::sqrt(1 - sinA * sinA);
  const double R = (A - 1.5) * tanA;
  Hit h;
  const Ray down(Vec3(1.5, 4, 0), Vec3(0, -2, 0));
  REQUIRE(s.intersect(down, h));
  CHECK_THAT(h.t * 2, WithinAbs(4 - R, 1e-14));
  // The normal tilts away from the axis by α towards the smaller ball.
  const Vec3 n = s.surface(down, h).ng;
  CHECK_THAT(n.x, WithinAbs(sinA, 1e-14));
  CHECK_THAT(n.y, WithinAbs(std::sqrt(1 - sinA * sinA), 1e-14));
  CHECK(s.inside(Vec3(1.5, R - 1e-9, 0)));
  CHECK_FALSE(s.inside(Vec3(1.5, R + 1e-9, 0)));
  // Past the tangent circle on the big ball the surface is the ball's: x = −0.5 on it.
  REQUIRE(s.intersect(Ray(Vec3(-0.5, 4, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(4 - std::sqrt(0.75), 1e-14));
}

TEST_CASE("sphere-sweep: a ball within its neighbour adds no cone", "[primitives][sweep]") {
  const SphereSweep s(SweepSpline::Linear, {{Vec3(0, 0, 0), 1.0}, {Vec3(0.3, 0, 0), 0.5}});
  Hit h;
  REQUIRE(s.intersect(Ray(Vec3(0.3, 5, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(5 - std::sqrt(1 - 0.09), 1e-14));
  CHECK(s.bounds().hi.x == 1.0);
}

TEST_CASE("sphere-sweep: splines through evenly spaced points on a line are capsules",
          "[primitives][sweep]") {
  // Catmull-Rom and B-spline both reproduce a straight, evenly parametrised line: the one
  // segment runs from the second point to the third with the radius constant.
  const S line = {
      {Vec3(-1, 0, 0), 0.5}, {Vec3(0, 0, 0), 0.5}, {Vec3(1, 0, 0), 0.5}, {Vec3(2, 0, 0), 0.5}};
  for (SweepSpline sp : {SweepSpline::Cubic, SweepSpline::BSpline}) {
    const SphereSweep s(sp, line);
    CHECK(s.segments() == 1);
    CrossingList cl;
    s.crossings(Ray(Vec3(-5, 0, 0), Vec3(1, 0, 0)), cl);
    REQUIRE(cl.items.size() == 2);
    CHECK_THAT(cl.items[0].hit.t, WithinAbs(4.5, 1e-14));
    CHECK_THAT(cl.items[1].hit.t, WithinAbs(6.5, 1e-14));
    Hit h;
    REQUIRE(s.intersect(Ray(Vec3(0.25, 5, 0), Vec3(0, -1, 0)), h));
    CHECK_THAT(h.t, WithinAbs(4.5, 1e-14));
    CHECK_FALSE(s.intersect(Ray(Vec3(-0.75, 5, 0), Vec3(0, -1, 0)), h));  // before P1's ball
  }
}

TEST_CASE("sphere-sweep: first hits and normals against a long-double reference",
          "[primitives][sweep]") {
  checkAgainstReference(SweepSpline::Linear, kWiggle, 41);
  checkAgainstReference(SweepSpline::Cubic, kWiggle, 42);
  checkAgainstReference(SweepSpline::BSpline, kWiggle, 43);
}

TEST_CASE("sphere-sweep: inside agrees with the union of the balls and with the crossings",
          "[primitives][sweep]") {
  for (SweepSpline sp : {SweepSpline::Linear, SweepSpline::Cubic, SweepSpline::BSpline}) {
    const SphereSweep s(sp, kWiggle);
    const Reference ref{sp, kWiggle};
    Rng rng(44);
    const AABB b = s.bounds();
    int in = 0;
    for (int i = 0; i < 400; ++i) {
      const Vec3 p = randomInBox(rng, b.lo, b.hi);
      const LD g = ref.gauge(p);
      if (std::abs((double)g) < 1e-9) continue;
      CHECK(s.inside(p) == (g < 0));
      in += g < 0;
    }
    CHECK(in > 20);
    // Between consecutive crossings the inside test alternates as the crossings say.
    for (int i = 0; i < 200; ++i) {
      const Ray ray = randomRayAt(rng, b, 2.0);
      CrossingList cl;
      s.crossings(ray, cl);
      REQUIRE(crossingsViolation(s, ray, cl) == "");
      for (size_t k = 0; k + 1 < cl.items.size(); ++k) {
        const double t0 = cl.items[k].hit.t, t1 = cl.items[k + 1].hit.t;
        if (t1 - t0 < 1e-6) continue;
        CHECK(s.inside(ray.at(0.5 * (t0 + t1))) == cl.items[k].entering);
      }
    }
  }
}

TEST_CASE("sphere-sweep: the box holds every ball of the path", "[primitives][sweep]") {
  for (SweepSpline sp : {SweepSpline::Linear, SweepSpline::Cubic, SweepSpline::BSpline}) {
    const SphereSweep s(sp, kWiggle);
    const AABB b = s.bounds();
    for (size_t i = 0; i < s.segments(); ++i)
      for (int k = 0; k <= 100; ++k) {
        const double u = k / 100.0, r = std::abs(s.radiusAt(i, u));
        const Vec3 c = s.centerAt(i, u);
        CHECK(glm::all(glm::lessThanEqual(b.lo, c - Vec3(r))));
        CHECK(glm::all(glm::lessThanEqual(c + Vec3(r), b.hi)));
      }
  }
}

TEST_CASE("sphere-sweep: POV-Ray's counts and radii are checked", "[primitives][sweep]") {
  CHECK_THROWS(SphereSweep(SweepSpline::Linear, {{Vec3(0), 1}}));
  CHECK_THROWS(SphereSweep(SweepSpline::Cubic, {{Vec3(0), 1}, {Vec3(1), 1}, {Vec3(2), 1}}));
  CHECK_THROWS(SphereSweep(SweepSpline::BSpline, {{Vec3(0), 1}, {Vec3(1), 1}, {Vec3(2), 1}}));
  CHECK_THROWS(SphereSweep(SweepSpline::Linear, {{Vec3(0), 1}, {Vec3(1), -1}}));
  CHECK_THROWS(SphereSweep(SweepSpline::Linear, {{Vec3(0), 0}, {Vec3(1), 0}}));
  CHECK_NOTHROW(SphereSweep(SweepSpline::Linear, {{Vec3(0), 0}, {Vec3(1), 0.5}}));
}

TEST_CASE("sphere-sweep: a hit whose ball is off the contact by 1e-6 is moved onto the surface",
          "[primitives][sweep][offset]") {
  // A cubic sweep's hit (the registry's sample, found by 800,000 secondary rays) came with
  // u = 0.97269766, the ball touching the surface there being at u = 0.97269693: the point
  // lay inside the surface by more than its error bound, and the mirror ray leaving it met
  // the surface again at t = 1.8e-13.
  const SphereSweep sweep(SweepSpline::Cubic, {{Vec3(-1, -0.6, 0), 0.1},
                                               {Vec3(-0.6, 0, 0), 0.3},
                                               {Vec3(0, 0.4, 0.2), 0.2},
                                               {Vec3(0.6, -0.1, 0), 0.35},
                                               {Vec3(1, 0.5, -0.3), 0.1}});
  const Vec3 p(0.7510921994581683, 0.02365835324264709, 0.29088658165785963);
  const Vec3 w(0.51523936691213401, 0.17000955248703997, 0.8400149682280309);
  const double uFound = 0.97269766018840431;
  // The gauge: least over u of |q − c(u)| − r(u) near the hit, sampled finely.
  auto gauge = [&](const Vec3& q) {
    double best = INFINITY;
    for (int k = -20000; k <= 20000; ++k) {
      const double u = std::clamp(uFound + k * 1e-10, 0.0, 1.0);
      best = std::min(best, glm::length(q - sweep.centerAt(1, u)) - sweep.radiusAt(1, u));
    }
    return best;
  };
  REQUIRE(gauge(p) < -1e-13);  // the point as the hit had it: inside the surface
  const Ray in(p - w, w);      // a ray whose hit at t = 1 is that point, with that u
  Hit h;
  h.t = 1.0;
  h.shape = &sweep;
  h.part = 1;
  h.b1 = uFound;
  const SurfaceInfo si = sweep.surface(in, h);
  CHECK(std::abs(sweep.contactParameter(1, p, uFound) - 0.972696929) < 1e-8);
  CHECK(std::abs(gauge(si.p)) < 1e-15);
  CHECK(glm::dot(w, si.ng) > 0.9);
  const Ray out(offsetRayOrigin(si.p, si.pError, si.ng, w), w);
  Hit again;
  CHECK_FALSE(sweep.intersect(out, again));
}
