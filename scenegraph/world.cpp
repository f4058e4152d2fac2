#include "world.h"

#include "located_error.h"
#include "shape_registry.h"

#include "csg/csg_node.h"
#include "csg/inverted.h"
#include "primitives/offset.h"
#include "primitives/sphere.h"
#include "primitives/sphere_image.h"
#include "primitives/test_counts.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace lucent {

namespace {

// SAH cost of testing a sphere kept in the BVH's leaves, relative to a node visit.
constexpr double kInlineSphereCost = 0.2;

// The walk of a shadow ray through the objects that may transmit tests each in turn, when
// they are at most this many, instead of traversing their BVH: they are few (glass
// spheres and lenses), and the BVH's set-up per ray cost more than the box tests save
// (docs/performance-history.md, "Figures behind comments in the code").
constexpr size_t kLinearTransmissive = 4;

bool finiteTransform(const Transform& t) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(t.worldFromObject()[c][r]) || !std::isfinite(t.objectFromWorld()[c][r]))
        return false;
  return true;
}

CsgOp csgOpOf(NodeKind k) {
  switch (k) {
    case NodeKind::Union:
      return CsgOp::Union;
    case NodeKind::Merge:
      return CsgOp::Merge;
    case NodeKind::Intersection:
      return CsgOp::Intersection;
    default:
      return CsgOp::Difference;
  }
}

// Whether a leaf of the object has a transmissive material.
bool transmitsLight(const Shape& object, const std::vector<Material>& materials) {
  if (const auto* csg = dynamic_cast<const CsgNode*>(&object)) {
    for (const auto& c : csg->children())
      if (transmitsLight(*c, materials)) return true;
    return false;
  }
  if (const auto* inv = dynamic_cast<const Inverted*>(&object))
    return transmitsLight(inv->solid(), materials);
  const auto* leaf = dynamic_cast<const Instance*>(&object);
  return leaf && materials[leaf->tag()].isTransmissive();
}

// The node's world transform below `parentWorld`; throws what building the world refuses.
Transform nodeWorld(const Node& node, const Transform& parentWorld) {
  // Most nodes of a large scene have no transform of their own: no inverse to compute.
  if (node.parentFromNode == Mat4(1.0)) return parentWorld;
  auto local = Transform::fromMatrix(node.parentFromNode);
  if (!local) throw LocatedError(node.loc, "singular transform");
  Transform world = local->followedBy(parentWorld);
  // Each transform is finite, but nested ones multiply (twenty groups of scale(1e30)).
  if (!finiteTransform(world))
    throw LocatedError(node.loc, "the transforms down to this node multiply beyond double range");
  return world;
}

// Walks the graph as Builder does, computing transforms only.
void checkNode(const Node& node, const Transform& parentWorld) {
  Transform world = nodeWorld(node, parentWorld);
  if (node.kind == NodeKind::Use) return checkNode(*node.target, world);
  for (const auto& c : node.children) checkNode(*c, world);
}

// Does any node lead to another through <use> (so that one node may be reached twice)?
bool hasUses(const Scene& scene) {
  std::vector<const Node*> stack{scene.root.get()};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    if (n->kind == NodeKind::Use) return true;
    for (const auto& c : n->children) stack.push_back(c.get());
  }
  return false;
}

struct Builder {
  const ShapeMaker& makeShape;
  // A shape reached through several <use>s is built once; without <use>s every shape is
  // reached once, and the map (a hash per node of a million) is skipped.
  bool share;
  std::unordered_map<const Node*, std::shared_ptr<const Shape>> shapes;
  std::vector<const Instance*>& instances;

  // Adds the node's objects to `out`, each with whether it casts shadows in `casts`.
  // `inSolid`: the node is (inside) an operand of a merge, intersection or difference,
  // whose shadow is the whole operation's: the flags of its parts are not consulted.
  void add(const Node& node, const Transform& parentWorld, uint32_t inherited, bool castsAbove,
           bool inSolid, std::vector<std::unique_ptr<Shape>>& out, std::vector<char>& casts) {
    if (node.inverse) addInverted(node, parentWorld, inherited, castsAbove, inSolid, out, casts);
    else addPlain(node, parentWorld, inherited, castsAbove, inSolid, out, casts);
  }

