#include "shape_checks.h"

#include "primitives/sor.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

namespace {

using V = std::vector<Vec2>;
const V kCylinder = {{1, -1}, {1, 0}, {1, 1}, {1, 2}};
const V kVase = {{0, -0.5}, {0.6, 0}, {0.9, 0.4}, {0.4, 1}, {0.5, 1.4}, {0.7, 1.6}, {0.8, 1.8}};
const V kBulb = {
    {0.5, -0.5}, {0, 0}, {0.8, 0.5}, {0, 1}, {0.5, 1.5}};  // meets the axis at both ends
const V kWaist = {{1, -1}, {1, 0}, {0.2, 0.5}, {0.9, 1.0}, {0.3, 1.6}, {0.1, 2.0}};

// An independent reference in long double: POV-Ray's construction itself, the cubic
// r² = A·y³ + B·y² + C·y + D in y through the Hermite conditions (a 4×4 system solved by
// elimination), the solid x² + z² <= r²(y) between the joints, and its crossings along a
// line by dense sampling of that inside test and bisection.
struct Reference {
  struct Cubic {
    long double A, B, C, D, y1, y2;
  };
  std::vector<Cubic> seg;
  bool open;

  Reference(const V& P, bool open_) : open(open_) {
    for (size_t i = 0; i + 3 < P.size(); ++i) {
      const long double x0 = P[i].x, x1 = P[i + 1].x, x2 = P[i + 2].x, x3 = P[i + 3].x;
      const long double y0 = P[i].y, y1 = P[i + 1].y, y2 = P[i + 2].y, y3 = P[i + 3].y;
      long double M[4][5] = {{y1 * y1 * y1, y1 * y1, y1, 1, x1 * x1},
                             {y2 * y2 * y2, y2 * y2, y2, 1, x2 * x2},
                             {3 * y1 * y1, 2 * y1, 1, 0, 2 * x1 * (x2 - x0) / (y2 - y0)},
                             {3 * y2 * y2, 2 * y2, 1, 0, 2 * x2 * (x3 - x1) / (y3 - y1)}};
      for (int c = 0; c < 4; ++c) {
        int piv = c;
        for (int r = c + 1; r < 4; ++r)
          if (std::abs(M[r][c]) > std::abs(M[piv][c])) piv = r;
        for (int k = 0; k < 5; ++k) std::swap(M[c][k], M[piv][k]);
        for (int r = 0; r < 4; ++r) {
          if (r == c) continue;
          const long double q = M[r][c] / M[c][c];
          for (int k = 0; k < 5; ++k) M[r][k] -= q * M[c][k];
        }
      }
      seg.push_back(
          {M[0][4] / M[0][0], M[1][4] / M[1][1], M[2][4] / M[2][2], M[3][4] / M[3][3], y1, y2});
    }
  }
  const Cubic* at(long double y) const {
    for (const Cubic& c : seg)
      if (y >= c.y1 && y <= c.y2) return &c;
    return nullptr;
  }
  static long double f(const Cubic& c, long double y) {
    return ((c.A * y + c.B) * y + c.C) * y + c.D;
  }
  static long double df(const Cubic& c, long double y) { return (3 * c.A * y + 2 * c.B) * y + c.C; }
  bool inside(long double x, long double y, long double z) const {
    const Cubic* c = at(y);
    return c && x * x + z * z <= f(*c, y);
  }
  // Every crossing of the solid's boundary on the line, by sampling 40000 steps over the
  // bounds and 200 bisections of each change (as long double).
  std::vector<long double> crossings(const Ray& ray, const AABB& box) const {
    const long double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z, dx = ray.d.x, dy = ray.d.y,
                      dz = ray.d.z;
    const Interval span = box.slab(Ray(ray.o, ray.d, -kInf, kInf), 1.0 / ray.d);
    std::vector<long double> out;
    if (span.empty()) return out;
    const long double t0 = span.lo - 1e-3, t1 = span.hi + 1e-3;
    auto in = [&](long double t) { return inside(ox + t * dx, oy + t * dy, oz + t * dz); };
    const int n = 40000;
    bool prev = in(t0);
    long double tp = t0;
    for (int k = 1; k <= n; ++k) {
      const long double t = t0 + (t1 - t0) * k / n;
      const bool now = in(t);
      if (now != prev) {
        long double a = tp, b = t;
        for (int it = 0; it < 200; ++it) {
          const long double mid = 0.5L * (a + b);
          (in(mid) == prev ? a : b) = mid;
        }
        out.push_back(0.5L * (a + b));
      }
      prev = now;
      tp = t;
    }
    return out;
  }
};

}  // namespace

