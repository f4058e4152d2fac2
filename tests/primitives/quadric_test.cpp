// <quadric>: hits against closed forms (a sphere, an ellipsoid's box, a plane, a cylinder
// and a cone written as quadrics), the sign rules of the whole line (a > 0, a < 0, linear,
// constant), and a ray from far away against a long-double reference.
#include "primitives/quadric.h"
#include "primitives/plane.h"
#include "primitives/sphere.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace lucent;

namespace {

QuadricCoefficients sphereQ(double r) { return {Vec3(1.0), Vec3(0.0), Vec3(0.0), -r * r}; }

std::vector<Crossing> crossingsOf(const Shape& s, const Ray& ray, bool& startsInside) {
  CrossingList list;
  s.crossings(ray, list);
  startsInside = list.startsInside;
  return list.items;
}

}  // namespace

TEST_CASE("quadric: x² + y² + z² − r² is the sphere, hit for hit", "[primitives][quadric]") {
  const Quadric q(sphereQ(1.5));
  const Sphere s(Vec3(0.0), 1.5);
  uint32_t seed = 7;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0 * 2.0 - 1.0;
  };
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o(4 * next(), 4 * next(), 4 * next());
    const Vec3 target(1.2 * next(), 1.2 * next(), 1.2 * next());
    const Ray ray(o, glm::normalize(target - o));
    Hit hq, hs;
    const bool a = q.intersect(ray, hq), b = s.intersect(ray, hs);
    REQUIRE(a == b);
    if (!a) continue;
    ++hits;
    CHECK(hq.t == Approx(hs.t).margin(1e-13));
    const Vec3 nq = q.surface(ray, hq).ng, ns = s.surface(ray, hs).ng;
    CHECK(glm::length(nq - ns) < 1e-12);
  }
  CHECK(hits > 500);
}

TEST_CASE("quadric: a cylinder along an axis is bounded across it", "[primitives][quadric]") {
  const double inf = std::numeric_limits<double>::infinity();
  // x² + y² < 1, no term in z: the column |x|, |y| <= 1.
  AABB b = Quadric({Vec3(1, 1, 0), Vec3(0.0), Vec3(0.0), -1.0}).bounds();
  CHECK(b.lo.x == Approx(-1.0).margin(1e-8));
  CHECK(b.hi.y == Approx(1.0).margin(1e-8));
  CHECK(b.hi.x >= 1.0);
  CHECK(b.lo.z == -inf);
  CHECK(b.hi.z == inf);
  // (y − 1)² / 4 + (z + 2)² < 1 written out, along x: y in [-1, 3], z in [-3, -1].
  QuadricCoefficients c{Vec3(0.0, 0.25, 1.0), Vec3(0.0), Vec3(0.0, -0.5, 4.0), 0.25 + 4.0 - 1.0};
  b = Quadric(c).bounds();
  CHECK(b.lo.y == Approx(-1.0).margin(1e-8));
  CHECK(b.hi.y == Approx(3.0).margin(1e-8));
  CHECK(b.lo.z == Approx(-3.0).margin(1e-8));
  CHECK(b.hi.z == Approx(-1.0).margin(1e-8));
  CHECK(b.lo.x == -inf);
  // A hyperbolic cylinder (x² − y² < 1) is bounded nowhere.
  b = Quadric({Vec3(1, -1, 0), Vec3(0.0), Vec3(0.0), -1.0}).bounds();
  CHECK_FALSE(std::isfinite(b.hi.x));
  CHECK_FALSE(std::isfinite(b.hi.y));
}

