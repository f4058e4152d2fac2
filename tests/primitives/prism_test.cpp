#include "shape_checks.h"

#include "csg/csg_node.h"
#include "primitives/box.h"
#include "primitives/prism.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using LD = long double;

namespace {

PrismContour polygon(const std::vector<Vec2>& pts) {
  PrismContour c;
  for (size_t i = 0; i < pts.size(); ++i) {
    PrismSegment s;
    s.degree = 1;
    s.p[0] = pts[i];
    s.p[1] = pts[(i + 1) % pts.size()];
    c.push_back(s);
  }
  return c;
}

const std::vector<Vec2> kSquare = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
const std::vector<Vec2> kHole = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};

// A circle of four cubic Béziers (the usual 0.5523 handles), radius 1.
PrismContour bezierCircle() {
  const double k = 0.5522847498307936;
  PrismContour c;
  const Vec2 pts[13] = {{1, 0},   {1, k},   {k, 1},  {0, 1},  {-k, 1}, {-1, k}, {-1, 0},
                        {-1, -k}, {-k, -1}, {0, -1}, {k, -1}, {1, -k}, {1, 0}};
  for (int i = 0; i < 4; ++i) {
    PrismSegment s;
    s.degree = 3;
    for (int j = 0; j < 4; ++j) s.p[j] = pts[3 * i + j];
    c.push_back(s);
  }
  return c;
}

// The exact crossings of a line with the convex solid of half-spaces n·p <= c, long double.
bool clipConvex(const Ray& ray, const std::vector<std::pair<Vec3, double>>& planes, LD& t0,
                LD& t1) {
  t0 = -1e300L;
  t1 = 1e300L;
  for (auto& [n, c] : planes) {
    LD dn = (LD)n.x * ray.d.x + (LD)n.y * ray.d.y + (LD)n.z * ray.d.z;
    LD on = (LD)n.x * ray.o.x + (LD)n.y * ray.o.y + (LD)n.z * ray.o.z;
    if (dn == 0) {
      if (on > c) return false;
      continue;
    }
    LD t = (c - on) / dn;
    if (dn > 0) t1 = std::min(t1, t);
    else t0 = std::max(t0, t);
  }
  return t0 <= t1;
}

void checkContract(const Prism& p, Rng& rng, int n) {
  for (int i = 0; i < n; ++i) {
    Ray ray = randomRayAt(rng, p.bounds(), uniform(rng, 0.3, 3.0));
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(crossingsViolation(p, ray, cl).empty());
    REQUIRE(intersectAgreesWithCrossings(p, ray).empty());
    if (!p.isSolid()) continue;
    CHECK(cl.startsInside == p.inside(ray.o));
    bool in = cl.startsInside;
    double last = ray.tmin;
    for (const Crossing& c : cl.items) {
      if (c.hit.t - last > 1e-7) CHECK(p.inside(ray.at(0.5 * (last + c.hit.t))) == in);
      in = c.entering;
      last = c.hit.t;
    }
  }
}

// Random rays about `box` cross `a` where they cross `b`: the same number of crossings, at
// the same t (relative 1e-14), the same way, and with `normals` the same normals. Returns
// how many rays crossed at all.
int checkSameCrossings(const Shape& a, const Shape& b, const AABB& box, Rng& rng, bool normals) {
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = randomRayAt(rng, box);
    CrossingList ca, cb;
    a.crossings(ray, ca);
    b.crossings(ray, cb);
    REQUIRE(ca.items.size() == cb.items.size());
    for (size_t k = 0; k < ca.items.size(); ++k) {
      CHECK(std::abs(ca.items[k].hit.t - cb.items[k].hit.t) <=
            1e-14 * (1 + std::abs(cb.items[k].hit.t)));
      CHECK(ca.items[k].entering == cb.items[k].entering);
      if (!normals) continue;
      SurfaceInfo sa = a.surface(ray, ca.items[k].hit), sb = b.surface(ray, cb.items[k].hit);
      CHECK(glm::length(sa.ng - sb.ng) < 1e-15);
    }
    hits += !ca.items.empty();
  }
  return hits;
}

}  // namespace

