// Quadrics unbounded alone (a cone, a hyperboloid, a paraboloid) are bounded inside the box
// the other children of an intersection leave: every point of the solid there lies in the
// box found, the box is no wider than the widest section, and rays aimed at points of the
// solid still hit it.
#include "csg/csg_node.h"
#include "primitives/instance.h"
#include "primitives/plane.h"
#include "primitives/quadric.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace lucent;

namespace {

struct Rng {
  uint32_t seed = 11;
  double operator()(double lo, double hi) {
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * ((seed >> 8) / 16777216.0);
  }
};

AABB slab(int axis, double lo, double hi) {
  AABB box = AABB::everything();
  box.lo[axis] = lo;
  box.hi[axis] = hi;
  return box;
}

// Points of the solid inside `clip` (sampled in `within`, a finite box around them) all lie
// in `box`; returns how close the farthest comes to each face (0: touches it).
Vec3 checkHolds(const Shape& solid, const AABB& clip, const AABB& within, const AABB& box) {
  Rng rng;
  Vec3 reach(kInf);
  int inside = 0;
  for (int n = 0; n < 200000; ++n) {
    const Vec3 p(rng(within.lo.x, within.hi.x), rng(within.lo.y, within.hi.y),
                 rng(within.lo.z, within.hi.z));
    if (!clip.contains(p) || !solid.inside(p)) continue;
    ++inside;
    INFO("point " << p.x << " " << p.y << " " << p.z);
    REQUIRE(box.contains(p));
    for (int k = 0; k < 3; ++k)
      reach[k] = std::min(reach[k], std::min(p[k] - box.lo[k], box.hi[k] - p[k]));
  }
  CHECK(inside > 1000);
  return reach;
}

}  // namespace

TEST_CASE("quadric bounds within a slab: hyperboloid, cone and paraboloid about y",
          "[csg][quadric][bounds]") {
  struct Case {
    const char* name;
    QuadricCoefficients q;
    double lo, hi;  // the slab in y
    double radius;  // the widest section's radius there
  };
  const Case cases[] = {
      // x² + z² − y² − 1 < 0: the one-sheet hyperboloid; at |y| = 3 the radius is √10.
      {"hyperboloid", {Vec3(1, -1, 1), Vec3(0), Vec3(0), -1.0}, -2.0, 3.0, std::sqrt(10.0)},
      // x² + z² − y² < 0: the double cone; between 1 and 2 the widest is 2.
      {"cone", {Vec3(1, -1, 1), Vec3(0), Vec3(0), 0.0}, 1.0, 2.0, 2.0},
      // x² + z² − y < 0: the paraboloid; up to 4 the radius is 2.
      {"paraboloid", {Vec3(1, 0, 1), Vec3(0), Vec3(0, -1, 0), 0.0}, 0.0, 4.0, 2.0},
      // (x − 1)² + 4z² − (y − 1)² − 1 < 0, off the axis and squeezed in z.
      {"shifted", {Vec3(1, -1, 4), Vec3(0), Vec3(-2, 2, 0), -1.0}, 0.0, 3.0, std::sqrt(5.0)},
  };
  for (const Case& c : cases) {
    SECTION(c.name) {
      const Quadric q(c.q);
      CHECK(!q.bounds().isBounded());
      const AABB clip = slab(1, c.lo, c.hi);
      const AABB box = q.boundsWithin(clip);
      REQUIRE(box.isBounded());
      CHECK(box.lo.y == c.lo);
      CHECK(box.hi.y == c.hi);
      // No wider than the widest section (plus the widening of a few roundings).
      CHECK(box.hi.x - box.lo.x == Approx(2.0 * c.radius).epsilon(1e-8));
      const AABB around{box.lo - Vec3(1.0), box.hi + Vec3(1.0)};
      const Vec3 reach = checkHolds(q, clip, around, box);
      CHECK(reach.x < 0.05 * c.radius);  // the box is tight: the solid reaches its sides
    }
  }
}

TEST_CASE("quadric bounds within a box: mixed terms and unfitting clips change nothing",
          "[csg][quadric][bounds]") {
  // x·y − 1 < 0 mixes y with x: no section across y is an ellipse.
  const Quadric saddle({Vec3(0), Vec3(1, 0, 0), Vec3(0), -1.0});
  const AABB clip = slab(1, 0.0, 1.0);
  const AABB box = saddle.boundsWithin(clip);
  CHECK(box.lo == clip.lo);
  CHECK(box.hi == clip.hi);
  // A slab the hyperboloid does not reach across y is still a slab.
  const Quadric hyperboloid({Vec3(1, -1, 1), Vec3(0), Vec3(0), -1.0});
  CHECK(!hyperboloid.boundsWithin(slab(0, 0.0, 1.0)).isBounded());
  // A slab where a cone's section is a point: x² + z² − y² < 0 at y = 0 holds no point.
  const Quadric cone({Vec3(1, -1, 1), Vec3(0), Vec3(0), 0.0});
  CHECK(cone.boundsWithin(slab(1, 0.0, 0.0)).empty());
}

TEST_CASE("an intersection of a placed hyperboloid and two planes has a finite box",
          "[csg][quadric][bounds]") {
  // chess2.pov's pawn neck: Hyperboloid_Y translate 5y scale <0.5, 1, 0.5>, between the
  // planes y = 2.5 and y = 5.5.
  auto hyperboloid =
      std::make_shared<Quadric>(QuadricCoefficients{Vec3(1, -1, 1), Vec3(0), Vec3(0), -1.0});
  const Mat4 placed =
      glm::scale(Mat4(1.0), Vec3(0.5, 1.0, 0.5)) * glm::translate(Mat4(1.0), Vec3(0.0, 5.0, 0.0));
  std::vector<std::unique_ptr<Shape>> children;
  children.push_back(std::make_unique<Instance>(hyperboloid, *Transform::fromMatrix(placed), 0));
  children.push_back(std::make_unique<Plane>(Vec3(0, 1, 0), 5.5));
  children.push_back(std::make_unique<Plane>(Vec3(0, -1, 0), -2.5));
  const CsgNode neck(CsgOp::Intersection, std::move(children));
  const AABB box = neck.bounds();
  REQUIRE(box.isBounded());
  // In object space y runs from −2.5 to 0.5: the widest section is at −2.5, radius √7.25,
  // scaled by 0.5 across.
  const double radius = 0.5 * std::sqrt(7.25);
  CHECK(box.hi.x == Approx(radius).epsilon(1e-8));
  CHECK(box.lo.z == Approx(-radius).epsilon(1e-8));
  CHECK(box.lo.y == 2.5);
  CHECK(box.hi.y == 5.5);
  const AABB around{box.lo - Vec3(0.5), box.hi + Vec3(0.5)};
  checkHolds(neck, AABB::everything(), around, box);
  // Rays aimed at points of the solid from outside the box still hit it, before the point.
  Rng rng;
  int aimed = 0;
  for (int n = 0; n < 20000 && aimed < 500; ++n) {
    const Vec3 p(rng(around.lo.x, around.hi.x), rng(around.lo.y, around.hi.y),
                 rng(around.lo.z, around.hi.z));
    if (!neck.inside(p)) continue;
    ++aimed;
    const Vec3 from = p + 10.0 * glm::normalize(Vec3(rng(-1, 1), rng(-1, 1), rng(-1, 1)));
    Hit hit;
    const Ray ray(from, glm::normalize(p - from));
    REQUIRE(neck.intersect(ray, hit));
    CHECK(hit.t <= glm::length(p - from) + 1e-9);
  }
  CHECK(aimed == 500);
}