  // The node's objects as written, its own inverse aside.
  void addPlain(const Node& node, const Transform& parentWorld, uint32_t inherited, bool castsAbove,
                bool inSolid, std::vector<std::unique_ptr<Shape>>& out, std::vector<char>& casts) {
    Transform world = nodeWorld(node, parentWorld);
    uint32_t material = node.material.value_or(inherited);
    const bool castsShadow = inSolid || (castsAbove && node.shadows);

    switch (node.kind) {
      case NodeKind::Shape: {
        std::shared_ptr<const Shape> shape;
        if (share) {
          auto& shared = shapes[&node];
          if (!shared) shared = makeShape(*node.shape);
          shape = shared;
        } else {
          shape = makeShape(*node.shape);
        }
        auto inst =
            std::make_unique<Instance>(std::move(shape), world, material, node.shape->index());
        instances.push_back(inst.get());
        out.push_back(std::move(inst));
        casts.push_back(castsShadow);
        break;
      }
      case NodeKind::Group:
        for (const auto& c : node.children)
          add(*c, world, material, castsShadow, inSolid, out, casts);
        break;
      case NodeKind::Use:
        // The referenced node's own transform applies first, then the <use>'s.
        add(*node.target, world, material, castsShadow, inSolid, out, casts);
        break;
      case NodeKind::Light:
        break;  // placed by placeLights, not built
      case NodeKind::Union: {
        std::vector<std::unique_ptr<Shape>> children;
        std::vector<char> childCasts;
        for (const auto& c : node.children)
          add(*c, world, material, castsShadow, inSolid, children, childCasts);
        if (children.empty()) break;
        const bool mixed = std::any_of(childCasts.begin(), childCasts.end(),
                                       [&](char c) { return c != childCasts.front(); });
        if (!mixed) {
          out.push_back(std::make_unique<CsgNode>(CsgOp::Union, std::move(children)));
          casts.push_back(childCasts.front());
          break;
        }
        // Some children cast shadows and some do not: two unions, which together show and
        // hold the same as one (POV-Ray splits every union into its children).
        for (char flag : {char(1), char(0)}) {
          std::vector<std::unique_ptr<Shape>> part;
          for (size_t i = 0; i < children.size(); ++i)
            if (childCasts[i] == flag) part.push_back(std::move(children[i]));
          out.push_back(std::make_unique<CsgNode>(CsgOp::Union, std::move(part)));
          casts.push_back(flag);
        }
        break;
      }
      case NodeKind::Merge:
      case NodeKind::Intersection:
      case NodeKind::Difference: {
        std::vector<std::unique_ptr<Shape>> children;
        std::vector<char> ignored;
        for (const auto& c : node.children) add(*c, world, material, true, true, children, ignored);
        if (children.empty()) break;
        out.push_back(std::make_unique<CsgNode>(csgOpOf(node.kind), std::move(children)));
        casts.push_back(castsShadow);
        break;
      }
    }
  }

  // inverse="true": the node's objects as one solid (a union of them when there are
  // several, unsplit by shadow flags: the inverse of a union is not the union of the
  // inverses), inside out. It casts shadows as the node says.
  void addInverted(const Node& node, const Transform& parentWorld, uint32_t inherited,
                   bool castsAbove, bool inSolid, std::vector<std::unique_ptr<Shape>>& out,
                   std::vector<char>& casts) {
    std::vector<std::unique_ptr<Shape>> parts;
    std::vector<char> partCasts;
    addPlain(node, parentWorld, inherited, castsAbove, inSolid, parts, partCasts);
    if (parts.empty()) return;
    std::unique_ptr<Shape> solid = parts.size() == 1
                                       ? std::move(parts.front())
                                       : std::make_unique<CsgNode>(CsgOp::Union, std::move(parts));
    out.push_back(std::make_unique<Inverted>(std::move(solid)));
    casts.push_back(inSolid || (castsAbove && node.shadows));
  }
};

}  // namespace

