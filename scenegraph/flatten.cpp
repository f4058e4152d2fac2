#include "flatten.h"

#include "primitives/box.h"

#include "light_group.h"
#include "located_error.h"

#include "csg/bounded.h"
#include "csg/clipped.h"
#include "csg/csg_node.h"
#include "csg/inverted.h"

#include <algorithm>
#include <cmath>
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
  for (const auto& c : node.clip) checkNode(*c, world);
  for (const auto& c : node.bound) checkNode(*c, world);
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

// Which rays see an object: shadow rays, camera rays (and those that went on through
// surfaces from the camera), reflected rays. A union whose children differ is split.
struct Seen {
  bool casts = true;       // it casts shadows (shadows="false" clears it)
  bool image = true;       // image="false" clears it
  bool reflection = true;  // reflection="false" clears it
  bool operator==(const Seen& o) const {
    return casts == o.casts && image == o.image && reflection == o.reflection;
  }
  bool operator!=(const Seen& o) const { return !(*this == o); }
};

// The node's own flags under those of its ancestors.
Seen seenBelow(const Seen& above, const Node& node) {
  return {above.casts && node.shadows, above.image && node.image,
          above.reflection && node.reflection};
}

// What a node passes down to its children: its material, interior material and whether
// its surfaces are lit from both sides.
struct Inherited {
  uint32_t material = 0;
  std::optional<uint32_t> interior;
  bool doubleIlluminate = false;
  LightGroupScope lights;

  Inherited below(const Node& node) const {
    return {node.material.value_or(material),
            node.interiorMaterial ? node.interiorMaterial : interior,
            doubleIlluminate || node.doubleIlluminate, lights};
  }
};

// An object being built, with what its leaves say of it.
struct Part {
  std::unique_ptr<Shape> shape;
  uint32_t firstLeaf = 0;  // its first leaf in scene order: a solid's medium is its material
  Seen seen;
  bool transmits = false;  // one of its leaves has a transmissive material
  // All its leaves (a split union's parts need not be consecutive).
  std::vector<uint32_t> leaves;
};

// The parts as one object: the operation `op` of their shapes (all of them non-empty).
Part compose(CsgOp op, std::vector<Part> parts, const Seen& seen) {
  Part whole;
  whole.firstLeaf = parts.front().firstLeaf;
  whole.seen = seen;
  std::vector<std::unique_ptr<Shape>> shapes;
  for (Part& p : parts) {
    whole.transmits = whole.transmits || p.transmits;
    whole.leaves.insert(whole.leaves.end(), p.leaves.begin(), p.leaves.end());
    shapes.push_back(std::move(p.shape));
  }
  whole.shape = std::make_unique<CsgNode>(op, std::move(shapes));
  return whole;
}

struct Builder {
  const Scene& scene;
  const ShapeMaker& makeShape;
  // A shape reached through several <use>s is built once; without <use>s every shape is
  // reached once, and the map (a hash per node of a million) is skipped.
  bool share;
  std::unordered_map<const Node*, std::shared_ptr<const Shape>> shapes;
  std::vector<WorldLeaf>& leaves;
  // The light groups met so far, in placeLights' order (scenegraph/light_group.h).
  uint32_t lightGroups = 0;
  // Where the blobs' component materials go (null: a solid whose materials do not matter).
  std::deque<std::vector<uint32_t>>* componentMaterials = nullptr;

  // Adds the node's objects to `out`.
  // `inSolid`: the node is (inside) an operand of a merge, intersection or difference,
  // which shows and casts its shadow as a whole: the flags of its parts are not consulted.
  // `invert`: inverted once more (a subtrahend of a difference written as an intersection).
  void add(const Node& node, const Transform& parentWorld, const Inherited& inherited,
           const Seen& above, bool inSolid, std::vector<Part>& out, bool invert = false) {
    const size_t first = out.size();
    if (node.inverse != invert) addInverted(node, parentWorld, inherited, above, inSolid, out);
    else addPlain(node, parentWorld, inherited, above, inSolid, out);
    if (node.clip.empty() && node.bound.empty()) return;
    // The clip tests points of the (possibly inverted) surface, as POV-Ray's, and the bound
    // the ray before anything else; both are in the node's frame.
    const Transform world = nodeWorld(node, parentWorld);
    const AABB within = node.clip.empty() ? AABB::everything() : clipBox(node.clip, world);
    for (size_t i = first; i < out.size(); ++i) {
      if (!node.clip.empty())
        out[i].shape =
            std::make_unique<Clipped>(std::move(out[i].shape), solids(node.clip, world), within);
      if (!node.bound.empty())
        out[i].shape =
            std::make_unique<Bounded>(std::move(out[i].shape), solids(node.bound, world));
    }
  }