TEST_CASE("prism: a square prism crosses rays where the box does", "[primitives][prism]") {
  Prism p({polygon(kSquare)}, -0.5, 0.75);
  Box box(Vec3(-1, -0.5, -1), Vec3(1, 0.75, 1));
  Rng rng(41);
  CHECK(checkSameCrossings(p, box, box.bounds(), rng, true) > 1000);
}

TEST_CASE("prism: a hole by the even-odd rule", "[primitives][prism]") {
  Prism p({polygon(kSquare), polygon(kHole)}, 0, 1);
  Rng rng(42);
  for (int i = 0; i < 5000; ++i) {
    Vec3 q = randomInBox(rng, Vec3(-1.2, -0.2, -1.2), Vec3(1.2, 1.2, 1.2));
    const bool outer = std::abs(q.x) < 1 && std::abs(q.z) < 1 && q.y > 0 && q.y < 1;
    const bool hole = std::abs(q.x) < 0.5 && std::abs(q.z) < 0.5;
    REQUIRE(p.inside(q) == (outer && !hole));
  }
  // Along x through the middle: in at -1, out at the hole's -0.5, in at 0.5, out at 1.
  Ray ray(Vec3(-3, 0.5, 0), Vec3(1, 0, 0));
  CrossingList cl;
  p.crossings(ray, cl);
  REQUIRE(cl.items.size() == 4);
  CHECK(cl.items[0].hit.t == 2.0);
  CHECK(cl.items[1].hit.t == 2.5);
  CHECK(cl.items[2].hit.t == 3.5);
  CHECK(cl.items[3].hit.t == 4.0);
  CHECK(p.surface(ray, cl.items[1].hit).ng == Vec3(1, 0, 0));  // the hole's wall faces in
  checkContract(p, rng, 2000);
}

TEST_CASE("prism: hard cases on a square with a hole", "[primitives][prism]") {
  Prism p({polygon(kSquare), polygon(kHole)}, 0, 1);
  // Through two outer vertices along the diagonal: in at (-1, -1), out at (1, 1), with the
  // hole's corners on the way (crossed, not touched).
  {
    Ray ray(Vec3(-2, 0.5, -2), Vec3(1, 0, 1));
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(crossingsViolation(p, ray, cl).empty());
    REQUIRE(cl.items.size() == 4);
    CHECK(cl.items[0].hit.t == 1.0);
    CHECK(cl.items[1].hit.t == 1.5);
    CHECK(cl.items[2].hit.t == 2.5);
    CHECK(cl.items[3].hit.t == 3.0);
  }
  // Touching a vertex from outside (x + z = -2 meets the square only at (-1, -1)): no
  // crossing or a zero-length span, never one crossing.
  {
    Ray ray(Vec3(-3, 0.5, 1), Vec3(1, 0, -1));
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(crossingsViolation(p, ray, cl).empty());
    CHECK(cl.items.size() % 2 == 0);
    if (!cl.items.empty()) CHECK(cl.items[1].hit.t - cl.items[0].hit.t == 0.0);
  }
  // Along a side face (x = 1) and along the cap plane's edge: consistent either way.
  for (const Ray& ray : {Ray(Vec3(1, 0.5, -3), Vec3(0, 0, 1)), Ray(Vec3(1, 1, -3), Vec3(0, 0, 1)),
                         Ray(Vec3(-3, 1, 0), Vec3(1, 0, 0)), Ray(Vec3(0.5, -1, 0.5), Vec3(0, 1, 0)),
                         Ray(Vec3(0.75, -1, 0.75), Vec3(0, 1, 0))}) {
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(crossingsViolation(p, ray, cl).empty());
    REQUIRE(intersectAgreesWithCrossings(p, ray).empty());
    CHECK(cl.items.size() % 2 == 0);
  }
  // A vertical ray through the solid part: the two caps at their exact heights.
  {
    Ray ray(Vec3(0.75, -1, 0.75), Vec3(0, 2, 0));
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(cl.items.size() == 2);
    CHECK(cl.items[0].hit.t == 0.5);
    CHECK(cl.items[1].hit.t == 1.0);
    CHECK(p.surface(ray, cl.items[0].hit).ng == Vec3(0, -1, 0));
    CHECK(p.surface(ray, cl.items[1].hit).ng == Vec3(0, 1, 0));
  }
}