void checkWorld(const Scene& scene) { checkNode(*scene.root, Transform()); }

World::World(const Scene& scene) : World(scene, makeShape) {}

World::World(const Scene& scene, const ShapeMaker& make) : scene_(scene) {
  Builder b{make, hasUses(scene), {}, instances_};
  std::vector<char> casts;
  b.add(*scene.root, Transform(), 0, true, false, objects_, casts);
  // The objects that cast no shadow (shadows="false").
  std::unordered_set<const Shape*> shadowless;
  for (size_t i = 0; i < objects_.size(); ++i)
    if (!casts[i]) shadowless.insert(objects_[i].get());

  std::vector<Shape*> bounded;
  for (const auto& o : objects_) {
    AABB box = o->bounds();
    if (box.isBounded() || box.empty())
      bounded.push_back(o.get());  // an empty box is left out by the BVH itself
    else all_.direct.push_back(o.get());
  }
  if (bounded.size() == 1 && !bounded[0]->bounds().empty()) {
    // A lone object (one mesh, say) culls rays itself: a tree above it would only add
    // a box test and a traversal per ray.
    all_.direct.push_back(bounded[0]);
    bounded.clear();
  }

  // Spheres under a similarity transform become world-space spheres. A field of a
  // million spheres then costs one 32-byte read per leaf test instead of following
  // the BVH's slot to the Instance, and the Instance to its Sphere, each a separate
  // allocation that misses the cache (docs/performance-history.md). The Instance stays the
  // hit's shape: surface() and the material work as before.
  std::vector<Leaf> leafOf(bounded.size(), Leaf{0.0, 0.0, 0.0, -1.0});
  std::vector<AABB> boxes(bounded.size());
  for (size_t i = 0; i < bounded.size(); ++i) {
    boxes[i] = bounded[i]->bounds();
    auto* inst = dynamic_cast<Instance*>(bounded[i]);
    const auto* sphere = inst ? dynamic_cast<const Sphere*>(&inst->shape()) : nullptr;
    if (!sphere) continue;
    auto image = sphereImage(inst->transform(), sphere->center(), sphere->radius());
    if (!image) continue;
    leafOf[i] =
        Leaf{image->center.x, image->center.y, image->center.z, image->radius * image->radius};
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
  // keep the default cost 1; a mixed world takes the mean.
  auto fill = [&](Objects& set, const std::vector<uint32_t>& items) {
    size_t spheres = 0;
    for (uint32_t i : items) spheres += leafOf[i].r2 >= 0.0;
    Bvh::Options options;
    if (!items.empty())
      options.itemCost =
          float((kInlineSphereCost * double(spheres) + double(items.size() - spheres)) /
                double(items.size()));
    set.bvh = Bvh(
        items.size(), [&](uint32_t k) { return boxes[items[k]]; }, options);
    // Keep the leaves in leaf order: the traversal then hands out positions in leaves.
    std::vector<uint32_t> order = set.bvh.takeOrder();
    set.leaves.reserve(order.size());
    set.leafObjects.reserve(order.size());
    for (uint32_t k : order) {
      set.leaves.push_back(leafOf[items[k]]);
      set.leafObjects.push_back(bounded[items[k]]);
    }
  };
  std::vector<uint32_t> every(bounded.size());
  for (uint32_t i = 0; i < every.size(); ++i) every[i] = i;
  fill(all_, every);

  // The objects that may transmit and cast shadows, each tested as all_ tests it (one by
  // one, or in a tree as the same kind of leaf), so that a walk through them finds the
  // same hits.
  auto castsNone = [&](const Shape* o) { return shadowless.count(o) != 0; };
  auto mayTransmit = [&](const Shape* o) {
    return !castsNone(o) && transmitsLight(*o, scene_.materials);
  };
  std::vector<uint32_t> clear;
  for (uint32_t i = 0; i < bounded.size(); ++i)
    if (mayTransmit(bounded[i])) clear.push_back(i);
  for (const Shape* o : all_.direct)
    if (mayTransmit(o)) transmissive_.direct.push_back(o);
  anyShadowless_ = !shadowless.empty();
  if (clear.empty() && transmissive_.direct.empty() && !anyShadowless_) return;
  if (!clear.empty() || !transmissive_.direct.empty()) {
    fill(transmissive_, clear);
    transmissive_.linearSearch = kLinearTransmissive;
  }
  auto flags = [&](const Shape* o) {
    return static_cast<uint8_t>((mayTransmit(o) ? kTransmits : 0) |
                                (castsNone(o) ? kShadowless : 0));
  };
  skip_.reserve(all_.direct.size() + all_.leafObjects.size());
  for (const Shape* o : all_.direct) skip_.push_back(flags(o));
  for (const Shape* o : all_.leafObjects) skip_.push_back(flags(o));
}

bool World::intersect(const Ray& ray, Hit& hit) const { return all_.intersect(ray, hit); }

bool World::intersectTransmissive(const Ray& ray, Hit& hit) const {
  return transmissive_.intersect(ray, hit);
}

bool World::Objects::intersect(const Ray& ray, Hit& hit) const {
  Ray r = ray;
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
    ++threadTestCounts[slotOf<SphereSpec>()];
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
  }
  return found || inTree;
}

