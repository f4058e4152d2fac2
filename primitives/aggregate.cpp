#include "aggregate.h"

#include "instance.h"
#include "offset.h"
#include "sphere.h"
#include "sphere_image.h"

namespace lucent {

namespace {

// SAH cost of testing a sphere kept in the BVH's leaves, relative to a node visit.
constexpr double kInlineSphereCost = 0.2;

}  // namespace

Aggregate::Aggregate(const std::vector<Object>& objects, const Options& options) {
  // Input indices: of the objects the BVH holds, and of those tested one by one.
  std::vector<uint32_t> bounded, direct;
  for (uint32_t i = 0; i < objects.size(); ++i) {
    AABB box = objects[i].shape->bounds();
    if (box.isBounded() || box.empty())
      bounded.push_back(i);  // an empty box is left out by the BVH itself
    else direct.push_back(i);
  }
  if (bounded.size() == 1 && !objects[bounded[0]].shape->bounds().empty()) {
    // A lone object (one mesh, say) culls rays itself: a tree above it would only add
    // a box test and a traversal per ray.
    direct.push_back(bounded[0]);
    bounded.clear();
  }
  for (uint32_t i : direct) all_.direct.push_back(objects[i].shape);

  // Spheres under a similarity transform become world-space spheres. A field of a
  // million spheres then costs one 32-byte read per leaf test instead of following
  // the BVH's slot to the Instance, and the Instance to its Sphere, each a separate
  // allocation that misses the cache (docs/performance-history.md). The Instance stays the
  // hit's shape: surface() and the material work as before. (The casts run here, once.)
  std::vector<Leaf> leafOf(bounded.size(), Leaf{0.0, 0.0, 0.0, -1.0});
  std::vector<AABB> boxes(bounded.size());
  std::vector<uint32_t> tagOf(bounded.size(), 0);
  for (size_t i = 0; i < bounded.size(); ++i) {
    Shape* object = objects[bounded[i]].shape;
    boxes[i] = object->bounds();
    auto* inst = dynamic_cast<Instance*>(object);
    const auto* sphere = inst ? dynamic_cast<const Sphere*>(&inst->shape()) : nullptr;
    if (!sphere) continue;
    auto image = sphereImage(inst->transform(), sphere->center(), sphere->radius());
    if (!image) continue;
    leafOf[i] =
        Leaf{image->center.x, image->center.y, image->center.z, image->radius * image->radius};
    tagOf[i] = inst->tag();
    if (image->error > 0.0) {
      // Secondary rays leaving this sphere are tested against the world copy: their
      // origins must clear it too. Its box: the copy's, widened by the same bound and
      // rounded outward (tighter than the box of the transformed object box when rotated).
      inst->widenSurfaceError(image->error);
      Vec3 reach(image->radius + image->error);
      Vec3 lo = image->center - reach, hi = image->center + reach;
      for (int a = 0; a < 3; ++a) {
        lo[a] = nextDown(lo[a]);
        hi[a] = nextUp(hi[a]);
      }
      boxes[i] = AABB{lo, hi};
    }
    ++inlineSpheres_;
  }

  // The SAH weighs a leaf by the cost of testing its items: an inline sphere costs a
  // fraction of a node's box test (kInlineSphereCost), so that a million spheres make
  // larger leaves and fewer nodes to fetch (the value is measured in
  // docs/performance-history.md, "Figures behind comments in the code"). Other objects
  // keep the default cost 1; a mixed set takes the mean. Returns the input index of each
  // leaf slot.
  auto fill = [&](Search& set, const std::vector<uint32_t>& items) {
    set.sphereTestSlot = options.sphereTestSlot;
    size_t spheres = 0;
    for (uint32_t i : items) spheres += leafOf[i].r2 >= 0.0;
    Bvh::Options bvhOptions;
    if (!items.empty())
      bvhOptions.itemCost =
          float((kInlineSphereCost * double(spheres) + double(items.size() - spheres)) /
                double(items.size()));
    set.bvh = Bvh(
        items.size(), [&](uint32_t k) { return boxes[items[k]]; }, bvhOptions);
    // Keep the leaves in leaf order: the traversal then hands out positions in leaves.
    std::vector<uint32_t> order = set.bvh.takeOrder();
    std::vector<uint32_t> slotInput;
    set.leaves.reserve(order.size());
    set.leafObjects.reserve(order.size());
    set.sphereTags.reserve(order.size());
    for (uint32_t k : order) {
      set.leaves.push_back(leafOf[items[k]]);
      set.leafObjects.push_back(objects[bounded[items[k]]].shape);
      set.sphereTags.push_back(tagOf[items[k]]);
      slotInput.push_back(bounded[items[k]]);
    }
    return slotInput;
  };
  std::vector<uint32_t> every(bounded.size());
  for (uint32_t i = 0; i < every.size(); ++i) every[i] = i;
  const std::vector<uint32_t> slotInput = fill(all_, every);

  for (const Object& o : objects) anyMask_ |= o.mask;
  if (anyMask_ == 0) return;
  masks_.reserve(objectCount());
  for (uint32_t i : direct) masks_.push_back(objects[i].mask);
  for (uint32_t i : slotInput) masks_.push_back(objects[i].mask);

  // The selected objects, each tested as all_ tests it (one by one, or in a tree as the
  // same kind of leaf), so that a search of them finds the same hits.
  // The objects a predicate keeps, as a search of their own.
  auto subset = [&](Search& set, auto keeps) {
    std::vector<uint32_t> items;
    for (uint32_t i = 0; i < bounded.size(); ++i)
      if (keeps(bounded[i])) items.push_back(i);
    for (uint32_t i : direct)
      if (keeps(i)) set.direct.push_back(objects[i].shape);
    if (!items.empty() || !set.direct.empty()) fill(set, items);
  };
  subset(selected_, [&](uint32_t i) { return (objects[i].mask & options.selected) != 0; });
  selected_.linearSearch = options.linearSelected;
  for (size_t v = 0; v < viewOf_.size(); ++v) {
    const Mask hidden = options.hidden[v];
    if ((anyMask_ & hidden) == 0) continue;
    viewOf_[v] = static_cast<int>(views_.size());
    views_.emplace_back();
    subset(views_.back(), [&](uint32_t i) { return (objects[i].mask & hidden) == 0; });
  }
}

bool Aggregate::Search::closest(const Ray& ray, Hit& hit) const {
  Ray r = copyByMembers(ray);
  bool found = false;
  for (const Shape* o : direct) {
    if (o->intersect(r, hit)) {
      r.tmax = hit.t;
      found = true;
    }
  }
  // The BVH search starts with tmax already at the nearest direct hit, if any. A sphere
  // hit records only t and its slot; its Instance is looked up once, for the winner
  // (leafObjects is another array: reading it for every closer hit missed the cache).
  const uint32_t kNoSlot = ~0u;
  uint32_t sphereSlot = kNoSlot;
  double sphereT = 0.0;
  auto hitSlot = [&](uint32_t i, Ray& rr) {
    const Leaf& leaf = leaves[i];
    if (leaf.r2 < 0.0) {
      if (!leafObjects[i]->intersect(rr, hit)) return false;
      rr.tmax = hit.t;
      sphereSlot = kNoSlot;
      return true;
    }
    ++threadTestCounts[sphereTestSlot];
    // Sphere::intersect's test: for a sphere under the identity the same hit to the bit.
    double t;
    if (!sphereHitDistance(Vec3(leaf.cx, leaf.cy, leaf.cz), leaf.r2, rr, t)) return false;
    rr.tmax = t;
    sphereSlot = i;
    sphereT = rr.tmax;
    return true;
  };
  bool inTree = false;
  if (leaves.size() <= linearSearch) {
    for (uint32_t i = 0; i < leaves.size(); ++i) inTree = hitSlot(i, r) || inTree;
  } else {
    inTree = bvh.closest(r, hitSlot,
                         [this](uint32_t first, uint32_t count) { prefetchLeaves(first, count); });
  }
  if (sphereSlot != kNoSlot) {
    hit = Hit();
    hit.t = sphereT;
    hit.shape = leafObjects[sphereSlot];
    hit.tag = sphereTags[sphereSlot];
  }
  return found || inTree;
}

bool Aggregate::Search::slotOccluded(uint32_t slot, const Ray& ray) const {
  const Leaf& leaf = leaves[slot];
  if (leaf.r2 < 0.0) return leafObjects[slot]->occluded(ray);
  ++threadTestCounts[sphereTestSlot];
  double t;
  return sphereHitDistance(Vec3(leaf.cx, leaf.cy, leaf.cz), leaf.r2, ray, t);
}

const Shape* Aggregate::object(ObjectId id) const {
  if (id == kNoObject) return nullptr;
  return id < all_.direct.size() ? all_.direct[id] : all_.leafObjects[id - all_.direct.size()];
}

}  // namespace lucent