TEST_CASE("prism: a Bézier circle's hits lie on the curve, normals radial", "[primitives][prism]") {
  Prism p({bezierCircle()}, 0, 1);
  Rng rng(43);
  int sides = 0;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = randomRayAt(rng, p.bounds());
    Hit h;
    if (!p.intersect(ray, h) || h.part == Prism::kLowCap || h.part == Prism::kHighCap) continue;
    SurfaceInfo si = p.surface(ray, h);
    // The hit's (x, z) against the curve at the hit's parameter, in long double.
    const PrismSegment sg = bezierCircle()[h.part & ~Prism::kEntering];
    LD s = h.b1, u = 1 - s;
    LD bx = u * u * u * sg.p[0].x + 3 * u * u * s * sg.p[1].x + 3 * u * s * s * sg.p[2].x +
            s * s * s * sg.p[3].x;
    LD bz = u * u * u * sg.p[0].y + 3 * u * u * s * sg.p[1].y + 3 * u * s * s * sg.p[2].y +
            s * s * s * sg.p[3].y;
    CHECK(std::hypot((double)(bx - si.p.x), (double)(bz - si.p.z)) < 1e-12);
    // The Bézier circle is within 3e-4 of round: the normal is nearly radial, outward.
    Vec3 radial = glm::normalize(Vec3(si.p.x, 0, si.p.z));
    CHECK(glm::dot(si.ng, radial) > 0.9999);
    CHECK(glm::dot(si.ng, ray.d) < 0);
    ++sides;
  }
  CHECK(sides > 500);
  checkContract(p, rng, 2000);
}

TEST_CASE("prism: a conic square is the pyramid |x|, |z| < y", "[primitives][prism]") {
  Prism p({polygon(kSquare)}, 0.25, 1, Prism::Sweep::Conic);
  const std::vector<std::pair<Vec3, double>> planes = {{{1, -1, 0}, 0}, {{-1, -1, 0}, 0},
                                                       {{0, -1, 1}, 0}, {{0, -1, -1}, 0},
                                                       {{0, 1, 0}, 1},  {{0, -1, 0}, -0.25}};
  Rng rng(44);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = randomRayAt(rng, p.bounds());
    ray.tmin = -kInf;
    LD t0, t1;
    const bool expect = clipConvex(ray, planes, t0, t1) && t1 - t0 > 1e-9L;
    CrossingList cl;
    p.crossings(ray, cl);
    REQUIRE(crossingsViolation(p, ray, cl).empty());
    if (!expect) {
      CHECK(cl.items.size() <= 2);
      continue;
    }
    REQUIRE(cl.items.size() == 2);
    CHECK(std::abs(cl.items[0].hit.t - (double)t0) <= 1e-13 * (1 + std::abs((double)t0)));
    CHECK(std::abs(cl.items[1].hit.t - (double)t1) <= 1e-13 * (1 + std::abs((double)t1)));
    ++hits;
  }
  CHECK(hits > 500);
  // A side's normal: the face |x| = y has normal (1, -1, 0)/√2 on the x = y side.
  Ray ray(Vec3(3, 0.5, 0), Vec3(-1, 0, 0));
  Hit h;
  REQUIRE(p.intersect(ray, h));
  CHECK(h.t == 2.5);
  CHECK(glm::length(p.surface(ray, h).ng - Vec3(1, -1, 0) / std::sqrt(2.0)) < 1e-15);
  checkContract(p, rng, 2000);
}

