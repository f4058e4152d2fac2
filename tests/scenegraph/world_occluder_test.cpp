// World::occluder, the any-hit search a shadow cache drives: whichever object is tested
// first, it answers as World::occluded does, and it names an object that blocks.
#include "../primitives/random_items.h"
#include "world_helpers.h"

#include "csg/csg_node.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <set>

using namespace lucent;
using namespace lucent::testing;

namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Mat4 randomPlacement(std::mt19937_64& rng, bool uniformScale) {
  Mat4 m = glm::translate(Mat4(1.0), randomVec(rng, -9, 9));
  m = glm::rotate(m, uniform(rng, 0.0, 6.3), glm::normalize(randomVec(rng, 0.1, 1.0)));
  Vec3 s = uniformScale ? Vec3(uniform(rng, 0.3, 2.0)) : randomVec(rng, 0.3, 2.0);
  return glm::scale(m, s);
}

// Every kind of top-level object a world holds, through the real makeShape: spheres by
// their centre, under similarity transforms (kept in world space by the BVH) and under
// non-uniform scales (Instances); rotated boxes and cylinders; CSG differences; a floor
// plane and a tilted plane (unbounded, beside the BVH).
Scene mixedScene(std::mt19937_64& rng, bool withSpheres) {
  Scene scene;
  for (int i = 0; i < 240; ++i) {
    switch (i % 6) {
      case 0:
        if (withSpheres)
          scene.root->children.push_back(
              shapeNode(SphereSpec{randomVec(rng, -9, 9), uniform(rng, 0.1, 0.8)}));
        break;
      case 1:
        if (withSpheres)
          scene.root->children.push_back(
              shapeNode(SphereSpec{Vec3(0.2, 0, 0), 0.5}, randomPlacement(rng, true)));
        break;
      case 2:
        if (withSpheres)
          scene.root->children.push_back(
              shapeNode(SphereSpec{Vec3(0.0), 0.5}, randomPlacement(rng, false)));
        break;
      case 3:
        scene.root->children.push_back(
            shapeNode(BoxSpec{Vec3(-0.4), Vec3(0.5, 0.3, 0.6)}, randomPlacement(rng, false)));
        break;
      case 4:
        scene.root->children.push_back(shapeNode(CylinderSpec{Vec3(0.0), Vec3(0, 1, 0), 0.3, false},
                                                 randomPlacement(rng, false)));
        break;
      case 5: {
        auto csg = std::make_unique<Node>();
        csg->kind = NodeKind::Difference;
        csg->element = "difference";
        csg->parentFromNode = randomPlacement(rng, false);
        csg->children.push_back(shapeNode(BoxSpec{Vec3(-0.5), Vec3(0.5)}));
        csg->children.push_back(
            shapeNode(CylinderSpec{Vec3(0, -1, 0), Vec3(0, 1, 0), 0.35, false}));
        scene.root->children.push_back(std::move(csg));
        break;
      }
    }
  }
  scene.root->children.push_back(shapeNode(PlaneSpec{Vec3(0, 1, 0), -10.0}));
  scene.root->children.push_back(
      shapeNode(PlaneSpec{Vec3(0, 1, 0), 0.0},
                glm::rotate(glm::translate(Mat4(1.0), Vec3(0, 0, 9.5)), 1.4, Vec3(1, 0, 0))));
  return scene;
}

// Shadow-ray-like segments: random rays cut at a random length, so about half are blocked.
std::vector<Ray> segments(std::mt19937_64& rng, size_t n) {
  std::vector<Ray> rays = randomRays(rng, n, 10.0);
  for (Ray& r : rays) r.tmax = uniform(rng, 0.01, 1.5);
  return rays;
}

World::ObjectId idCount(const World& world) {
  return static_cast<World::ObjectId>(world.directObjects().size() + world.bvh().itemCount());
}

}  // namespace

TEST_CASE("occluder answers as occluded whichever object it tests first",
          "[bvh][world][occluder]") {
  std::mt19937_64 rng(41);
  Scene scene = mixedScene(rng, true);
  World world(scene);
  REQUIRE(world.inlineSphereCount() > 0);  // both kinds of BVH leaf are exercised
  REQUIRE(world.directObjects().size() == 2);
  const World::ObjectId ids = idCount(world);
  REQUIRE(ids == world.objects().size());
  std::set<const Shape*> objects;
  for (const auto& o : world.objects()) objects.insert(o.shape.get());
  std::uniform_int_distribution<World::ObjectId> anyId(0, ids - 1);

  size_t blocked = 0, checked = 0;
  const std::vector<Ray> rays = segments(rng, 20000);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& ray = rays[i];
    const bool want = world.occluded(ray);
    const World::ObjectId found = world.occluder(ray);
    REQUIRE((found != World::kNoObject) == want);
    if (want) {
      ++blocked;
      REQUIRE(found < ids);
      REQUIRE(objects.count(world.object(found)) == 1);
      // A cached blocker answers the same ray itself (the cache hit).
      REQUIRE(world.occluder(ray, found) == found);
    }
    // A cache holding some other object: the answer is still the full search's.
    REQUIRE((world.occluder(ray, anyId(rng)) != World::kNoObject) == want);
    if (i % 100 == 0) {
      for (World::ObjectId first = 0; first < ids; ++first) {
        const World::ObjectId got = world.occluder(ray, first);
        REQUIRE((got != World::kNoObject) == want);
        ++checked;
      }
    }
  }
  CHECK(blocked > rays.size() / 5);
  CHECK(blocked < rays.size() * 4 / 5);
  CHECK(checked == (rays.size() / 100) * ids);
  CHECK(world.object(World::kNoObject) == nullptr);
}