void World::Objects::prefetchLeaves(uint32_t first, uint32_t count) const {
  const char* p = reinterpret_cast<const char*>(leaves.data() + first);
  const char* end = reinterpret_cast<const char*>(leaves.data() + first + count);
  // From the cache line holding the first record (the records are 32 bytes, aligned).
  for (p -= reinterpret_cast<uintptr_t>(p) & 63; p < end; p += 64) __builtin_prefetch(p);
}

bool World::Objects::slotOccluded(uint32_t slot, const Ray& ray) const {
  const Leaf& leaf = leaves[slot];
  if (leaf.r2 < 0.0) return leafObjects[slot]->occluded(ray);
  ++threadTestCounts[slotOf<SphereSpec>()];
  double t;
  return sphereHitDistance(Vec3(leaf.cx, leaf.cy, leaf.cz), leaf.r2, ray, t);
}

bool World::occluded(const Ray& ray) const { return occluder(ray) != kNoObject; }

World::ObjectId World::occluder(const Ray& ray, ObjectId first) const {
  if (!anyShadowless_) return findOccluder<0>(ray, first);
  return findOccluder<kShadowless>(ray, first);
}

World::ObjectId World::opaqueOccluder(const Ray& ray, ObjectId first) const {
  if (skip_.empty()) return findOccluder<0>(ray, first);
  return findOccluder<kTransmits | kShadowless>(ray, first);
}

template <uint8_t kSkip>
World::ObjectId World::findOccluder(const Ray& ray, ObjectId first) const {
  const std::integral_constant<uint8_t, kSkip> skipped;
  const auto& direct = all_.direct;
  const auto directCount = static_cast<ObjectId>(direct.size());
  if (first != kNoObject && !skips(first, skipped) &&
      (first < directCount ? direct[first]->occluded(ray)
                           : all_.slotOccluded(first - directCount, ray)))
    return first;
  // The BVH before the unbounded objects (an any-hit search may take them in any
  // order): a floor plane is tested by every shadow ray and blocks few, and this order
  // made such scenes markedly faster, which was measured, not explained
  // (docs/performance-history.md, "Shadow rays").
  ObjectId found = kNoObject;
  auto blocks = [&](uint32_t slot, const Ray& r) {
    const ObjectId id = directCount + slot;
    // `first` missed already
    if (id == first || skips(id, skipped) || !all_.slotOccluded(slot, r)) return false;
    found = id;
    return true;
  };
  all_.bvh.any(ray, blocks,
               [this](uint32_t first, uint32_t count) { all_.prefetchLeaves(first, count); });
  if (found != kNoObject) return found;
  for (ObjectId k = 0; k < directCount; ++k)
    if (k != first && !skips(k, skipped) && direct[k]->occluded(ray)) return k;
  return kNoObject;
}

const Shape* World::object(ObjectId id) const {
  if (id == kNoObject) return nullptr;
  return id < all_.direct.size() ? all_.direct[id] : all_.leafObjects[id - all_.direct.size()];
}

}  // namespace lucent
