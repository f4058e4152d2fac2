// The BVH gives the same answers as testing every item: closest hit (t and item), any hit,
// and the set of items whose boxes a ray overlaps; and its tree is well formed.
#include "random_items.h"

#include "primitives/bvh.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

using namespace lucent;
using namespace lucent::testing;

namespace {

template <class Item>
std::vector<AABB> boundsOf(const std::vector<Item>& items) {
  std::vector<AABB> b;
  for (const auto& it : items) b.push_back(it.bounds());
  return b;
}

struct Answer {
  double t = kInf;
  int64_t item = -1;
};

template <class Item>
Answer bruteClosest(const std::vector<Item>& items, const Ray& ray) {
  Answer a;
  Ray r = ray;
  for (size_t i = 0; i < items.size(); ++i) {
    double t = items[i].hit(r);
    if (t < r.tmax) {
      r.tmax = t;
      a = {t, int64_t(i)};
    }
  }
  return a;
}

template <class Item>
Answer bvhClosest(const Bvh& bvh, const std::vector<Item>& items, const Ray& ray) {
  Answer a;
  bvh.closest(ray, [&](uint32_t i, Ray& r) {
    double t = items[i].hit(r);
    if (!(t < r.tmax)) return false;
    r.tmax = t;
    a = {t, int64_t(i)};
    return true;
  });
  return a;
}

// Same distance, and the item the BVH names really is hit there (ties between items at
// the same distance, such as two triangles sharing an edge, may go either way).
template <class Item>
void requireSameClosest(const Bvh& bvh, const std::vector<Item>& items,
                        const std::vector<Ray>& rays) {
  size_t hits = 0, mismatches = 0;
  for (const Ray& ray : rays) {
    Answer want = bruteClosest(items, ray);
    Answer got = bvhClosest(bvh, items, ray);
    bool same = want.t == got.t &&
                (want.item == got.item || (got.item >= 0 && items[got.item].hit(ray) == got.t));
    if (!same) {
      if (mismatches++ < 5)
        FAIL_CHECK("ray o=(" << ray.o.x << "," << ray.o.y << "," << ray.o.z << ") d=(" << ray.d.x
                             << "," << ray.d.y << "," << ray.d.z << "): brute force t=" << want.t
                             << " item " << want.item << ", BVH t=" << got.t << " item "
                             << got.item);
    }
    hits += want.item >= 0;
  }
  CHECK(mismatches == 0);
  // The rays must really exercise the tree: many hit, many miss.
  CHECK(hits > rays.size() / 10);
  CHECK(hits < rays.size());
}

std::vector<TestSphere> randomSpheres(std::mt19937_64& rng, size_t n, double extent) {
  std::vector<TestSphere> s;
  std::uniform_real_distribution<double> radius(0.002 * extent, 0.05 * extent);
  for (size_t i = 0; i < n; ++i) s.push_back({randomVec(rng, -extent, extent), radius(rng)});
  return s;
}

// A sphere tessellated into a closed triangle mesh: rays meet shared edges and vertices.
std::vector<TestTriangle> tessellatedSphere(int rings, int segments, double r, Vec3 c) {
  auto p = [&](int i, int j) {
    double th = kPi * i / rings, ph = 2 * kPi * j / segments;
    return c + r * Vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
  };
  std::vector<TestTriangle> t;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      if (i > 0) t.push_back({p(i, j), p(i + 1, j), p(i, j + 1)});
      if (i + 1 < rings) t.push_back({p(i, j + 1), p(i + 1, j), p(i + 1, j + 1)});
    }
  return t;
}

