// The world's top-level BVH answers as testing every object would, planes (unbounded)
// are tested beside it, and a shape used many times through <use> is built once.
#include "../primitives/mock_shapes.h"
#include "../primitives/random_items.h"
#include "world_helpers.h"

#include "scenegraph/world.h"

#include <catch2/catch.hpp>
#include <glm/ext/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::testing;

namespace {

struct CountingMaker {
  std::shared_ptr<int> calls = std::make_shared<int>(0);
  std::shared_ptr<const Shape> operator()(const ShapeSpec& spec) const {
    ++*calls;
    if (auto* s = std::get_if<SphereSpec>(&spec))
      return std::make_shared<MockSphere>(s->center, s->radius);
    if (auto* p = std::get_if<PlaneSpec>(&spec))
      return std::make_shared<MockHalfSpace>(p->normal, p->offset);
    throw std::logic_error("mock: unexpected shape");
  }
};

void requireSameAsBruteForce(const World& world, const std::vector<Ray>& rays) {
  size_t hits = 0;
  for (const Ray& ray : rays) {
    Hit want = bruteForce(world, ray), got;
    bool found = world.intersect(ray, got);
    REQUIRE(found == want.found());
    if (!found) continue;
    ++hits;
    REQUIRE(got.t == want.t);
    if (got.shape != want.shape) {  // a tie: the BVH's object must really be hit there
      Hit again;
      REQUIRE(got.shape->intersect(ray, again));
      REQUIRE(again.t == got.t);
    }
    REQUIRE(world.occluded(Ray(ray.o, ray.d, ray.tmin, got.t * 1.000001)));
    REQUIRE_FALSE(world.occluded(Ray(ray.o, ray.d, ray.tmin, got.t * 0.999999)));
  }
  CHECK(hits > rays.size() / 10);
  CHECK(hits < rays.size());
}

}  // namespace

TEST_CASE("world BVH gives the brute-force closest hit, planes tested beside it", "[bvh][world]") {
  std::mt19937_64 rng(11);
  Scene scene;
  std::uniform_real_distribution<double> radius(0.02, 0.4);
  for (int i = 0; i < 1200; ++i)
    scene.root->children.push_back(shapeNode(SphereSpec{randomVec(rng, -10, 10), radius(rng)}));
  // A floor at y = -8 (the world below it is solid): unbounded, so never in the BVH.
  scene.root->children.push_back(shapeNode(PlaneSpec{Vec3(0, 1, 0), -8.0}));

  CountingMaker maker;
  World world(scene, maker);
  CHECK(world.objects().size() == 1201);
  CHECK(world.directObjects().size() == 1);
  CHECK(world.bvh().itemCount() == 1200);
  requireSameAsBruteForce(world, randomRays(rng, 100000, 10.0));
}

TEST_CASE("a shape used many times through <use> is built once and shared", "[bvh][world]") {
  Scene scene;
  scene.defs.push_back(shapeNode(SphereSpec{Vec3(0.0), 0.3}));
  const Node* def = scene.defs.back().get();
  std::mt19937_64 rng(12);
  for (int i = 0; i < 2000; ++i) {
    auto use = std::make_unique<Node>();
    use->kind = NodeKind::Use;
    use->element = "use";
    use->target = def;
    use->parentFromNode = glm::translate(Mat4(1.0), randomVec(rng, -10, 10));
    scene.root->children.push_back(std::move(use));
  }
  CountingMaker maker;
  World world(scene, maker);
  CHECK(*maker.calls == 1);
  REQUIRE(world.leaves().size() == 2000);
  for (const WorldLeaf& leaf : world.leaves())
    REQUIRE(&leaf.instance->shape() == &world.leaves()[0].instance->shape());
  requireSameAsBruteForce(world, randomRays(rng, 20000, 10.0));
}

TEST_CASE("world with only unbounded objects, or nothing at all", "[bvh][world]") {
  Scene scene;
  CountingMaker maker;
  World empty(scene, maker);
  Hit h;
  CHECK_FALSE(empty.intersect(Ray(Vec3(0.0), Vec3(0, -1, 0)), h));
  CHECK_FALSE(empty.occluded(Ray(Vec3(0.0), Vec3(0, -1, 0))));

  scene.root->children.push_back(shapeNode(PlaneSpec{Vec3(0, 1, 0), -2.0}));
  World floor(scene, maker);
  CHECK(floor.directObjects().size() == 1);
  REQUIRE(floor.intersect(Ray(Vec3(0.0), Vec3(0, -1, 0)), h));
  CHECK(h.t == 2.0);
  CHECK(floor.occluded(Ray(Vec3(0.0), Vec3(0, -1, 0), 0.0, 2.5)));
  CHECK_FALSE(floor.occluded(Ray(Vec3(0.0), Vec3(0, -1, 0), 0.0, 1.5)));
}

TEST_CASE("a world of one object tests it directly, and answers the same", "[bvh][world]") {
  Scene scene;
  scene.root->children.push_back(shapeNode(SphereSpec{Vec3(0.0), 1.0}));
  CountingMaker maker;
  World world(scene, maker);
  CHECK(world.directObjects().size() == 1);
  CHECK(world.bvh().empty());
  std::mt19937_64 rng(13);
  size_t hits = 0;
  for (const Ray& ray : randomRays(rng, 2000, 2.0)) {
    Hit want = bruteForce(world, ray), got;
    REQUIRE(world.intersect(ray, got) == want.found());
    if (want.found()) REQUIRE(got.t == want.t);
    hits += want.found();
  }
  CHECK(hits > 100);
}