  // A world box that holds the clips' common part, met in the clips' own frame: there a
  // clip of planes square to the axes and an infinite cylinder along one (a slab of it) has
  // a finite box, which the world's frame turns into an unbounded one when the object is
  // rotated (POV-Ray's Helix of shapesq.inc, clipped by Cylinder_Z and two planes).
  AABB clipBox(const std::vector<std::unique_ptr<Node>>& clip, const Transform& world) {
    const size_t leavesBefore = leaves.size();  // these solids are only measured
    AABB local = AABB::everything();
    for (const auto& s : solids(clip, Transform())) local = AABB::meet(local, s->bounds());
    leaves.erase(leaves.begin() + static_cast<std::ptrdiff_t>(leavesBefore), leaves.end());
    if (!local.isBounded()) return AABB::everything();
    return transformBounds(world.worldFromObject(), local);
  }

  // The solids of a <clip> or <bound>, each one shape (a union of its parts when it has
  // several), placed below `world`. Their leaves are never hit, so no material matters.
  std::vector<std::unique_ptr<Shape>> solids(const std::vector<std::unique_ptr<Node>>& nodes,
                                             const Transform& world) {
    std::vector<std::unique_ptr<Shape>> shapes;
    // Nothing lights a clip's leaves: its groups are not numbered.
    const uint32_t groupsBefore = lightGroups;
    for (const auto& n : nodes)
      if (auto shape = oneShape(*n, world)) shapes.push_back(std::move(shape));
    lightGroups = groupsBefore;
    return shapes;
  }

  // The node's geometry below `world` as one shape, as an operand of a solid (one union of
  // its parts when it has several, never split by shadow flags); null when it has none.
  std::unique_ptr<Shape> oneShape(const Node& node, const Transform& world) {
    std::vector<Part> parts;
    add(node, world, Inherited{}, Seen{}, true, parts);
    if (parts.empty()) return nullptr;
    if (parts.size() == 1) return std::move(parts.front().shape);
    return compose(CsgOp::Union, std::move(parts), Seen{}).shape;
  }

  // The node's shape. A shape's own constructor refuses degenerate parameters (a cylinder
  // whose cap is its base) with std::invalid_argument; the parsers refuse them first, but a
  // scene made otherwise (the POV-Ray importer) is refused here, at the node.
  std::shared_ptr<const Shape> made(const Node& node) {
    try {
      return makeShape(*node.shape);
    } catch (const std::invalid_argument& e) {
      throw LocatedError(node.loc, e.what());
    }
  }

