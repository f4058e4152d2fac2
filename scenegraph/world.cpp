#include "world.h"

#include "make_shape.h"

#include "csg/csg_node.h"

#include <stdexcept>
#include <unordered_map>

namespace lucent {

namespace {

CsgOp csgOpOf(NodeKind k) {
  switch (k) {
    case NodeKind::Union: return CsgOp::Union;
    case NodeKind::Merge: return CsgOp::Merge;
    case NodeKind::Intersection: return CsgOp::Intersection;
    default: return CsgOp::Difference;
  }
}

struct Builder {
  std::unordered_map<const Node*, std::shared_ptr<const Shape>> shapes;  // built once per node
  std::vector<const Instance*>& instances;

  void add(const Node& node, const Transform& parentWorld, uint32_t inherited,
           std::vector<std::unique_ptr<Shape>>& out) {
    auto local = Transform::fromMatrix(node.parentFromNode);
    if (!local) throw std::runtime_error(node.loc.str() + ": error: singular transform");
    Transform world = local->followedBy(parentWorld);
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

World::World(const Scene& scene) : scene_(scene) {
  Builder b{{}, instances_};
  b.add(*scene.root, Transform(), 0, objects_);
}

bool World::intersect(const Ray& ray, Hit& hit) const {
  // A plain loop for now; the acceleration structure replaces it.
  Ray r = ray;
  bool found = false;
  for (const auto& o : objects_) {
    if (o->intersect(r, hit)) {
      r.tmax = hit.t;
      found = true;
    }
  }
  return found;
}

bool World::occluded(const Ray& ray) const {
  for (const auto& o : objects_)
    if (o->occluded(ray)) return true;
  return false;
}

}  // namespace lucent