// Walks the tree: every node's box holds its children's, every leaf's holds its items'
// (double boxes, so the float rounding went outward), every item sits in one leaf, and
// a node has free slots only if all its leaves hold one item.
void requireWellFormed(const Bvh& bvh, const std::vector<AABB>& items, uint32_t maxLeaf) {
  const auto& nodes = bvh.nodes();
  REQUIRE(reinterpret_cast<uintptr_t>(nodes.data()) % 64 == 0);
  std::vector<int> seen(items.size(), 0);
  auto inside = [](const AABB& inner, const AABB& outer) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
  };
  std::vector<int> visits(nodes.size(), 0);
  std::vector<std::pair<uint32_t, AABB>> todo{{0, AABB::everything()}};
  while (!todo.empty()) {
    auto [i, parentBox] = todo.back();
    todo.pop_back();
    REQUIRE(i < nodes.size());
    visits[i]++;
    const BvhNode& n = nodes[i];
    int used = 0;
    for (int c = 0; c < BvhNode::kWidth; ++c) {
      if (n.isEmpty(c)) {
        CHECK(n.bounds(c).empty());
        continue;
      }
      ++used;
      REQUIRE(inside(n.bounds(c), parentBox));
      if (n.isLeaf(c)) {
        REQUIRE(n.count[c] <= maxLeaf);
        for (uint32_t s = n.index[c]; s < n.index[c] + n.count[c]; ++s) {
          uint32_t item = bvh.order()[s];
          REQUIRE(inside(items[item], n.bounds(c)));
          seen[item]++;
        }
      } else {
        todo.push_back({n.index[c], n.bounds(c)});
      }
    }
    REQUIRE(used >= (i == 0 ? 1 : 2));
    // A free slot costs nothing to test, so no leaf beside one holds two items or more:
    // the build splits such leaves into the free slots.
    if (used < BvhNode::kWidth)
      for (int c = 0; c < BvhNode::kWidth; ++c) REQUIRE((!n.isLeaf(c) || n.count[c] == 1));
  }
  for (size_t i = 0; i < nodes.size(); ++i) REQUIRE(visits[i] == 1);  // a tree, all used
  CHECK(bvh.depth() < Bvh::kMaxDepth);
  for (size_t i = 0; i < items.size(); ++i) {
    INFO("item " << i);
    REQUIRE(seen[i] == (items[i].empty() ? 0 : 1));
  }
}

}  // namespace

TEST_CASE("BVH nodes hold 32-byte child entries on cache-line boundaries", "[bvh]") {
  CHECK(sizeof(BvhNode) == BvhNode::kWidth * 32);
  CHECK(alignof(BvhNode) == 64);
}

TEST_CASE("BVH closest hit equals brute force on 2000 random spheres and 10^5 rays", "[bvh]") {
  std::mt19937_64 rng(1);
  auto spheres = randomSpheres(rng, 2000, 10.0);
  Bvh bvh(boundsOf(spheres));
  requireWellFormed(bvh, boundsOf(spheres), Bvh::Options().maxLeafSize);
  requireSameClosest(bvh, spheres, randomRays(rng, 100000, 10.0));
}

TEST_CASE("BVH closest hit equals brute force on closed tessellated meshes", "[bvh]") {
  std::mt19937_64 rng(2);
  std::vector<TestTriangle> tris;
  for (int k = 0; k < 3; ++k) {
    auto s = tessellatedSphere(14, 28, 1.5 + k * 0.5, randomVec(rng, -4.0, 4.0));
    tris.insert(tris.end(), s.begin(), s.end());
  }
  Bvh bvh(boundsOf(tris));
  requireWellFormed(bvh, boundsOf(tris), Bvh::Options().maxLeafSize);
  requireSameClosest(bvh, tris, randomRays(rng, 100000, 6.0));
}

TEST_CASE("BVH finds hits on flat, axis-aligned triangles from grazing rays", "[bvh]") {
  // A grid of triangles in the plane z = 0.1 (not a float: its boxes are rounded outward
  // to a thin slab) and rays nearly parallel to it: a narrowed box would lose hits.
  std::vector<TestTriangle> tris;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) {
      Vec3 a(i * 0.1, j * 0.1, 0.1), b = a + Vec3(0.1, 0, 0), c = a + Vec3(0, 0.1, 0),
                                     d = a + Vec3(0.1, 0.1, 0);
      tris.push_back({a, b, c});
      tris.push_back({c, b, d});
    }
  std::mt19937_64 rng(3);
  std::vector<Ray> rays;
  std::uniform_real_distribution<double> u(-1.0, 7.0), slope(-1e-3, 1e-3);
  for (int k = 0; k < 20000; ++k) {
    Vec3 o(u(rng), u(rng), 0.1 + slope(rng));
    Vec3 d(u(rng), u(rng), slope(rng));
    if (k % 4 == 0) d.z = 0.0;  // parallel: misses unless hitting nothing at all
    rays.emplace_back(o, d);
  }
  // Rays from above and below at steep angles too.
  for (int k = 0; k < 20000; ++k)
    rays.emplace_back(Vec3(u(rng), u(rng), k % 2 ? 3.0 : -3.0),
                      Vec3(slope(rng), slope(rng), k % 2 ? -1.0 : 1.0));
  Bvh bvh(boundsOf(tris));
  requireSameClosest(bvh, tris, rays);
}

