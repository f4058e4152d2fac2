// The isosurface primitive against exact references: a sphere and a torus given as
// functions (hit distances from the closed forms, the torus from primitives/torus.h's
// exact quartic), the crossings contract, inside(), normals, both containers, open, and
// the record of gradients beyond the declared bound.
#include "shape_checks.h"

#include "primitives/isosurface.h"
#include "primitives/quadratic.h"
#include "primitives/torus.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace lucent;
using namespace lucent::test;

namespace {

class FnField final : public ScalarField {
 public:
  explicit FnField(std::function<double(const Vec3&)> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override { return f_(p); }

 private:
  std::function<double(const Vec3&)> f_;
};

std::shared_ptr<const ScalarField> field(std::function<double(const Vec3&)> f) {
  return std::make_shared<FnField>(std::move(f));
}

Isosurface::Params params(std::function<double(const Vec3&)> f) {
  Isosurface::Params p;
  p.field = field(std::move(f));
  return p;
}

IsosurfaceContainer ball(Vec3 c, double r) {
  IsosurfaceContainer k;
  k.kind = IsosurfaceContainer::Sphere;
  k.center = c;
  k.radius = r;
  return k;
}

IsosurfaceContainer box(Vec3 lo, Vec3 hi) {
  IsosurfaceContainer k;
  k.min = lo;
  k.max = hi;
  return k;
}

double sphereF(const Vec3& p) { return glm::length(p - Vec3(0.1, -0.2, 0.05)) - 0.7; }
double torusF(const Vec3& p) { return std::hypot(std::hypot(p.x, p.z) - 0.8, p.y) - 0.3; }

}  // namespace

TEST_CASE("isosurface: a sphere function is hit where the closed form says",
          "[primitives][isosurface]") {
  Isosurface::Params p = params(sphereF);
  p.container = box(Vec3(-1), Vec3(1));
  Isosurface iso(p);
  Rng rng(11);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    Ray ray = randomRayAt(rng, iso.bounds());
    double t0 = 0.0, t1 = 0.0;
    bool exact =
        solveDistanceQuadratic(ray.o - Vec3(0.1, -0.2, 0.05), ray.d, 0.49, t0, t1) && t0 < t1;
    Hit h;
    bool hit = iso.intersect(ray, h);
    // Rays grazing the sphere within the accuracy may go either way.
    if (exact && std::abs(t1 - t0) * glm::length(ray.d) < 1e-3) continue;
    REQUIRE(hit == exact);
    if (!hit) continue;
    ++hits;
    CHECK(std::abs(h.t - t0) * glm::length(ray.d) < 1e-9);
    SurfaceInfo s = iso.surface(ray, h);
    Vec3 n = glm::normalize(s.p - Vec3(0.1, -0.2, 0.05));
    CHECK(glm::length(s.ng - n) < 1e-7);
    CHECK(s.pError.x >= 0.0);
    CrossingList cl;
    iso.crossings(ray, cl);
    REQUIRE(cl.items.size() == 2);
    CHECK(cl.items[0].entering);
    CHECK_FALSE(cl.items[1].entering);
    CHECK(std::abs(cl.items[1].hit.t - t1) * glm::length(ray.d) < 1e-9);
  }
  CHECK(hits > 100);
}

TEST_CASE("isosurface: a torus function crosses where the exact torus does, in order",
          "[primitives][isosurface]") {
  Isosurface::Params p = params(torusF);
  p.container = ball(Vec3(0.0), 1.2);
  Isosurface iso(p);
  Torus exact(0.8, 0.3);
  Rng rng(12);
  int fourCrossings = 0;
  for (int i = 0; i < 600; ++i) {
    Ray ray = randomRayAt(rng, iso.bounds());
    CrossingList a, b;
    iso.crossings(ray, a);
    exact.crossings(ray, b);
    INFO("ray " << i);
    REQUIRE(crossingsViolation(iso, ray, a) == "");
    REQUIRE(intersectAgreesWithCrossings(iso, ray) == "");
    // A graze closer than the accuracy may drop a pair: compare only clean rays.
    bool close = false;
    for (size_t k = 1; k < b.items.size(); ++k)
      close |= (b.items[k].hit.t - b.items[k - 1].hit.t) * glm::length(ray.d) < 2e-3;
    if (close) continue;
    REQUIRE(a.items.size() == b.items.size());
    for (size_t k = 0; k < a.items.size(); ++k) {
      CHECK(a.items[k].entering == b.items[k].entering);
      CHECK(std::abs(a.items[k].hit.t - b.items[k].hit.t) * glm::length(ray.d) < 1e-9);
    }
    if (a.items.size() == 4) {
      ++fourCrossings;
      Hit h = a.items[2].hit;
      Vec3 q = ray.at(h.t);
      Vec3 ring = 0.8 * glm::normalize(Vec3(q.x, 0.0, q.z));
      CHECK(glm::length(iso.surface(ray, h).ng - glm::normalize(q - ring)) < 1e-7);
    }
  }
  CHECK(fourCrossings > 10);
}