TEST_CASE("sor: a cylinder of four points is hit where the closed form says", "[primitives][sor]") {
  const Sor s(kCylinder, false);
  CHECK(s.segments() == 1);
  CHECK(s.bounds().lo.y == 0.0);
  CHECK(s.bounds().hi.y == 1.0);
  CHECK_THAT(s.bounds().hi.x, WithinAbs(1.0, 1e-15));
  Hit h;
  const Ray across(Vec3(3, 0.5, 0), Vec3(-2, 0, 0));
  REQUIRE(s.intersect(across, h));
  CHECK_THAT(h.t, WithinAbs(1.0, 1e-15));
  CHECK_THAT(s.surface(across, h).ng.x, WithinAbs(1.0, 1e-15));
  // Down the axis: the top cap, then the bottom cap, normals up and down.
  const Ray down(Vec3(0.2, 5, 0.1), Vec3(0, -1, 0));
  CrossingList cl;
  s.crossings(down, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(4.0, 1e-15));
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(5.0, 1e-15));
  CHECK(cl.items[0].entering);
  CHECK_FALSE(cl.items[1].entering);
  CHECK_THAT(s.surface(down, cl.items[0].hit).ng.y, WithinAbs(1.0, 0.0));
  CHECK_THAT(s.surface(down, cl.items[1].hit).ng.y, WithinAbs(-1.0, 0.0));
  // Slanted: in through the top at (0.25, 1, 0), out through the bottom at (0.5, 0, 0).
  const Ray slant(Vec3(0, 2, 0), Vec3(0.25, -1, 0));
  s.crossings(slant, cl = {});
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(1.0, 1e-15));
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(2.0, 1e-15));
  CHECK(cl.items[1].hit.part == s.segments());  // the bottom cap
  // (u, v) as POV-Ray's: u the turn from +x towards +z, v the height through the segment;
  // on the caps from the centre (-1 at the bottom's, 2 at the top's) to the rim (0 and 1).
  const Ray fromZ(Vec3(0, 0.25, 3), Vec3(0, 0, -1));
  REQUIRE(s.intersect(fromZ, h));
  SurfaceInfo si = s.surface(fromZ, h);
  CHECK_THAT(si.uv.x, WithinAbs(0.25, 1e-15));
  CHECK_THAT(si.uv.y, WithinAbs(0.25, 1e-15));
  si = s.surface(across, [&] {
    Hit a;
    s.intersect(across, a);
    return a;
  }());
  CHECK_THAT(si.uv.x, WithinAbs(0.0, 1e-15));
  CHECK_THAT(si.uv.y, WithinAbs(0.5, 1e-15));
  si = s.surface(slant, cl.items[1].hit);
  CHECK_THAT(si.uv.y,
             WithinAbs(-0.5, 1e-15));  // the slanted ray's exit through the bottom at radius 0.5
  // Tangent to the side: no crossing; just inside: two.
  CHECK_FALSE(s.intersect(Ray(Vec3(1.0, 0.5, -3), Vec3(0, 0.1, 1)), h));
  CHECK(s.intersect(Ray(Vec3(0.999, 0.5, -3), Vec3(0, 0.1, 1)), h));
}

TEST_CASE("sor: the cubic takes POV-Ray's values at the joints and between them",
          "[primitives][sor]") {
  const Sor s(kVase, false);
  const Reference ref(kVase, false);
  REQUIRE(s.segments() == 4);
  for (size_t i = 1; i + 1 < kVase.size(); ++i)
    CHECK_THAT(s.radiusSquaredAt(kVase[i].y), WithinAbs(kVase[i].x * kVase[i].x, 1e-15));
  for (int k = 0; k <= 1000; ++k) {
    const double y = 1.6 * k / 1000;
    CHECK_THAT(s.radiusSquaredAt(y),
               WithinAbs(static_cast<double>(Reference::f(*ref.at(y), y)), 1e-13));
  }
}