TEST_CASE("BVH finds boxes that share faces from rays running inside the shared face", "[bvh]") {
  // Unit cubes packed face to face; rays lie exactly in the planes x = k with a zero (or
  // negative zero) x direction, so the slab test meets NaN and ±inf.
  std::vector<TestBox> boxes;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k)
        if ((i + j + k) % 3 != 0) boxes.push_back({AABB(Vec3(i, j, k), Vec3(i + 1, j + 1, k + 1))});
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> plane(0, 8);
  std::uniform_real_distribution<double> u(-2.0, 10.0);
  std::vector<Ray> rays;
  for (int n = 0; n < 20000; ++n) {
    Vec3 o(plane(rng), u(rng), u(rng));
    Vec3 d(n % 2 ? 0.0 : -0.0, u(rng) - 4.0, u(rng) - 4.0);
    if (n % 5 == 0) d.y = 0.0, o.y = plane(rng);  // along an edge shared by four cubes
    if (d == Vec3(0.0)) d.z = 1.0;
    rays.emplace_back(o, d);
  }
  Bvh bvh(boundsOf(boxes));
  requireSameClosest(bvh, boxes, rays);
}

TEST_CASE("BVH any hit equals brute-force occlusion within a segment", "[bvh]") {
  std::mt19937_64 rng(5);
  auto spheres = randomSpheres(rng, 3000, 10.0);
  Bvh bvh(boundsOf(spheres));
  auto rays = randomRays(rng, 100000, 10.0);
  std::uniform_real_distribution<double> len(0.0, 2.0);
  size_t blocked = 0;
  for (Ray ray : rays) {
    ray.tmax = len(rng);  // shadow rays end at the light
    bool want = bruteClosest(spheres, ray).item >= 0;
    size_t tested = 0;
    bool got = bvh.any(ray, [&](uint32_t i, const Ray& r) {
      ++tested;
      return spheres[i].hit(r) < kInf;
    });
    REQUIRE(got == want);
    blocked += want;
    if (got) CHECK(tested <= spheres.size());
  }
  CHECK(blocked > rays.size() / 20);
  CHECK(blocked < rays.size());
}

TEST_CASE("BVH visits every item whose box the ray overlaps, each once", "[bvh]") {
  std::mt19937_64 rng(6);
  auto spheres = randomSpheres(rng, 1500, 10.0);
  auto bounds = boundsOf(spheres);
  Bvh bvh(bounds);
  auto rays = randomRays(rng, 20000, 10.0);
  size_t visitedTotal = 0;
  for (Ray ray : rays) {
    ray.tmin = 0.25;
    ray.tmax = 1.5;
    std::vector<uint32_t> got;
    bvh.all(ray, [&](uint32_t i) { got.push_back(i); });
    std::sort(got.begin(), got.end());
    REQUIRE(std::adjacent_find(got.begin(), got.end()) == got.end());
    for (size_t i = 0; i < bounds.size(); ++i)
      if (!bounds[i].slab(ray, 1.0 / ray.d).empty())
        REQUIRE(std::binary_search(got.begin(), got.end(), uint32_t(i)));
    visitedTotal += got.size();
    // In the tree's order (any-hit searches), the same items, each once.
    std::vector<uint32_t> inTreeOrder;
    bvh.candidates(
        ray, ray.tmax,
        [&](uint32_t i) {
          inTreeOrder.push_back(i);
          return true;
        },
        Bvh::NoPrefetch(), Bvh::Order::Tree);
    std::sort(inTreeOrder.begin(), inTreeOrder.end());
    REQUIRE(inTreeOrder == got);
  }
  // Culling works: a segment visits a small fraction of the items on average.
  CHECK(visitedTotal < rays.size() * spheres.size() / 20);
}

