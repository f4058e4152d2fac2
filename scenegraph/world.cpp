#include "world.h"

#include "make_shape.h"

#include "csg/csg_node.h"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace lucent {

namespace {

bool finiteTransform(const Transform& t) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(t.worldFromObject()[c][r]) || !std::isfinite(t.objectFromWorld()[c][r]))
        return false;
  return true;
}

CsgOp csgOpOf(NodeKind k) {
  switch (k) {
    case NodeKind::Union: return CsgOp::Union;
    case NodeKind::Merge: return CsgOp::Merge;
    case NodeKind::Intersection: return CsgOp::Intersection;
    default: return CsgOp::Difference;
  }
}

struct Builder {
  const ShapeMaker& makeShape;
  std::unordered_map<const Node*, std::shared_ptr<const Shape>> shapes;  // built once per node
  std::vector<const Instance*>& instances;

  void add(const Node& node, const Transform& parentWorld, uint32_t inherited,
           std::vector<std::unique_ptr<Shape>>& out) {
    auto local = Transform::fromMatrix(node.parentFromNode);
    if (!local) throw std::runtime_error(node.loc.str() + ": error: singular transform");
    Transform world = local->followedBy(parentWorld);
    // Each transform is finite, but nested ones multiply (twenty groups of scale(1e30)).
    if (!finiteTransform(world))
      throw std::runtime_error(node.loc.str() +
                               ": error: the transforms down to this node multiply beyond double range");
    uint32_t material = node.material.value_or(inherited);

    switch (node.kind) {
      case NodeKind::Shape: {
        auto& shape = shapes[&node];
        if (!shape) shape = makeShape(*node.shape);
        auto inst = std::make_unique<Instance>(shape, world, material);
        instances.push_back(inst.get());
        out.push_back(std::move(inst));
        break;
      }
      case NodeKind::Group:
        for (const auto& c : node.children) add(*c, world, material, out);
        break;
      case NodeKind::Use:
        // The referenced node's own transform applies first, then the <use>'s.
        add(*node.target, world, material, out);
        break;
      case NodeKind::Union:
      case NodeKind::Merge:
      case NodeKind::Intersection:
      case NodeKind::Difference: {
        std::vector<std::unique_ptr<Shape>> children;
        for (const auto& c : node.children) add(*c, world, material, children);
        if (!children.empty())
          out.push_back(std::make_unique<CsgNode>(csgOpOf(node.kind), std::move(children)));
        break;
      }
    }
  }
};

}  // namespace

World::World(const Scene& scene) : World(scene, makeShape) {}

World::World(const Scene& scene, const ShapeMaker& make) : scene_(scene) {
  Builder b{make, {}, instances_};
  b.add(*scene.root, Transform(), 0, objects_);

  std::vector<const Shape*> bounded;
  for (const auto& o : objects_) {
    AABB box = o->bounds();
    if (box.isBounded() || box.empty())
      bounded.push_back(o.get());  // an empty box is left out by the BVH itself
    else
      direct_.push_back(o.get());
  }
  if (bounded.size() == 1 && !bounded[0]->bounds().empty()) {
    // A lone object (one mesh, say) culls rays itself: a tree above it would only add
    // a box test and a traversal per ray.
    direct_.push_back(bounded[0]);
    bounded.clear();
  }
  bvh_ = Bvh(bounded.size(), [&](uint32_t i) { return bounded[i]->bounds(); });
  // Keep the objects in leaf order: the traversal then hands out positions in bounded_.
  for (uint32_t i : bvh_.takeOrder()) bounded_.push_back(bounded[i]);
}

bool World::intersect(const Ray& ray, Hit& hit) const {
  Ray r = ray;
  bool found = false;
  for (const Shape* o : direct_) {
    if (o->intersect(r, hit)) {
      r.tmax = hit.t;
      found = true;
    }
  }
  // The BVH search starts with tmax already at the nearest direct hit, if any.
  bool inTree = bvh_.closest(r, [&](uint32_t i, Ray& rr) {
    if (!bounded_[i]->intersect(rr, hit)) return false;
    rr.tmax = hit.t;
    return true;
  });
  return found || inTree;
}

bool World::occluded(const Ray& ray) const {
  for (const Shape* o : direct_)
    if (o->occluded(ray)) return true;
  return bvh_.any(ray, [&](uint32_t i, const Ray& r) { return bounded_[i]->occluded(r); });
}

}  // namespace lucent
