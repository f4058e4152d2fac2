#include "world.h"

#include "located_error.h"
#include "shape_registry.h"

#include "csg/csg_node.h"
#include "csg/inverted.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lucent {

namespace {

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

  // Each object's mask: whether it may transmit light (a leaf with a transmissive
  // material, and it casts shadows), whether it casts none (shadows="false").
  std::vector<Aggregate::Object> items;
  items.reserve(objects_.size());
  for (size_t i = 0; i < objects_.size(); ++i) {
    const bool transmits = casts[i] && transmitsLight(*objects_[i], scene_.materials);
    items.push_back(
        {objects_[i].get(), static_cast<Aggregate::Mask>((transmits ? kTransmits : 0) |
                                                         (casts[i] ? 0 : kShadowless))});
  }
  Aggregate::Options options;
  options.selected = kTransmits;
  options.linearSelected = kLinearTransmissive;
  options.sphereTestSlot = slotOf<SphereSpec>();
  aggregate_ = Aggregate(items, options);
}

}  // namespace lucent