TEST_CASE("BVH over no items, one item, and items with empty boxes", "[bvh]") {
  Ray ray(Vec3(0, 0, -5), Vec3(0, 0, 1));
  auto never = [](uint32_t, Ray&) { return true; };
  Bvh none(std::vector<AABB>{});
  CHECK(none.empty());
  CHECK_FALSE(none.closest(ray, never));
  CHECK_FALSE(none.any(ray, [](uint32_t, const Ray&) { return true; }));

  std::vector<TestSphere> one{{Vec3(0.0), 1.0}};
  Bvh single(boundsOf(one));
  CHECK(bvhClosest(single, one, ray).t == 4.0);
  CHECK(bvhClosest(single, one, Ray(Vec3(0, 3, -5), Vec3(0, 0, 1))).item == -1);

  // An empty box (a CSG intersection of disjoint solids, a NaN vertex) is never visited.
  std::vector<AABB> boxes{AABB(), AABB(Vec3(-1.0), Vec3(1.0)), AABB(Vec3(std::nan("")), Vec3(1.0))};
  Bvh skip(boxes);
  CHECK(skip.itemCount() == 1);
  std::vector<uint32_t> visited;
  skip.all(ray, [&](uint32_t i) { visited.push_back(i); });
  CHECK(visited == std::vector<uint32_t>{1});
}

TEST_CASE("BVH refuses items with unbounded boxes", "[bvh]") {
  std::vector<AABB> boxes{AABB(Vec3(-1.0), Vec3(1.0)), AABB::everything()};
  CHECK_THROWS_WITH(Bvh(boxes), "BVH: an item has an unbounded box");
}

TEST_CASE("BVH over many identical items splits by count and keeps leaves small", "[bvh]") {
  // Every centroid coincides: no plane separates them, so the build halves by count.
  std::vector<TestSphere> same(1000, TestSphere{Vec3(1, 2, 3), 0.5});
  Bvh bvh(boundsOf(same));
  requireWellFormed(bvh, boundsOf(same), Bvh::Options().maxLeafSize);
  Answer a = bvhClosest(bvh, same, Ray(Vec3(1, 2, -3), Vec3(0, 0, 1)));
  CHECK(a.t == 5.5);
}

TEST_CASE("BVH depth stays bounded on inputs that make the SAH peel a few items at a time",
          "[bvh]") {
  // Thin slabs along x whose size grows geometrically, then stays at 1e15: there the
  // surface areas differ by less than float resolution, every split costs the same but
  // for rounding, and the SAH keeps cutting off thin slices. On this input it alone would
  // make a tree 71 splits deep; the build switches to median splits at depth 64 (with
  // 20000 slabs the SAH went past the traversal stack while small nodes had 16 bins,
  // and stays at 46 since they have fewer).
  std::vector<TestBox> boxes;
  for (int i = 0; i < 80000; ++i) {
    double s = std::min(std::pow(1.02, i), 1e15);
    boxes.push_back({AABB(Vec3(i, -s, -s), Vec3(i + 0.5, s, s))});
  }
  Bvh bvh(boundsOf(boxes));
  requireWellFormed(bvh, boundsOf(boxes), Bvh::Options().maxLeafSize);
  INFO("depth " << bvh.depth());
  CHECK(bvh.depth() >= 64);             // the input really is adversarial...
  CHECK(bvh.depth() < Bvh::kMaxDepth);  // ...and the traversal stack still suffices
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(-10.0, 80010.0), yz(-3.0, 3.0);
  std::vector<Ray> rays;
  for (int k = 0; k < 1500; ++k) {
    rays.emplace_back(Vec3(x(rng), yz(rng), yz(rng)), Vec3(k % 2 ? 1 : -1, 0.01, 0.02));
    rays.emplace_back(Vec3(x(rng), 1e30, yz(rng)), Vec3(0.1, -1.0, 0.0));
  }
  requireSameClosest(bvh, boxes, rays);
}