TEST_CASE("sor: all crossings, in order, against a long double reference", "[primitives][sor]") {
  for (const V* pts : {&kVase, &kBulb, &kWaist}) {
    const Sor s(*pts, false);
    const Reference ref(*pts, false);
    Rng rng(3);
    int checked = 0, skipped = 0;
    double worst = 0.0;
    for (int i = 0; i < 600; ++i) {
      Ray ray = randomRayAt(rng, s.bounds());
      ray.d = glm::normalize(ray.d);
      const Ray line(ray.o, ray.d, -kInf, kInf);
      CrossingList cl;
      s.crossings(line, cl);
      CHECK(crossingsViolation(s, line, cl) == "");
      CHECK_FALSE(cl.startsInside);
      const auto want = ref.crossings(ray, s.bounds());
      // Crossings closer than the sampling step cannot be told apart by the reference.
      bool close = false;
      for (size_t k = 0; k + 1 < want.size(); ++k) close |= want[k + 1] - want[k] < 1e-3;
      for (size_t k = 0; k + 1 < cl.items.size(); ++k)
        close |= cl.items[k + 1].hit.t - cl.items[k].hit.t < 1e-3;
      if (close) {
        ++skipped;
        continue;
      }
      ++checked;
      REQUIRE(cl.items.size() == want.size());
      for (size_t k = 0; k < want.size(); ++k) {
        worst = std::max(worst, std::abs(cl.items[k].hit.t - static_cast<double>(want[k])));
        CHECK(cl.items[k].entering == (k % 2 == 0));
      }
    }
    INFO("checked " << checked << " skipped " << skipped);
    CHECK(checked > 250);
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("sor: the closest hit is the first crossing, and inside agrees with the reference",
          "[primitives][sor]") {
  for (const V* pts : {&kVase, &kBulb, &kWaist}) {
    const Sor s(*pts, false);
    const Reference ref(*pts, false);
    Rng rng(9);
    for (int i = 0; i < 1500; ++i)
      CHECK(intersectAgreesWithCrossings(s, randomRayAt(rng, s.bounds())) == "");
    int wrong = 0, in = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 p = randomInBox(rng, s.bounds().lo - 0.1, s.bounds().hi + 0.1);
      const bool want = ref.inside(p.x, p.y, p.z);
      in += want;
      wrong += s.inside(p) != want;
    }
    CHECK(in > 1000);
    CHECK(wrong == 0);
  }
}

TEST_CASE("sor: normals are the reference's gradient, caps face down and up", "[primitives][sor]") {
  const Sor s(kVase, false);
  const Reference ref(kVase, false);
  Rng rng(21);
  int sides = 0, caps = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = randomRayAt(rng, s.bounds());
    Hit h;
    if (!s.intersect(ray, h)) continue;
    const SurfaceInfo si = s.surface(ray, h);
    CHECK(std::abs(glm::length(si.ng) - 1.0) < 1e-12);
    if (h.part >= s.segments()) {
      ++caps;
      CHECK(si.ng.y == (h.part == s.segments() ? -1.0 : 1.0));
      CHECK(si.ng.y * ray.d.y < 0.0);
      continue;
    }
    ++sides;
    const Reference::Cubic* c = ref.at(si.p.y);
    REQUIRE(c);
    const Vec3 g = glm::normalize(
        Vec3(2 * si.p.x, -static_cast<double>(Reference::df(*c, si.p.y)), 2 * si.p.z));
    CHECK(glm::length(si.ng - g) < 1e-9);
    CHECK(glm::dot(si.ng, ray.d) < 0.0);  // entered from outside: the normal faces the ray
    CHECK(si.hasUV);
    CHECK(si.uv.y >= 0.0);
    CHECK(si.uv.y <= 1.0);
  }
  CHECK(sides > 500);
  CHECK(caps > 50);
}

