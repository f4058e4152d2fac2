// CSG nodes with many children, whose crossings come only from the children whose boxes
// the ray overlaps: checked against membership along the ray and against brute force.
#include "../primitives/mock_shapes.h"
#include "../primitives/random_items.h"

#include "csg/csg_node.h"
#include "primitives/instance.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::testing;

namespace {

std::unique_ptr<Shape> sphere(Vec3 c, double r) {
  return std::make_unique<Instance>(std::make_shared<MockSphere>(c, r), Transform(), 0);
}

std::vector<std::unique_ptr<Shape>> randomSpheres(std::mt19937_64& rng, int n, double extent,
                                                  double rmin, double rmax) {
  std::vector<std::unique_ptr<Shape>> v;
  std::uniform_real_distribution<double> radius(rmin, rmax);
  for (int i = 0; i < n; ++i) v.push_back(sphere(randomVec(rng, -extent, extent), radius(rng)));
  return v;
}

// The crossing list is right if membership (inside()) between successive crossings is the
// state the list says, and every crossing is a real crossing of a child surface.
void requireCrossingsMatchMembership(const CsgNode& csg, const std::vector<Ray>& rays) {
  size_t withCrossings = 0;
  for (Ray ray : rays) {
    ray.tmin = 0.0;
    ray.tmax = 40.0;
    CrossingList list;
    csg.crossings(ray, list);
    withCrossings += !list.items.empty();
    bool state = list.startsInside;
    REQUIRE(state == csg.inside(ray.at(ray.tmin)));
    double from = ray.tmin;
    for (const Crossing& c : list.items) {
      REQUIRE(c.hit.t >= from);
      REQUIRE(c.entering == !state);
      if (c.hit.t - from > 1e-9) REQUIRE(csg.inside(ray.at(0.5 * (from + c.hit.t))) == state);
      // The leaf it names really is crossed there.
      CrossingList leaf;
      c.hit.shape->crossings(ray, leaf);
      bool real = false;
      for (const Crossing& l : leaf.items) real = real || l.hit.t == c.hit.t;
      REQUIRE(real);
      state = c.entering;
      from = c.hit.t;
    }
    if (ray.tmax - from > 1e-9) REQUIRE(csg.inside(ray.at(0.5 * (from + ray.tmax))) == state);
  }
  CHECK(withCrossings > rays.size() / 10);
}

}  // namespace

TEST_CASE("union of many children: BVH closest hit and any hit equal brute force", "[bvh][csg]") {
  std::mt19937_64 rng(21);
  auto kids = randomSpheres(rng, 800, 10.0, 0.05, 0.8);
  std::vector<const Shape*> raw;
  for (const auto& k : kids) raw.push_back(k.get());
  CsgNode u(CsgOp::Union, std::move(kids));
  size_t hits = 0;
  for (const Ray& ray : randomRays(rng, 100000, 10.0)) {
    Hit want;
    Ray r = ray;
    for (const Shape* s : raw)
      if (s->intersect(r, want)) r.tmax = want.t;
    Hit got;
    REQUIRE(u.intersect(ray, got) == want.found());
    REQUIRE(u.occluded(ray) == want.found());
    if (!want.found()) continue;
    ++hits;
    REQUIRE(got.t == want.t);
    REQUIRE(got.shape == want.shape);
  }
  CHECK(hits > 10000);
  requireCrossingsMatchMembership(u, randomRays(rng, 20000, 10.0));
}

TEST_CASE("difference of a sphere and hundreds of holes: crossings follow membership",
          "[bvh][csg]") {
  std::mt19937_64 rng(22);
  std::vector<std::unique_ptr<Shape>> kids;
  kids.push_back(sphere(Vec3(0.0), 8.0));
  for (auto& k : randomSpheres(rng, 400, 8.0, 0.2, 1.0)) kids.push_back(std::move(k));
  CsgNode d(CsgOp::Difference, std::move(kids));
  auto rays = randomRays(rng, 20000, 10.0);
  requireCrossingsMatchMembership(d, rays);
  // The closest hit is the first crossing, and its leaf's normal faces out of the result.
  for (const Ray& ray : rays) {
    CrossingList list;
    d.crossings(ray, list);
    Hit h;
    bool found = d.intersect(ray, h);
    bool want = false;
    for (const Crossing& c : list.items)
      if (c.hit.t > ray.tmin && c.hit.t < ray.tmax) {
        want = true;
        REQUIRE(found);
        REQUIRE(h.t == c.hit.t);
        REQUIRE(h.flip == c.hit.flip);
        break;
      }
    REQUIRE(found == want);
  }
}

TEST_CASE("intersection and merge of many children follow membership", "[bvh][csg]") {
  std::mt19937_64 rng(23);
  CsgNode inter(CsgOp::Intersection, randomSpheres(rng, 30, 1.0, 6.0, 9.0));
  requireCrossingsMatchMembership(inter, randomRays(rng, 10000, 10.0));
  CsgNode merge(CsgOp::Merge, randomSpheres(rng, 500, 8.0, 0.3, 1.5));
  requireCrossingsMatchMembership(merge, randomRays(rng, 20000, 10.0));
}

TEST_CASE("CSG children without a finite box are tested beside the BVH", "[bvh][csg]") {
  // Spheres cut by the half-space y < 0: the half-space is unbounded.
  std::mt19937_64 rng(24);
  auto kids = randomSpheres(rng, 300, 8.0, 0.3, 1.5);
  std::vector<std::unique_ptr<Shape>> inter;
  inter.push_back(std::make_unique<CsgNode>(CsgOp::Union, std::move(kids)));
  inter.push_back(std::make_unique<Instance>(std::make_shared<MockHalfSpace>(Vec3(0, 1, 0), 0.0),
                                             Transform(), 0));
  CsgNode cut(CsgOp::Intersection, std::move(inter));
  requireCrossingsMatchMembership(cut, randomRays(rng, 20000, 10.0));

  std::vector<std::unique_ptr<Shape>> both;
  both.push_back(sphere(Vec3(0, 5, 0), 1.0));
  both.push_back(std::make_unique<Instance>(std::make_shared<MockHalfSpace>(Vec3(0, 1, 0), 0.0),
                                            Transform(), 0));
  CsgNode u(CsgOp::Union, std::move(both));
  Hit h;
  REQUIRE(u.intersect(Ray(Vec3(0, 10, 0), Vec3(0, -1, 0)), h));
  CHECK(h.t == 4.0);
  REQUIRE(u.intersect(Ray(Vec3(3, 10, 0), Vec3(0, -1, 0)), h));
  CHECK(h.t == 10.0);
  CHECK(u.occluded(Ray(Vec3(3, 10, 0), Vec3(0, -1, 0), 0.0, 11.0)));
  CHECK_FALSE(u.occluded(Ray(Vec3(3, 10, 0), Vec3(0, -1, 0), 0.0, 9.0)));
}
