#include "open_operands.h"

#include "scenegraph/light.h"
#include "scenegraph/shape_registry.h"

#include <memory>
#include <utility>
#include <vector>

namespace lucent::sdl {

namespace {

// Whether POV-Ray's Inside is false everywhere in n: a triangle, polygon, bicubic patch,
// parametric or mesh without an inside (Lucent's open mesh), or groups of such. (Not a
// disc: POV-Ray's disc is inside below its plane, a half-space its surface does not cover.)
bool holdsNoSolid(const Node& n) {
  switch (n.kind) {
    case NodeKind::Shape:
      return n.shape && !isSolid(*n.shape) &&
             (std::holds_alternative<TriangleSpec>(*n.shape) ||
              std::holds_alternative<PolygonSpec>(*n.shape) ||
              std::holds_alternative<BicubicPatchSpec>(*n.shape) ||
              std::holds_alternative<ParametricSpec>(*n.shape) ||
              std::holds_alternative<MeshSpec>(*n.shape));
    case NodeKind::Use:
      return n.target && holdsNoSolid(*n.target);
    case NodeKind::Union:
    case NodeKind::Group:
      for (const auto& c : n.children)
        if (!c->isLight() && !holdsNoSolid(*c)) return false;
      return !n.children.empty();
    case NodeKind::Merge:
    case NodeKind::Intersection:
    case NodeKind::Difference:
      return false;
    case NodeKind::Light:
      return false;
  }
  return false;
}

// A deep copy: every field of Node, its subtrees copied too.
std::unique_ptr<Node> copyOf(const Node& n) {
  auto c = std::make_unique<Node>();
  c->kind = n.kind;
  c->element = n.element;
  c->id = n.id;
  c->loc = n.loc;
  c->parentFromNode = n.parentFromNode;
  c->material = n.material;
  c->shadows = n.shadows;
  c->image = n.image;
  c->reflection = n.reflection;
  c->doubleIlluminate = n.doubleIlluminate;
  c->interiorMaterial = n.interiorMaterial;
  c->inverse = n.inverse;
  c->lightGroup = n.lightGroup;
  c->globalLights = n.globalLights;
  for (const auto& k : n.clip) c->clip.push_back(copyOf(*k));
  for (const auto& k : n.bound) c->bound.push_back(copyOf(*k));
  c->shape = n.shape;
  for (const auto& k : n.children) c->children.push_back(copyOf(*k));
  c->target = n.target;
  if (n.light) c->light = std::make_unique<Light>(*n.light);
  return c;
}

// `solid` as a clip of `open` (in open's own frame), inside it or, `outside`, inverted.
void clipBy(Node& open, const Node& solid, bool outside) {
  std::unique_ptr<Node> c = copyOf(solid);
  c->parentFromNode = glm::inverse(open.parentFromNode) * solid.parentFromNode;
  if (outside) c->inverse = !c->inverse;
  open.clip.push_back(std::move(c));
}

}  // namespace

bool rewriteOpenOperands(Node& csg) {
  if (csg.kind != NodeKind::Merge && csg.kind != NodeKind::Intersection &&
      csg.kind != NodeKind::Difference)
    return true;
  // The operands in order (lights aside); each a solid or open, else nothing is changed.
  std::vector<std::unique_ptr<Node>> lights, operands;
  std::vector<bool> open;
  bool anyOpen = false;
  for (const auto& c : csg.children) {
    if (c->isLight()) continue;
    const bool isOpen = holdsNoSolid(*c);
    if (!isOpen && !c->isSolid()) return true;  // a union of both: left as it was
    anyOpen = anyOpen || isOpen;
  }
  if (!anyOpen) return true;
  for (auto& c : csg.children) {
    if (c->isLight()) {
      lights.push_back(std::move(c));
      continue;
    }
    open.push_back(holdsNoSolid(*c));
    // Only the whole operation's no_shadow, no_image, no_reflection count (now the union's).
    c->shadows = c->image = c->reflection = true;
    operands.push_back(std::move(c));
  }
  csg.children.clear();
  const NodeKind kind = csg.kind;
  std::vector<std::unique_ptr<Node>> kept;
  std::vector<size_t> solids;
  size_t openCount = 0;
  for (size_t i = 0; i < operands.size(); ++i) {
    if (open[i]) ++openCount;
    else solids.push_back(i);
  }
  if (kind == NodeKind::Merge) {
    // A surface is kept where no other operand is inside: the solids merged as they are,
    // each open operand outside every solid.
    for (size_t i = 0; i < operands.size(); ++i) {
      if (!open[i]) continue;
      auto piece = copyOf(*operands[i]);
      for (size_t j : solids) clipBy(*piece, *operands[j], true);
      kept.push_back(std::move(piece));
    }
    if (solids.size() == 1) {
      kept.insert(kept.begin(), std::move(operands[solids[0]]));
    } else if (solids.size() > 1) {
      auto part = std::make_unique<Node>();
      part->kind = kind;
      part->element = csg.element;
      part->loc = csg.loc;
      for (size_t j : solids) part->children.push_back(std::move(operands[j]));
      kept.insert(kept.begin(), std::move(part));
    }
  } else if (openCount == 1) {
    // An intersection or difference keeps a surface where every other operand (inverted,
    // for a difference's later ones) is inside. An open operand is never inside, inverted
    // or not (POV-Ray's Inside of it is false whatever its inverse flag): only the open
    // operand's surface can show, inside each solid of an intersection, inside a
    // difference's first operand and outside its later ones.
    size_t k = 0;
    while (!open[k]) ++k;
    auto piece = std::move(operands[k]);
    for (size_t j : solids) clipBy(*piece, *operands[j], kind == NodeKind::Difference && j > 0);
    kept.push_back(std::move(piece));
  }
  // Two open operands or more in an intersection or difference: nothing is kept.
  csg.kind = NodeKind::Union;
  csg.element = "union";
  for (auto& k : kept) csg.children.push_back(std::move(k));
  for (auto& l : lights) csg.children.push_back(std::move(l));
  return !csg.children.empty();
}

}  // namespace lucent::sdl