TEST_CASE("quadric: an ellipsoid's box is exact", "[primitives][quadric]") {
  // (x−1)²/4 + (y+2)² + (z−0.5)²/9 < 1, written out.
  QuadricCoefficients c{Vec3(0.25, 1.0, 1.0 / 9.0), Vec3(0.0), Vec3(-0.5, 4.0, -1.0 / 9.0), 0.0};
  c.constant = 0.25 + 4.0 + 0.25 / 9.0 - 1.0;
  const Quadric q(c);
  const AABB b = q.bounds();
  CHECK(b.lo.x == Approx(-1.0).margin(1e-8));
  CHECK(b.hi.x == Approx(3.0).margin(1e-8));
  CHECK(b.lo.y == Approx(-3.0).margin(1e-8));
  CHECK(b.hi.y == Approx(-1.0).margin(1e-8));
  CHECK(b.lo.z == Approx(-2.5).margin(1e-8));
  CHECK(b.hi.z == Approx(3.5).margin(1e-8));
  // Never tighter than the ellipsoid: its extreme points are inside the box.
  CHECK(b.hi.x >= 3.0);
  CHECK(b.lo.z <= -2.5);
  // A tilted ellipsoid (an xy term): its box from the inverse matrix, checked by sampling.
  const Quadric tilted({Vec3(1.0, 2.0, 1.0), Vec3(1.2, 0.0, 0.0), Vec3(0.0), -1.0});
  const AABB tb = tilted.bounds();
  REQUIRE(tb.isBounded());
  double maxX = 0.0;
  for (int i = 0; i <= 3600; ++i) {
    // Points on the ellipse in the z = 0 plane, by bisection along each direction.
    const double a = 2 * kPi * i / 3600;
    const Vec3 d(std::cos(a), std::sin(a), 0.0);
    double lo = 0.0, hi = 10.0;
    for (int k = 0; k < 80; ++k) {
      const double mid = 0.5 * (lo + hi);
      (tilted.value(mid * d) < 0.0 ? lo : hi) = mid;
    }
    maxX = std::max(maxX, lo * d.x);
  }
  CHECK(tb.hi.x >= maxX);
  CHECK(tb.hi.x == Approx(maxX).epsilon(1e-5));  // the densest sample is within 1e-5
}

TEST_CASE("quadric: a cylinder written as a quadric, along and across its axis",
          "[primitives][quadric]") {
  const Quadric cyl({Vec3(1, 0, 1), Vec3(0), Vec3(0), -1});
  bool inside;
  // Along the axis inside: no crossing, inside all along (a = 0, h = 0, c < 0).
  CHECK(crossingsOf(cyl, Ray(Vec3(0.3, -5, 0.2), Vec3(0, 1, 0)), inside).empty());
  CHECK(inside);
  // Along the axis outside: never inside.
  CHECK(crossingsOf(cyl, Ray(Vec3(2, -5, 0), Vec3(0, 1, 0)), inside).empty());
  CHECK_FALSE(inside);
  // Across: enters at x = -1, leaves at x = 1.
  auto c = crossingsOf(cyl, Ray(Vec3(-3, 7, 0), Vec3(1, 0, 0)), inside);
  CHECK_FALSE(inside);
  REQUIRE(c.size() == 2);
  CHECK(c[0].entering);
  CHECK(c[0].hit.t == Approx(2.0).margin(1e-14));
  CHECK_FALSE(c[1].entering);
  CHECK(c[1].hit.t == Approx(4.0).margin(1e-14));
  // A tangent line touches without crossing.
  CHECK(crossingsOf(cyl, Ray(Vec3(-3, 0, 1), Vec3(1, 0, 0)), inside).empty());
}

TEST_CASE("quadric: a double cone x² + z² − y² and its apex", "[primitives][quadric]") {
  const Quadric cone({Vec3(1, -1, 1), Vec3(0), Vec3(0), 0});
  bool inside;
  // Along the axis: inside (Q = −y² < 0) except at the apex, where the line only touches.
  auto c = crossingsOf(cone, Ray(Vec3(0, -3, 0), Vec3(0, 1, 0)), inside);
  CHECK(inside);
  CHECK(c.empty());
  // Across below the apex at y = -1: a < 0 is not the case here (a = 1): crosses at ±1.
  c = crossingsOf(cone, Ray(Vec3(-3, -1, 0), Vec3(1, 0, 0)), inside);
  REQUIRE(c.size() == 2);
  CHECK_FALSE(inside);
  CHECK(c[0].entering);
  CHECK(c[0].hit.t == Approx(2.0).margin(1e-14));
  // A line of slope 2 through the axis at y = 0.5 (a = 1 − 4 < 0): inside at both ends,
  // out between the two crossings.
  const Vec3 d = glm::normalize(Vec3(1, 2, 0));
  c = crossingsOf(cone, Ray(Vec3(-1, -1.5, 0), d), inside);
  CHECK(inside);
  REQUIRE(c.size() == 2);
  CHECK_FALSE(c[0].entering);
  CHECK(c[1].entering);
  // The normal at a side point is the gradient (x, −y, z)·2, normalised; at the apex, +x.
  Hit h;
  REQUIRE(cone.intersect(Ray(Vec3(-3, -1, 0), Vec3(1, 0, 0)), h));
  CHECK(glm::length(cone.surface(Ray(Vec3(-3, -1, 0), Vec3(1, 0, 0)), h).ng -
                    glm::normalize(Vec3(-1, 1, 0))) < 1e-12);
  CHECK(cone.gradient(Vec3(0.0)) == Vec3(0.0));
  h.t = 3.0;
  CHECK(cone.surface(Ray(Vec3(0, -3, 0), Vec3(0, 1, 0)), h).ng == Vec3(1, 0, 0));
}

