// Aggregate, the masked search structure a world's ray queries go through, against brute
// force over its objects: closest() and closestSelected() find the hit each object's own
// test finds, and anyHit() answers whether an object not left out by the mask blocks the
// ray, whichever object it is told to test first.
#include "random_items.h"

#include "primitives/aggregate.h"
#include "primitives/box.h"
#include "primitives/instance.h"
#include "primitives/plane.h"
#include "primitives/sphere.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <memory>

using namespace lucent;
using namespace lucent::testing;

namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Spheres by their centre (kept in world space by the aggregate), spheres under a rotation
// and uniform scale (kept in world space, their surface error widened), spheres under a
// non-uniform scale and rotated boxes (tested through their Instance), and two planes
// (unbounded, tested one by one). Masks cycle through every combination of two bits.
struct Objects {
  std::vector<std::unique_ptr<Shape>> owned;
  std::vector<Aggregate::Object> list;

  explicit Objects(std::mt19937_64& rng) {
    for (int i = 0; i < 400; ++i) {
      const Mat4 at = glm::translate(Mat4(1.0), randomVec(rng, -9, 9));
      const Mat4 turned =
          glm::rotate(at, uniform(rng, 0, 6.3), glm::normalize(randomVec(rng, 0.1, 1)));
      std::shared_ptr<const Shape> shape;
      Mat4 m(1.0);
      switch (i % 4) {
        case 0:
          shape = std::make_shared<Sphere>(randomVec(rng, -9, 9), uniform(rng, 0.1, 0.8));
          break;
        case 1:
          shape = std::make_shared<Sphere>(Vec3(0.2, 0, 0), 0.5);
          m = glm::scale(turned, Vec3(uniform(rng, 0.3, 2.0)));
          break;
        case 2:
          shape = std::make_shared<Sphere>(Vec3(0.0), 0.5);
          m = glm::scale(turned, randomVec(rng, 0.3, 2.0));
          break;
        default:
          shape = std::make_shared<Box>(Vec3(-0.4), Vec3(0.5, 0.3, 0.6));
          m = turned;
          break;
      }
      add(std::make_unique<Instance>(shape, *Transform::fromMatrix(m), 0), Aggregate::Mask(i % 4));
    }
    add(std::make_unique<Plane>(Vec3(0, 1, 0), -10.0), 1);
    add(std::make_unique<Plane>(glm::normalize(Vec3(0.1, 1, 0.3)), 9.0), 0);
  }
  void add(std::unique_ptr<Shape> s, Aggregate::Mask mask) {
    list.push_back({s.get(), mask});
    owned.push_back(std::move(s));
  }
};

// The nearest hit of the objects `take` accepts, each asked in turn.
template <class Take>
Hit bruteForce(const std::vector<Aggregate::Object>& objects, const Ray& ray, Take&& take) {
  Hit best;
  Ray r = ray;
  for (const Aggregate::Object& o : objects) {
    Hit h;
    if (take(o) && o.shape->intersect(r, h)) {
      r.tmax = h.t;
      best = h;
    }
  }
  return best;
}

// anyHit with the mask as the template argument it is.
Aggregate::ObjectId anyHit(const Aggregate& a, const Ray& ray, Aggregate::Mask skip,
                           Aggregate::ObjectId first) {
  switch (skip) {
    case 0:
      return a.anyHit<0>(ray, first);
    case 1:
      return a.anyHit<1>(ray, first);
    case 2:
      return a.anyHit<2>(ray, first);
    default:
      return a.anyHit<3>(ray, first);
  }
}

}  // namespace

TEST_CASE("Aggregate: closest hits over every object and over the selected ones, as brute force",
          "[aggregate][bvh]") {
  std::mt19937_64 rng(71);
  Objects objects(rng);
  Aggregate::Options options;
  options.selected = 2;
  const Aggregate aggregate(objects.list, options);
  REQUIRE(aggregate.objectCount() == objects.list.size());
  REQUIRE(aggregate.inlineSphereCount() == 200);
  REQUIRE(aggregate.directObjects().size() == 2);
  REQUIRE(aggregate.selectedCount() == 200);
  size_t hits = 0, selectedHits = 0;
  for (const Ray& ray : randomRays(rng, 20000, 10.0)) {
    Hit got, want = bruteForce(objects.list, ray, [](const auto&) { return true; });
    REQUIRE(aggregate.closest(ray, got) == want.found());
    if (want.found()) {
      ++hits;
      REQUIRE(got.shape == want.shape);  // random rays make no exact ties
      REQUIRE(got.t == Approx(want.t).epsilon(1e-12));
    }
    Hit gotSelected, wantSelected = bruteForce(objects.list, ray,
                                               [](const auto&o) { return (o.mask & 2) != 0; });
    REQUIRE(aggregate.closestSelected(ray, gotSelected) == wantSelected.found());
    if (wantSelected.found()) {
      ++selectedHits;
      REQUIRE(gotSelected.shape == wantSelected.shape);
    }
    // Where the nearest of all is selected, the selected search returns it to the bit.
    if (got.found() && got.shape == gotSelected.shape) REQUIRE(gotSelected.t == got.t);
  }
  CHECK(hits > 10000);
  CHECK(selectedHits > 3000);
}

TEST_CASE("Aggregate: anyHit leaves out the masked objects and tests any first object",
          "[aggregate][bvh][occluder]") {
  std::mt19937_64 rng(72);
  Objects objects(rng);
  const Aggregate aggregate(objects.list, Aggregate::Options());
  const auto ids = static_cast<Aggregate::ObjectId>(aggregate.objectCount());
  std::uniform_int_distribution<Aggregate::ObjectId> anyId(0, ids - 1);
  size_t blocked[4] = {0, 0, 0, 0};
  for (Ray ray : randomRays(rng, 20000, 10.0)) {
    ray.tmax = uniform(rng, 0.01, 1.5);
    for (Aggregate::Mask skip = 0; skip < 4; ++skip) {
      bool want = false;
      for (const Aggregate::Object& o : objects.list)
        want = want || ((o.mask & skip) == 0 && o.shape->occluded(ray));
      for (Aggregate::ObjectId first : {Aggregate::kNoObject, anyId(rng)}) {
        const Aggregate::ObjectId found = anyHit(aggregate, ray, skip, first);
        REQUIRE((found != Aggregate::kNoObject) == want);
        if (!want) continue;
        const Shape* blocker = aggregate.object(found);
        REQUIRE(blocker->occluded(ray));
        bool masked = true;
        for (const Aggregate::Object& o : objects.list)
          if (o.shape == blocker) masked = (o.mask & skip) != 0;
        REQUIRE_FALSE(masked);
      }
      blocked[skip] += want;
    }
  }
  CHECK(aggregate.object(Aggregate::kNoObject) == nullptr);
  CHECK(aggregate.anyMasked(1));
  CHECK(aggregate.anyMasked(3));
  CHECK_FALSE(aggregate.anyMasked(4));
  // A mask no object has leaves nothing out.
  for (Ray ray : randomRays(rng, 2000, 10.0)) {
    ray.tmax = uniform(rng, 0.01, 1.5);
    REQUIRE((aggregate.anyHit<4>(ray) != Aggregate::kNoObject) ==
            (aggregate.anyHit<0>(ray) != Aggregate::kNoObject));
  }
  // Each mask leaves out objects that would otherwise block some rays.
  CHECK(blocked[0] > blocked[1]);
  CHECK(blocked[0] > blocked[2]);
  CHECK(blocked[1] > blocked[3]);
  CHECK(blocked[3] > 1000);
}