TEST_CASE("isosurface: inside is below the threshold within the container",
          "[primitives][isosurface]") {
  Isosurface::Params p = params(torusF);
  p.threshold = 0.05;                                    // a fatter torus: tube radius 0.35
  p.container = box(Vec3(-1, -0.2, -1), Vec3(1, 1, 1));  // cuts the torus at y = -0.2
  Isosurface iso(p);
  CHECK(iso.inside(Vec3(0.8, 0.0, 0.0)));
  CHECK(iso.inside(Vec3(0.0, 0.1, -1.1 + 0.0 + 0.3)));  // |(0,0.1,-0.8)| on the ring, in the box
  CHECK_FALSE(iso.inside(Vec3(0.0, 0.0, 0.0)));         // the hole
  CHECK_FALSE(iso.inside(Vec3(0.8, -0.25, 0.0)));       // in the tube, below the box
  CHECK_FALSE(iso.inside(Vec3(0.0, 0.36, 0.8)));        // 0.36 from the ring
  CHECK(iso.inside(Vec3(0.0, 0.34, 0.8)));
  Rng rng(13);
  for (int i = 0; i < 2000; ++i) {
    Vec3 q = randomInBox(rng, Vec3(-1.5), Vec3(1.5));
    bool in =
        q.y >= -0.2 && q.y <= 1 && std::abs(q.x) <= 1 && std::abs(q.z) <= 1 && torusF(q) < 0.05;
    CHECK(iso.inside(q) == in);
  }
}