TEST_CASE("prism: POV-Ray's spline rules", "[primitives][prism]") {
  // Linear: two polygons, each closed by repeating its first point.
  PrismOutline lin =
      prismOutline({{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {0, 0}, {0.1, 0}, {0, 0.1}, {0, 0}},
                   PrismSpline::Linear);
  REQUIRE(lin.error.empty());
  REQUIRE(lin.contours.size() == 2);
  CHECK(lin.contours[0].size() == 3);
  CHECK_FALSE(lin.closedLast);
  PrismOutline open = prismOutline({{0, 0}, {1, 0}, {0, 1}}, PrismSpline::Linear);
  CHECK(open.closedLast);
  CHECK(open.contours.at(0).size() == 3);
  // Quadratic: a control point, then the points, the first repeated.
  PrismOutline quad =
      prismOutline({{-1, 0}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}, PrismSpline::Quadratic);
  REQUIRE(quad.error.empty());
  REQUIRE(quad.contours.size() == 1);
  CHECK(quad.contours[0].size() == 4);
  CHECK(quad.contours[0][0].p[0] == Vec2(0, -1));
  // Cubic: as quadratic with a control point after the closing point.
  PrismOutline cub =
      prismOutline({{0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}, {0, 1}}, PrismSpline::Cubic);
  REQUIRE(cub.error.empty());
  REQUIRE(cub.contours.size() == 1);
  CHECK(cub.contours[0].size() == 4);
  CHECK(cub.contours[0][0].p[1] == Vec2(1, 2.0 / 6.0));  // P1 + (P2 - P0)/6
  CHECK_FALSE(prismOutline({{0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}}, PrismSpline::Cubic)
                  .error.empty());
  CHECK_FALSE(
      prismOutline({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, PrismSpline::Quadratic).error.empty());
  CHECK_FALSE(prismOutline({{0, 0}, {1, 0}, {1, 1}, {2, 1}}, PrismSpline::Bezier).error.empty());
  CHECK_FALSE(prismOutline({{0, 0}, {1, 0}}, PrismSpline::Linear).error.empty());
  CHECK_THROWS_AS(Prism({polygon(kSquare)}, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS(Prism({}, 0, 1), std::invalid_argument);
}

TEST_CASE("prism: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][prism]") {
  std::vector<Prism> prisms;
  prisms.emplace_back(std::vector<PrismContour>{polygon(kSquare), polygon(kHole)}, 0, 1);
  prisms.emplace_back(std::vector<PrismContour>{bezierCircle()}, -1, 1);
  prisms.emplace_back(std::vector<PrismContour>{bezierCircle()}, 0.2, 1.5, Prism::Sweep::Conic);
  Rng rng(45);
  for (const Prism& p : prisms) {
    for (int i = 0; i < 1000; ++i) {
      Ray ray = randomRayAt(rng, p.bounds());
      Hit h;
      if (!p.intersect(ray, h)) continue;
      SurfaceInfo si = p.surface(ray, h);
      const double eps = glm::dot(glm::abs(si.ng), si.pError) * 2.0;
      CHECK_FALSE(p.inside(si.p + si.ng * eps));
      CHECK(p.inside(si.p - si.ng * eps));
      Ray out(si.p + si.ng * eps, glm::reflect(ray.d, si.ng));
      Hit h2;
      if (p.intersect(out, h2)) CHECK(h2.t > 1e-9);
    }
  }
}

TEST_CASE("prism: a square minus a box through it is the square ring", "[primitives][prism][csg]") {
  std::vector<std::unique_ptr<Shape>> kids;
  kids.push_back(std::make_unique<Prism>(std::vector<PrismContour>{polygon(kSquare)}, 0, 1));
  kids.push_back(std::make_unique<Box>(Vec3(-0.5, -1, -0.5), Vec3(0.5, 2, 0.5)));
  CsgNode d(CsgOp::Difference, std::move(kids));
  Prism ring({polygon(kSquare), polygon(kHole)}, 0, 1);
  Rng rng(46);
  CHECK(checkSameCrossings(d, ring, ring.bounds(), rng, false) > 1000);
}