  // A leaf: its Instance, tagged with its index in `leaves`.
  Part addLeaf(const Node& node, const Transform& world, const Inherited& inherited,
               const Seen& seen) {
    std::shared_ptr<const Shape> shape;
    const auto* patch = std::get_if<BicubicPatchSpec>(&*node.shape);
    if (patch && patch->flatnessInWorld) {
      // Cut where it is flat in the world, as POV-Ray cuts it: built for this placement.
      BicubicPatchSpec placed = *patch;
      placed.flatnessFrame = std::make_shared<const Mat4>(world.worldFromObject());
      try {
        shape = makeShape(ShapeSpec(placed));
      } catch (const std::invalid_argument& e) {
        throw LocatedError(node.loc, e.what());
      }
    } else if (share) {
      auto& shared = shapes[&node];
      if (!shared) shared = made(node);
      shape = shared;
    } else {
      shape = made(node);
    }
    const auto index = static_cast<uint32_t>(leaves.size());
    auto inst = std::make_unique<Instance>(std::move(shape), world, index, node.shape->index());
    WorldLeaf leaf;
    leaf.instance = inst.get();
    leaf.materialIndex = inherited.material;
    leaf.material = &scene.materials[inherited.material];
    leaf.medium = inst->isSolid() ? leaf.material : nullptr;
    leaf.transmissive = leaf.material->isTransmissive();
    if (inherited.interior && *inherited.interior != inherited.material) {
      leaf.interiorIndex = *inherited.interior;
      leaf.interior = &scene.materials[*inherited.interior];
    }
    leaf.doubleIlluminate = inherited.doubleIlluminate;
    leaf.uvMapped =
        usesUvMapping(*leaf.material) || (leaf.interior && usesUvMapping(*leaf.interior));
    const auto* blob = std::get_if<BlobSpec>(&*node.shape);
    if (blob && !blob->componentMaterials.empty() && componentMaterials) {
      std::vector<uint32_t>& list = componentMaterials->emplace_back();
      for (const auto& own : blob->componentMaterials) {
        const uint32_t m = own.value_or(inherited.material);
        list.push_back(m);
        leaf.transmissive |= scene.materials[m].isTransmissive();
        leaf.uvMapped |= usesUvMapping(scene.materials[m]);
      }
      leaf.componentMaterials = &list;
    }
    leaf.lightGroup = inherited.lights.group;
    leaf.globalLights = inherited.lights.globalLights();
    leaves.push_back(leaf);
    // A shadow ray may cross the surface from inside: the interior material's k_t counts.
    const bool transmits = leaf.transmissive || (leaf.interior && leaf.interior->isTransmissive());
    return Part{std::move(inst), index, seen, transmits, {index}};
  }

  // The node's objects as written, its own inverse aside.
  void addPlain(const Node& node, const Transform& parentWorld, const Inherited& inherited,
                const Seen& above, bool inSolid, std::vector<Part>& out) {
    Transform world = nodeWorld(node, parentWorld);
    Inherited here = inherited.below(node);
    if (node.lightGroup) here.lights = here.lights.inside(node, ++lightGroups);
    const Seen seen = inSolid ? Seen{} : seenBelow(above, node);

    switch (node.kind) {
      case NodeKind::Shape:
        out.push_back(addLeaf(node, world, here, seen));
        break;
      case NodeKind::Group:
        for (const auto& c : node.children) add(*c, world, here, seen, inSolid, out);
        break;
      case NodeKind::Use:
        // The referenced node's own transform applies first, then the <use>'s.
        add(*node.target, world, here, seen, inSolid, out);
        break;
      case NodeKind::Light:
        break;  // placed by placeLights, not built
      case NodeKind::Union:
        addUnion(node, world, here, seen, inSolid, out);
        break;
      case NodeKind::Merge:
      case NodeKind::Intersection:
      case NodeKind::Difference: {
        std::vector<Part> children;
        if (node.kind == NodeKind::Difference && clippedSubtrahend(node)) {
          // POV-Ray's difference is the intersection with the others inverted, and inverting
          // a clipped object leaves its clip as it is: inside the subtrahend is then inside
          // its clip and outside its shape. Written so, the same result.
          for (size_t i = 0; i < node.children.size(); ++i)
            add(*node.children[i], world, here, Seen{}, true, children, i > 0);
          if (children.empty()) break;
          out.push_back(compose(CsgOp::Intersection, std::move(children), seen));
          break;
        }
        for (const auto& c : node.children) add(*c, world, here, Seen{}, true, children);
        if (children.empty()) break;
        out.push_back(compose(csgOpOf(node.kind), std::move(children), seen));
        break;
      }
    }
  }

  // A union: one object, or one per set of flags its children have (POV-Ray splits every
  // union into its children), which together show and hold the same as one.
  void addUnion(const Node& node, const Transform& world, const Inherited& here, const Seen& seen,
                bool inSolid, std::vector<Part>& out) {
    std::vector<Part> children;
    for (const auto& c : node.children) add(*c, world, here, seen, inSolid, children);
    while (!children.empty()) {
      const Seen flags = children.front().seen;
      std::vector<Part> part, rest;
      for (Part& c : children) (c.seen == flags ? part : rest).push_back(std::move(c));
      out.push_back(compose(CsgOp::Union, std::move(part), flags));
      children = std::move(rest);
    }
  }