TEST_CASE("isosurface: the box container closes the solid where the function is inside",
          "[primitives][isosurface]") {
  // f = y: the lower half of the box.
  Isosurface::Params p = params([](const Vec3& q) { return q.y; });
  p.container = box(Vec3(-1), Vec3(1));
  Isosurface iso(p);
  Hit h;
  Ray down(Vec3(0.3, 5, 0.2), Vec3(0, -2, 0));
  REQUIRE(iso.intersect(down, h));
  CHECK(h.t == Approx(2.5).epsilon(1e-12));
  CHECK(h.part == Isosurface::kFunctionSurface);
  CHECK(glm::length(iso.surface(down, h).ng - Vec3(0, 1, 0)) < 1e-9);
  Ray up(Vec3(0.3, -5, 0.2), Vec3(0, 1, 0));
  REQUIRE(iso.intersect(up, h));
  CHECK(h.t == 4.0);
  CHECK(h.part == Isosurface::kContainerSurface);
  CHECK(iso.surface(up, h).ng == Vec3(0, -1, 0));
  Ray side(Vec3(-5, -0.5, 0.2), Vec3(1, 0, 0));
  REQUIRE(iso.intersect(side, h));
  CHECK(h.t == 4.0);
  CHECK(iso.surface(side, h).ng == Vec3(-1, 0, 0));
  CrossingList cl;
  iso.crossings(up, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == 4.0);
  CHECK(cl.items[1].hit.t == Approx(5.0).epsilon(1e-12));
  CHECK_FALSE(cl.items[1].entering);
  // From inside: starts inside, one leaving crossing.
  Ray from(Vec3(0, -0.5, 0), Vec3(0, 1, 0));
  cl.clear();
  iso.crossings(from, cl);
  CHECK(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].hit.t == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("isosurface: the sphere container closes a half-space into a hemisphere",
          "[primitives][isosurface]") {
  Isosurface::Params p = params([](const Vec3& q) { return q.y; });
  p.container = ball(Vec3(0.0), 1.0);
  Isosurface iso(p);
  Ray side(Vec3(-5, -0.6, 0), Vec3(1, 0, 0));
  Hit h;
  REQUIRE(iso.intersect(side, h));
  CHECK(h.t == Approx(5.0 - 0.8).epsilon(1e-14));
  CHECK(h.part == Isosurface::kContainerSurface);
  CHECK(glm::length(iso.surface(side, h).ng - Vec3(-0.8, -0.6, 0)) < 1e-12);
  Ray above(Vec3(-5, 0.6, 0), Vec3(1, 0, 0));
  CHECK_FALSE(iso.intersect(above, h));
  CHECK_FALSE(iso.occluded(above));
}

TEST_CASE("isosurface: open leaves only the function's surface, and is no solid",
          "[primitives][isosurface]") {
  Isosurface::Params p = params([](const Vec3& q) { return q.y; });
  p.container = box(Vec3(-1), Vec3(1));
  p.open = true;
  Isosurface iso(p);
  CHECK_FALSE(iso.isSolid());
  CHECK_FALSE(iso.inside(Vec3(0, -0.5, 0)));
  Ray up(Vec3(0.3, -5, 0.2), Vec3(0, 1, 0));
  Hit h;
  REQUIRE(iso.intersect(up, h));
  CHECK(h.t == Approx(5.0).epsilon(1e-12));
  CHECK(h.part == Isosurface::kFunctionSurface);
  Ray side(Vec3(-5, -0.5, 0.2), Vec3(1, 0, 0));
  CHECK_FALSE(iso.intersect(side, h));
  CrossingList cl;
  iso.crossings(up, cl);
  CHECK_FALSE(cl.startsInside);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
}

TEST_CASE("isosurface: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][isosurface]") {
  Isosurface::Params p = params(torusF);
  p.container = ball(Vec3(0.0), 1.2);
  Isosurface iso(p);
  Rng rng(14);
  int tried = 0;
  for (int i = 0; i < 400; ++i) {
    Ray ray = randomRayAt(rng, iso.bounds());
    Hit h;
    if (!iso.intersect(ray, h)) continue;
    SurfaceInfo s = iso.surface(ray, h);
    double off = glm::dot(glm::abs(s.ng), s.pError) * 2.0;
    CHECK_FALSE(iso.inside(s.p + s.ng * off));
    CHECK(iso.inside(s.p - s.ng * off));
    Ray out(s.p + s.ng * off, s.ng + 0.3 * randomUnit(rng));
    if (glm::dot(out.d, s.ng) <= 0.1) continue;
    ++tried;
    Hit h2;
    if (iso.intersect(out, h2)) CHECK(h2.t * glm::length(out.d) > 1e-6);
  }
  CHECK(tried > 50);
}

TEST_CASE("isosurface: a gradient beyond max-gradient is recorded, one within it is not",
          "[primitives][isosurface]") {
  // |∇f| = 5 everywhere.
  auto steep = [](const Vec3& q) { return 5.0 * (glm::length(q) - 0.5); };
  for (double declared : {1.0, 6.0}) {
    Isosurface::Params p = params(steep);
    p.maxGradient = declared;
    p.record = std::make_shared<GradientRecord>();
    Isosurface iso(p);
    Rng rng(15);
    for (int i = 0; i < 200; ++i) {
      Hit h;
      iso.intersect(randomRayAt(rng, iso.bounds()), h);
    }
    INFO("max-gradient " << declared);
    if (declared < 5.0) {
      // Slopes are estimated from pairs of values: at most the true 5, more than declared.
      CHECK(p.record->largest() > declared);
      CHECK(p.record->largest() <= 5.0 + 1e-9);
    } else {
      CHECK(p.record->largest() == 0.0);
    }
  }
}

TEST_CASE("isosurface: a function at the threshold everywhere ends its search within the budget",
          "[primitives][isosurface]") {
  // Every piece stays undecided: halving down to the accuracy would take 2^40 pieces.
  Isosurface::Params p = params([](const Vec3&) { return 0.0; });
  p.accuracy = 1e-12;
  Isosurface iso(p);
  Ray ray(Vec3(0.1, 0.2, 5), Vec3(0, 0, -1));
  Hit h;
  CHECK_FALSE(iso.intersect(ray, h));  // 0 counts as outside
  CrossingList cl;
  iso.crossings(ray, cl);
  CHECK(cl.items.empty());
  // Just below it: inside everywhere, so only the container's faces.
  Isosurface below(params([](const Vec3&) { return -1e-300; }));
  REQUIRE(below.intersect(ray, h));
  CHECK(h.t == 4.0);
  CHECK(h.part == Isosurface::kContainerSurface);
}

TEST_CASE("isosurface: invalid parameters are refused", "[primitives][isosurface]") {
  auto make = [](auto change) {
    Isosurface::Params p = params(sphereF);
    change(p);
    return [p] { Isosurface iso(p); };
  };
  CHECK_THROWS_AS(make([](Isosurface::Params& p) { p.field = nullptr; })(), std::invalid_argument);
  CHECK_THROWS_AS(make([](Isosurface::Params& p) { p.maxGradient = 0.0; })(),
                  std::invalid_argument);
  CHECK_THROWS_AS(make([](Isosurface::Params& p) { p.accuracy = -1.0; })(), std::invalid_argument);
  CHECK_THROWS_AS(make([](Isosurface::Params& p) { p.container = box(Vec3(1), Vec3(1)); })(),
                  std::invalid_argument);
  CHECK_THROWS_AS(make([](Isosurface::Params& p) { p.container = ball(Vec3(0.0), 0.0); })(),
                  std::invalid_argument);
  CHECK_NOTHROW(make([](Isosurface::Params&) {})());
}