TEST_CASE("occluder blocks exactly when some object's own test does", "[bvh][world][occluder]") {
  // No spheres: every object's own occluded() is then the very test the world makes
  // (spheres are tested as world-space copies, equal only within rounding).
  std::mt19937_64 rng(42);
  Scene scene = mixedScene(rng, false);
  World world(scene);
  std::uniform_int_distribution<World::ObjectId> anyId(0, idCount(world) - 1);
  size_t blocked = 0;
  for (const Ray& ray : segments(rng, 20000)) {
    bool want = false;
    for (const auto& o : world.objects()) want = want || o.shape->occluded(ray);
    const World::ObjectId found = world.occluder(ray, anyId(rng));
    REQUIRE((found != World::kNoObject) == want);
    if (want) {
      REQUIRE(world.object(found)->occluded(ray));
      ++blocked;
    }
  }
  CHECK(blocked > 2000);
}

namespace {

// mixedScene with every third top-level object made of glass (CSG nodes included: the
// node's material is inherited by its leaves).
Scene glassyScene(std::mt19937_64& rng, bool withSpheres) {
  Scene scene = mixedScene(rng, withSpheres);
  Material glass;
  glass.transmissive = Color(0.9f);
  scene.materials.push_back(glass);
  const uint32_t glassId = static_cast<uint32_t>(scene.materials.size() - 1);
  for (size_t i = 0; i < scene.root->children.size(); i += 3)
    scene.root->children[i]->material = glassId;
  return scene;
}

}  // namespace

TEST_CASE("opaqueOccluder blocks exactly when an opaque object's own test does",
          "[bvh][world][occluder][glass]") {
  std::mt19937_64 rng(43);
  Scene scene = glassyScene(rng, false);
  World world(scene);
  // One object per child of the root, in order; every third is glass (the CSG nodes hold
  // glass when the node does, their leaves inheriting it).
  REQUIRE(world.objects().size() == scene.root->children.size());
  auto isGlass = [](size_t i) { return i % 3 == 0; };
  size_t glassObjects = 0;
  for (size_t i = 0; i < world.objects().size(); ++i) {
    REQUIRE(world.objects()[i].transmits == isGlass(i));
    glassObjects += isGlass(i);
  }
  REQUIRE(world.transmissiveObjectCount() == glassObjects);
  std::uniform_int_distribution<World::ObjectId> anyId(0, idCount(world) - 1);
  size_t blockedByGlassOnly = 0, blocked = 0;
  for (const Ray& ray : segments(rng, 20000)) {
    bool opaque = false, glass = false;
    for (size_t i = 0; i < world.objects().size(); ++i) {
      const bool blocks = world.objects()[i].shape->occluded(ray);
      (isGlass(i) ? glass : opaque) = (isGlass(i) ? glass : opaque) || blocks;
    }
    const World::ObjectId found = world.opaqueOccluder(ray, anyId(rng));
    REQUIRE((found != World::kNoObject) == opaque);
    if (opaque) {
      ++blocked;
      REQUIRE(world.object(found)->occluded(ray));
    }
    if (glass && !opaque) ++blockedByGlassOnly;
    // The full search still sees the glass.
    REQUIRE((world.occluder(ray) != World::kNoObject) == (opaque || glass));
  }
  CHECK(blocked > 2000);
  CHECK(blockedByGlassOnly > 500);
}

TEST_CASE("intersectTransmissive finds the closest hit among the glass objects, to the bit",
          "[bvh][world][glass]") {
  // With spheres: the glass spheres kept in world space must be tested as the full search
  // tests them, so a ray that meets only glass gets the very hit intersect() gives.
  std::mt19937_64 rng(44);
  Scene scene = glassyScene(rng, true);
  World world(scene);
  REQUIRE(world.inlineSphereCount() > 0);
  size_t compared = 0, glassHits = 0;
  for (const Ray& ray : randomRays(rng, 20000, 10.0)) {
    Hit all, clear;
    const bool hitAll = world.intersect(ray, all);
    const bool hitClear = world.intersectTransmissive(ray, clear);
    if (hitClear) {
      ++glassHits;
      REQUIRE(world.material(clear).isTransmissive());
      if (hitAll) REQUIRE(all.t <= clear.t);
    }
    // Where the nearest hit of all is glass, the glass-only search returns it exactly.
    if (hitAll && world.material(all).isTransmissive()) {
      REQUIRE(hitClear);
      REQUIRE(clear.t == all.t);
      REQUIRE(clear.shape == all.shape);
      ++compared;
    }
  }
  CHECK(compared > 1000);
  CHECK(glassHits > compared);
}