TEST_CASE("quadric: a plane written as a quadric is the plane", "[primitives][quadric]") {
  const Quadric q({Vec3(0), Vec3(0), Vec3(0, 2, 0), -1});  // 2y − 1 < 0: below y = 0.5
  const Plane p(Vec3(0, 1, 0), 0.5);
  for (double a : {0.1, 0.7, 1.3, 2.9}) {
    const Ray ray(Vec3(1, 3, -2), glm::normalize(Vec3(std::cos(a), -1.0, std::sin(a))));
    Hit hq, hp;
    REQUIRE(q.intersect(ray, hq));
    REQUIRE(p.intersect(ray, hp));
    CHECK(hq.t == Approx(hp.t).margin(1e-14));
    CHECK(q.surface(ray, hq).ng == Vec3(0, 1, 0));
    bool inside;
    auto c = crossingsOf(q, ray, inside);
    CHECK_FALSE(inside);
    REQUIRE(c.size() == 1);
    CHECK(c[0].entering);
  }
  // Parallel to it: no crossing, on the side it starts.
  bool inside;
  CHECK(crossingsOf(q, Ray(Vec3(0, 0, 0), Vec3(1, 0, 0)), inside).empty());
  CHECK(inside);
  CHECK(q.bounds().lo.x == -kInf);
}

TEST_CASE("quadric: a ray from 1e6 away hits an off-centre ellipsoid to full precision",
          "[primitives][quadric]") {
  // 4(x − 3)² + y² + (z + 1)² < 1.
  const QuadricCoefficients c{Vec3(4, 1, 1), Vec3(0), Vec3(-24, 0, 2), 36.0 + 1.0 - 1.0};
  const Quadric q(c);
  for (double k : {0.0, 0.3, 0.9}) {
    const Vec3 target(3.0, 0.5 * k, -1.0 + 0.2 * k);
    const Vec3 o = target + Vec3(1e6, 2e5, -3e5);
    const Vec3 d = glm::normalize(target - o);
    Hit h;
    REQUIRE(q.intersect(Ray(o, d), h));
    // Long-double reference: Q along the ray is a t² + 2h t + c.
    using L = long double;
    const L ox = o.x - 3.0L, oy = o.y, oz = o.z + 1.0L;
    const L a = 4 * (L)d.x * d.x + (L)d.y * d.y + (L)d.z * d.z;
    const L hh = 4 * ox * d.x + oy * d.y + oz * d.z;
    const L cc = 4 * ox * ox + oy * oy + oz * oz - 1;
    L t0 = (-hh - std::sqrt(hh * hh - a * cc)) / a;
    // The discriminant cancels 12 digits here even in long double: polish the root by
    // Newton on Q at the point itself, where the numbers are of the ellipsoid's size.
    for (int it = 0; it < 4; ++it) {
      const L px = ox + t0 * d.x, py = oy + t0 * d.y, pz = oz + t0 * d.z;
      const L f = 4 * px * px + py * py + pz * pz - 1;
      const L df = 8 * px * d.x + 2 * py * d.y + 2 * pz * d.z;
      t0 -= f / df;
    }
    INFO("k = " << k);
    CHECK(std::abs((L)h.t - t0) / t0 < 1e-14L);
  }
}

TEST_CASE("quadric: a hyperboloid of one sheet holds its axis inside (a < 0 without roots)",
          "[primitives][quadric]") {
  const Quadric hyp({Vec3(1, -1, 1), Vec3(0), Vec3(0), -0.5});
  bool inside;
  CHECK(crossingsOf(hyp, Ray(Vec3(0, -10, 0), Vec3(0, 1, 0)), inside).empty());
  CHECK(inside);
  CHECK(hyp.inside(Vec3(0, 100, 0)));
  CHECK_FALSE(hyp.inside(Vec3(1, 0, 0)));
}

TEST_CASE("quadric: refuses coefficients without a surface or not finite",
          "[primitives][quadric]") {
  CHECK_THROWS(Quadric({Vec3(0), Vec3(0), Vec3(0), 1}));
  CHECK_THROWS(Quadric({Vec3(1, std::nan(""), 1), Vec3(0), Vec3(0), -1}));
}