  static bool clippedSubtrahend(const Node& difference) {
    if (difference.children.size() < 2) return false;
    return std::any_of(difference.children.begin() + 1, difference.children.end(),
                       [](const auto& c) { return !c->clip.empty(); });
  }

  // inverse="true": the node's objects as one solid (a union of them when there are
  // several, unsplit by their flags: the inverse of a union is not the union of the
  // inverses), inside out. It is seen and casts shadows as the node says.
  void addInverted(const Node& node, const Transform& parentWorld, const Inherited& inherited,
                   const Seen& above, bool inSolid, std::vector<Part>& out) {
    std::vector<Part> parts;
    addPlain(node, parentWorld, inherited, above, inSolid, parts);
    if (parts.empty()) return;
    const Seen seen = inSolid ? Seen{} : seenBelow(above, node);
    Part solid = parts.size() == 1 ? std::move(parts.front())
                                   : compose(CsgOp::Union, std::move(parts), seen);
    solid.seen = seen;
    solid.shape = std::make_unique<Inverted>(std::move(solid.shape));
    out.push_back(std::move(solid));
  }
};

// Where a light's projected-through objects stand; throws when its frame is flat.
Transform projectionWorld(const Light& light) {
  const std::optional<Transform> world = Transform::fromMatrix(light.worldFromLight);
  if (!world)
    throw LocatedError(light.loc,
                       "the transforms down to this light flatten its projected-through objects");
  return *world;
}

}  // namespace

// The nodes, then the lights' projected-through objects where buildProjection puts them.
void checkWorld(const Scene& scene) {
  checkNode(*scene.root, Transform());
  for (const Light& light : scene.lights)
    if (light.projectedThrough) checkNode(*light.projectedThrough, projectionWorld(light));
}

std::unique_ptr<Shape> buildSolid(const Scene& scene, const Node& node,
                                  const ShapeMaker& makeShape) {
  // POV-Ray's box counts its faces inside (Box::Inside): an object pattern's boxes do too,
  // so a surface lying in a box's face takes the inside entry, as in POV-Ray.
  const ShapeMaker closedBoxes = [&](const ShapeSpec& spec) -> std::shared_ptr<const Shape> {
    std::shared_ptr<const Shape> shape = makeShape(spec);
    const auto* box = dynamic_cast<const Box*>(shape.get());
    if (!box) return shape;
    auto closed = std::make_shared<Box>(*box);
    closed->closeFaces();
    return closed;
  };
  std::vector<WorldLeaf> leaves;  // never looked up: only inside() is asked
  Builder b{scene, closedBoxes, true, {}, leaves};
  return b.oneShape(node, Transform());
}

std::unique_ptr<Shape> buildProjection(const Scene& scene, const Light& light,
                                       const ShapeMaker& makeShape) {
  if (!light.projectedThrough) return nullptr;
  const Transform world = projectionWorld(light);
  std::vector<WorldLeaf> leaves;  // never looked up: only intersect() is asked
  Builder b{scene, makeShape, true, {}, leaves};
  return b.oneShape(*light.projectedThrough, world);
}

FlatScene flattenScene(const Scene& scene, const ShapeMaker& makeShape) {
  FlatScene flat;
  Builder b{scene, makeShape, hasUses(scene), {}, flat.leaves};
  b.componentMaterials = &flat.componentMaterials;
  std::vector<Part> parts;
  b.add(*scene.root, Transform(), Inherited{}, Seen{}, false, parts);
  flat.objects.reserve(parts.size());
  for (Part& p : parts) {
    WorldObject o;
    o.medium = p.shape->isSolid() ? flat.leaves[p.firstLeaf].material : nullptr;
    for (uint32_t i : p.leaves)
      if (flat.leaves[i].medium) flat.leaves[i].solidMedium = o.medium;
    o.castsShadow = p.seen.casts;
    o.seenByImage = p.seen.image;
    o.seenByReflection = p.seen.reflection;
    o.transmits = p.transmits;
    o.shape = std::move(p.shape);
    flat.objects.push_back(std::move(o));
  }
  return flat;
}

}  // namespace lucent