TEST_CASE("BVH built in parallel equals the serial build", "[bvh]") {
  std::mt19937_64 rng(8);
  auto spheres = randomSpheres(rng, 60000, 50.0);
  Bvh::Options serial;
  serial.parallel = false;
  Bvh a(boundsOf(spheres), serial);
  Bvh b(boundsOf(spheres));
  CHECK(a.order() == b.order());
  CHECK(a.nodes().size() == b.nodes().size());
  CHECK(a.depth() == b.depth());
  requireWellFormed(b, boundsOf(spheres), serial.maxLeafSize);
  auto rays = randomRays(rng, 20000, 50.0);
  for (const Ray& ray : rays) {
    Answer x = bvhClosest(a, spheres, ray), y = bvhClosest(b, spheres, ray);
    REQUIRE(x.t == y.t);
    REQUIRE(x.item == y.item);
  }
}

TEST_CASE("BVH traversal reports slots once the caller has taken the order", "[bvh]") {
  // A caller (a mesh) reorders its items to leaf order and drops the mapping.
  std::mt19937_64 rng(9);
  auto spheres = randomSpheres(rng, 500, 10.0);
  Bvh bvh(boundsOf(spheres));
  std::vector<uint32_t> order = bvh.takeOrder();
  CHECK(bvh.order().empty());
  std::vector<TestSphere> reordered;
  for (uint32_t i : order) reordered.push_back(spheres[i]);
  for (const Ray& ray : randomRays(rng, 5000, 10.0)) {
    Answer want = bruteClosest(spheres, ray);
    Answer got = bvhClosest(bvh, reordered, ray);
    REQUIRE(got.t == want.t);
    if (got.item >= 0) CHECK(order[got.item] == want.item);
  }
}

TEST_CASE("BVH float traversal keeps hits on items smaller than float spacing", "[bvh]") {
  // Spheres of radius 1e-4 around x = 1e4, where floats are 1e-3 apart: their boxes round
  // outward to a few float steps; rays come from afar, aimed at the centres, and graze.
  std::mt19937_64 rng(10);
  std::vector<TestSphere> spheres;
  for (int i = 0; i < 3000; ++i) spheres.push_back({Vec3(1e4) + randomVec(rng, -0.05, 0.05), 1e-4});
  Bvh bvh(boundsOf(spheres));
  std::vector<Ray> rays;
  std::uniform_int_distribution<size_t> pick(0, spheres.size() - 1);
  std::uniform_real_distribution<double> jitter(-1.2e-4, 1.2e-4);
  for (int k = 0; k < 30000; ++k) {
    Vec3 target = spheres[pick(rng)].c + Vec3(jitter(rng), jitter(rng), jitter(rng));
    Vec3 o = target + randomVec(rng, -1e5, 1e5);
    rays.emplace_back(o, target - o);
  }
  requireSameClosest(bvh, spheres, rays);
}

TEST_CASE("BVH candidates come nearest box first and stop when asked", "[bvh]") {
  // A row of unit boxes along x; a ray down the row meets them in order.
  std::vector<AABB> boxes;
  for (int i = 0; i < 200; ++i) boxes.push_back(AABB(Vec3(3 * i, 0, 0), Vec3(3 * i + 1, 1, 1)));
  std::mt19937_64 rng(12);
  std::shuffle(boxes.begin(), boxes.end(), rng);
  Bvh::Options oneEach;
  oneEach.maxLeafSize = 1;  // leaves of one box: the visit order is the boxes' order
  Bvh bvh(boxes, oneEach);
  Ray ray(Vec3(-5, 0.5, 0.5), Vec3(1, 1e-9, -1e-9));
  double tFar = kInf;
  std::vector<double> starts;
  bool completed = bvh.candidates(ray, tFar, [&](uint32_t i) {
    starts.push_back(boxes[i].lo.x);
    return starts.size() < 5;
  });
  CHECK_FALSE(completed);
  CHECK(starts == std::vector<double>{0, 3, 6, 9, 12});

  // Shrinking tFar after the first box skips every box that starts beyond it.
  starts.clear();
  tFar = kInf;
  completed = bvh.candidates(ray, tFar, [&](uint32_t i) {
    starts.push_back(boxes[i].lo.x);
    tFar = 20.0;  // boxes starting at x >= 15 (t >= 20) are never visited
    return true;
  });
  CHECK(completed);
  REQUIRE(!starts.empty());
  CHECK(*std::max_element(starts.begin(), starts.end()) <= 15.0);
  CHECK(starts.size() <= 6);  // 0, 3, ..., 15 at most
}