TEST_CASE("sor: rays along the axis and through the cap rims", "[primitives][sor]") {
  const Sor vase(kVase, false);
  CrossingList cl;
  // Up the axis: the bottom cap at y = 0 and the top cap at y = 1.6.
  vase.crossings(Ray(Vec3(0, -1, 0), Vec3(0, 1, 0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == 1.0);
  CHECK(cl.items[1].hit.t == 2.6);
  CHECK(cl.items[0].hit.part == vase.segments());
  CHECK(cl.items[1].hit.part == vase.segments() + 1);
  // Parallel to the axis at radius rho: where r²(y) = rho², bisected on the curve itself.
  for (double rho : {0.45, 0.55, 0.65, 0.85}) {
    cl = {};
    vase.crossings(Ray(Vec3(rho, -1, 0), Vec3(0, 1, 0)), cl);
    int changes = 0;
    bool prev = vase.inside(Vec3(rho, -1, 0));
    for (int k = 1; k <= 100000; ++k) {
      const bool now = vase.inside(Vec3(rho, -1 + 3.0 * k / 100000, 0));
      changes += now != prev;
      prev = now;
    }
    CHECK(static_cast<int>(cl.items.size()) == changes);
    for (const Crossing& c : cl.items) {
      if (c.hit.part >= vase.segments()) continue;
      CHECK_THAT(vase.radiusSquaredAt(-1 + c.hit.t), WithinAbs(rho * rho, 1e-14));
    }
  }
  // The bulb meets the axis at both ends: no caps, a ray up the axis enters and leaves at
  // the poles.
  const Sor bulb(kBulb, false);
  cl = {};
  bulb.crossings(Ray(Vec3(0, -1, 0), Vec3(0, 1, 0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(1.0, 1e-12));
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(2.0, 1e-12));
  // Rays through the bottom rim of the vase (radius 0.6 at y = 0) from every side: the
  // crossings stay alternating and the first is at the rim.
  Rng rng(4);
  for (int i = 0; i < 500; ++i) {
    const double a = uniform(rng, 0, 2 * kPi);
    const Vec3 rim(0.6 * std::cos(a), 0.0, 0.6 * std::sin(a));
    const Vec3 d = randomUnit(rng);
    const Ray r(rim - 3.0 * d, d, -kInf, kInf);
    cl = {};
    vase.crossings(r, cl);
    CHECK(crossingsViolation(vase, r, cl) == "");
    CHECK(cl.items.size() % 2 == 0);
  }
}

TEST_CASE("sor: open leaves out the caps and is no solid", "[primitives][sor]") {
  const Sor closed(kVase, false), open(kVase, true);
  CHECK(closed.isSolid());
  CHECK_FALSE(open.isSolid());
  CHECK_FALSE(open.inside(Vec3(0, 0.5, 0)));
  CHECK(closed.inside(Vec3(0, 0.5, 0)));
  Rng rng(17);
  int withCaps = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = randomRayAt(rng, closed.bounds());
    CrossingList a, b;
    closed.crossings(ray, a);
    open.crossings(ray, b);
    CHECK(crossingsViolation(open, ray, b) == "");
    CHECK(intersectAgreesWithCrossings(open, ray) == "");
    std::vector<double> want;
    for (const Crossing& c : a.items)
      if (c.hit.part < closed.segments()) want.push_back(c.hit.t);
    withCaps += want.size() != a.items.size();
    REQUIRE(b.items.size() == want.size());
    for (size_t k = 0; k < want.size(); ++k) CHECK(b.items[k].hit.t == want[k]);
  }
  CHECK(withCaps > 100);
  // Down the axis of the open vase: nothing to hit.
  Hit h;
  CHECK_FALSE(open.intersect(Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), h));
}

TEST_CASE("sor: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][sor]") {
  const Sor s(kWaist, false);
  Rng rng(11);
  int selfHits = 0, hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = randomRayAt(rng, s.bounds());
    Hit h;
    if (!s.intersect(ray, h)) continue;
    ++hits;
    const SurfaceInfo si = s.surface(ray, h);
    const Vec3 off = si.p + si.ng * (4.0 * glm::length(si.pError));
    Hit h2;
    if (s.intersect(Ray(off, si.ng + 0.9 * randomUnit(rng)), h2) && h2.t < 1e-9) ++selfHits;
  }
  CHECK(hits > 1000);
  CHECK(selfHits == 0);
}

TEST_CASE("sor: bad point lists are refused", "[primitives][sor]") {
  CHECK_THROWS_AS(Sor(V{{1, 0}, {1, 1}, {1, 2}}, false), std::invalid_argument);
  CHECK_THROWS_AS(Sor(V{{1, 0}, {-1, 1}, {1, 2}, {1, 3}}, false), std::invalid_argument);
  CHECK_THROWS_AS(Sor(V{{1, 0}, {1, 1}, {1, 1}, {1, 3}}, false), std::invalid_argument);
  CHECK_THROWS_AS(Sor(V{{1, 2}, {1, 1}, {1, 2}, {1, 3}}, false),
                  std::invalid_argument);  // P0 at P2's height
  CHECK_THROWS_AS(Sor(V{{1, 0}, {0, 1}, {0, 2}, {1, 3}}, false), std::invalid_argument);
  CHECK_NOTHROW(
      Sor(V{{1, 5}, {1, 1}, {1, 2}, {1, -3}}, false));  // the control points may lie anywhere else
}
