#include "open_operands.h"

#include "scenegraph/light.h"
#include "scenegraph/shape_registry.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace lucent::sdl {

namespace {

// Whether POV-Ray's Inside is false everywhere in n: a triangle, polygon, bicubic patch,
// parametric or mesh without an inside (Lucent's open mesh).
bool hasNoInside(const Node& n) {
  return n.kind == NodeKind::Shape && n.shape && !isSolid(*n.shape) &&
         (std::holds_alternative<TriangleSpec>(*n.shape) ||
          std::holds_alternative<PolygonSpec>(*n.shape) ||
          std::holds_alternative<BicubicPatchSpec>(*n.shape) ||
          std::holds_alternative<ParametricSpec>(*n.shape) ||
          std::holds_alternative<MeshSpec>(*n.shape));
}

const DiscSpec* discOf(const Node& n) {
  return n.kind == NodeKind::Shape && n.shape ? std::get_if<DiscSpec>(&*n.shape) : nullptr;
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

std::unique_ptr<Node> copyOrNull(const std::unique_ptr<Node>& n) {
  return n ? copyOf(*n) : nullptr;
}

// A solid as a clip: its lights and bounds play no part.
std::unique_ptr<Node> asClipper(const Node& solid, bool inverted) {
  std::unique_ptr<Node> c = copyOf(solid);
  c->bound.clear();
  c->children.erase(std::remove_if(c->children.begin(), c->children.end(),
                                   [](const auto& k) { return k->isLight(); }),
                    c->children.end());
  if (inverted) c->inverse = !c->inverse;
  return c;
}

// A CSG node of `kind` around `parts` in a frame and under clips of `like` (null for the
// identity and no clips). Null when there are no parts.
std::unique_ptr<Node> operation(NodeKind kind, std::vector<std::unique_ptr<Node>> parts,
                                const Node& like, bool framed) {
  if (parts.empty()) return nullptr;
  auto n = std::make_unique<Node>();
  n->kind = kind;
  n->element = nodeKindName(kind);
  n->loc = like.loc;
  if (framed) {
    n->parentFromNode = like.parentFromNode;
    for (const auto& k : like.clip) n->clip.push_back(asClipper(*k, false));
  }
  n->children = std::move(parts);
  return n;
}

// Clips `piece` (in the operation's frame) to `solid` (in the same frame), inverted or not.
void clipTo(Node& piece, const Node& solid, bool inverted) {
  std::unique_ptr<Node> c = asClipper(solid, inverted);
  c->parentFromNode = glm::inverse(piece.parentFromNode) * c->parentFromNode;
  piece.clip.push_back(std::move(c));
}

// Whether the solid o (in the operation's frame) projects onto the disc's plane within its
// radius: a sphere's ellipsoid by its centre and its largest axis in the plane (by power
// iteration), any other solid by the corners of its box.
bool projectsWithin(const Node& o, const Mat4& discFromCsg, const DiscSpec& d) {
  const Mat4 m = discFromCsg * o.parentFromNode;
  const Mat3 inPlane = Mat3(1.0) - glm::outerProduct(d.normal, d.normal);
  const auto offset = [&](const Vec3& p) { return glm::length(inPlane * (p - d.center)); };
  if (const SphereSpec* s = o.kind == NodeKind::Shape && o.shape && o.clip.empty()
                                ? std::get_if<SphereSpec>(&*o.shape)
                                : nullptr) {
    const Mat3 a = inPlane * Mat3(m) * s->radius;
    const Mat3 ata = glm::transpose(a) * a;
    Vec3 v(0.5773502691896258);
    double largest = 0.0;
    for (int k = 0; k < 64; ++k) {
      const Vec3 w = ata * v;
      const double len = glm::length(w);
      if (!(len > 0.0)) break;
      largest = len;
      v = w / len;
    }
    // Power iteration approaches the largest eigenvalue from below: a margin of 1e-9.
    return offset(Vec3(m * Vec4(s->center, 1.0))) + std::sqrt(largest) * (1.0 + 1e-9) <= d.radius;
  }
  const AABB box = nodeBox(o, Mat4(1.0));
  if (!box.isBounded() || box.empty()) return false;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                      (k & 4) ? box.hi.z : box.lo.z);
    if (offset(Vec3(discFromCsg * Vec4(corner, 1.0))) > d.radius) return false;
  }
  return true;
}

bool isOperationName(const std::string& element) {
  return element == "merge" || element == "intersection" || element == "difference";
}

}  // namespace

const OpenOperands::Rewritten* OpenOperands::rewritten(const Node& n) const {
  if (n.kind != NodeKind::Union || !isOperationName(n.element)) return nullptr;
  const auto it = rewritten_.find(&n);
  return it == rewritten_.end() ? nullptr : &it->second;
}

const AABB* OpenOperands::povBox(const Node& n) const {
  const Rewritten* r = rewritten(n);
  return r ? &r->box : nullptr;
}

bool OpenOperands::insidesOf(const Node& n, PovInsides& out) const {
  if (const Rewritten* r = rewritten(n)) {
    out.in = copyOrNull(r->insides.in);
    out.inverted = copyOrNull(r->insides.inverted);
    return true;
  }
  if (n.kind == NodeKind::Union && isOperationName(n.element)) return false;  // not known
  if (n.isSolid()) {
    out.in = asClipper(n, false);
    out.inverted = asClipper(n, true);
    return true;
  }
  if (hasNoInside(n)) {
    out = {};
    return true;
  }
  if (const DiscSpec* d = discOf(n)) {
    // POV-Ray's disc is inside where its z < 0: below its plane; its clips as the disc's.
    auto plane = std::make_unique<Node>();
    plane->kind = NodeKind::Shape;
    plane->element = "plane";
    plane->loc = n.loc;
    plane->parentFromNode = n.parentFromNode;
    plane->shape = PlaneSpec{d->normal, glm::dot(d->normal, d->center)};
    plane->inverse = n.inverse;
    for (const auto& k : n.clip) plane->clip.push_back(asClipper(*k, false));
    out.inverted = copyOf(*plane);
    out.inverted->inverse = !out.inverted->inverse;
    out.in = std::move(plane);
    return true;
  }
  if ((n.kind == NodeKind::Union || n.kind == NodeKind::Group) && !n.inverse) {
    // A union is inside where any part is; inverted, POV-Ray inverts each part and makes
    // the union an intersection.
    std::vector<std::unique_ptr<Node>> ins, inverteds;
    bool invertedNowhere = false;
    for (const auto& c : n.children) {
      if (c->isLight()) continue;
      PovInsides part;
      if (!insidesOf(*c, part)) return false;
      if (part.in) ins.push_back(std::move(part.in));
      if (part.inverted) inverteds.push_back(std::move(part.inverted));
      else invertedNowhere = true;
    }
    out.in = operation(NodeKind::Union, std::move(ins), n, true);
    out.inverted = invertedNowhere
                       ? nullptr
                       : operation(NodeKind::Intersection, std::move(inverteds), n, true);
    return true;
  }
  return false;
}

bool OpenOperands::invertSurfaces(Node& n) const {
  if ((n.kind != NodeKind::Union && n.kind != NodeKind::Group) || rewritten(n)) return true;
  const size_t count = n.children.size();
  std::vector<PovInsides> parts(count);
  std::vector<bool> light(count);
  for (size_t k = 0; k < count; ++k) {
    light[k] = n.children[k]->isLight();
    if (!light[k] && !insidesOf(*n.children[k], parts[k])) return true;
  }
  // Each part clipped by the others' insides inverted (all worked out before any changes).
  std::vector<bool> keep(count, true);
  for (size_t k = 0; k < count; ++k) {
    if (light[k]) continue;
    Node& c = *n.children[k];
    keep[k] = invertSurfaces(c);
    for (size_t m = 0; m < count && keep[k]; ++m) {
      if (m == k || light[m]) continue;
      if (!parts[m].inverted) keep[k] = false;
      else clipTo(c, *parts[m].inverted, false);
    }
  }
  std::vector<std::unique_ptr<Node>> kept;
  bool any = false;
  for (size_t k = 0; k < count; ++k)
    if (keep[k]) {
      any = any || !light[k];
      kept.push_back(std::move(n.children[k]));
    }
  n.children = std::move(kept);
  return any;
}

bool OpenOperands::closeCoveredDiscs(Node& csg) const {
  if (csg.kind != NodeKind::Intersection && csg.kind != NodeKind::Difference) return false;
  // A disc's surface is kept inside the others (an intersection's) or inside the first
  // operand (a difference's later disc): it covers the cut when one of those operands
  // projects onto its plane within its radius.
  bool changed = false;
  for (size_t i = 0; i < csg.children.size(); ++i) {
    Node& c = *csg.children[i];
    const DiscSpec* d = discOf(c);
    if (!d || d->innerRadius > 0.0 || !c.clip.empty() || c.inverse) continue;
    if (csg.kind == NodeKind::Difference && i == 0) continue;
    const Mat4 discFromCsg = glm::inverse(c.parentFromNode);
    bool covered = false;
    for (size_t j = 0; j < csg.children.size() && !covered; ++j) {
      const Node& o = *csg.children[j];
      if (j == i || o.isLight() || (csg.kind == NodeKind::Difference && j > 0)) continue;
      if (o.isSolid() && !rewritten(o)) covered = projectsWithin(o, discFromCsg, *d);
    }
    if (!covered) continue;
    c.shape = PlaneSpec{d->normal, glm::dot(d->normal, d->center)};
    c.element = "plane";
    changed = true;
  }
  return changed;
}

bool OpenOperands::rewrite(Node& csg, bool closeCovered, std::optional<AABB>& povBox) {
  const NodeKind kind = csg.kind;
  if (kind != NodeKind::Merge && kind != NodeKind::Intersection && kind != NodeKind::Difference)
    return true;
  const bool allSolidRead =
      std::all_of(csg.children.begin(), csg.children.end(),
                  [&](const auto& c) { return c->isLight() || (c->isSolid() && !rewritten(*c)); });
  if (allSolidRead) return true;
  const AABB before = nodeBox(csg, Mat4(1.0), knownBoxes());
  if (closeCovered && closeCoveredDiscs(csg)) povBox = before;
  // The operands in order (lights aside), each with its insides; a solid joins the solids'
  // own operation. Nothing is changed when all are solids or one's inside is not known.
  std::vector<PovInsides> insides;
  std::vector<bool> solid;
  bool allSolid = true;
  for (const auto& c : csg.children) {
    if (c->isLight()) continue;
    PovInsides in;
    if (!insidesOf(*c, in)) return true;
    solid.push_back(c->isSolid() && !rewritten(*c));
    allSolid = allSolid && solid.back();
    insides.push_back(std::move(in));
  }
  if (allSolid) return true;
  const AABB box = before;
  povBox = box;
  std::vector<std::unique_ptr<Node>> lights, operands;
  for (auto& c : csg.children) {
    if (c->isLight()) {
      lights.push_back(std::move(c));
      continue;
    }
    // Only the whole operation's no_shadow, no_image, no_reflection count (now the union's).
    c->shadows = c->image = c->reflection = true;
    operands.push_back(std::move(c));
  }
  csg.children.clear();

  // POV-Ray's operation as it evaluates it: an intersection (all operands inside) or a
  // merge (any), of operands inverted or not. A difference is an intersection with its
  // later operands inverted; inverting an operation inverts each operand and turns an
  // intersection into a merge and back.
  const bool all = (kind != NodeKind::Merge) != csg.inverse;
  std::vector<bool> inverted(operands.size());
  for (size_t j = 0; j < operands.size(); ++j) {
    inverted[j] = (kind == NodeKind::Difference && j > 0) != csg.inverse;
    if (inverted[j]) std::swap(insides[j].in, insides[j].inverted);
  }
  // Keeps `piece` where operand j is as the operation asks: inside it (all), or not inside it
  // (any). False when that is nowhere.
  const auto clipByOperand = [&](Node& piece, size_t j) {
    const std::unique_ptr<Node>& in = insides[j].in;
    if (!in) return !all;  // inside nowhere: never inside, always not inside
    clipTo(piece, *in, !all);
    return true;
  };

  // The solids' own operation. Its surfaces are those of the set it makes or of that set's
  // complement (the same boundary), whichever Lucent writes without inverting operands.
  std::vector<size_t> solids;
  for (size_t i = 0; i < operands.size(); ++i)
    if (solid[i]) solids.push_back(i);
  std::vector<std::unique_ptr<Node>> kept;
  if (!solids.empty()) {
    std::unique_ptr<Node> part;
    if (solids.size() == 1) {
      part = std::move(operands[solids[0]]);
    } else {
      // As an intersection of operands, each maybe inverted (a merge is the complement of
      // the intersection of its operands inverted).
      bool firstInverted = inverted[solids[0]] != !all, othersInverted = true, noneInverted = true;
      for (size_t k = 1; k < solids.size(); ++k) {
        const bool inv = inverted[solids[k]] != !all;
        othersInverted = othersInverted && inv;
        noneInverted = noneInverted && !inv;
      }
      NodeKind partKind = NodeKind::Intersection;
      bool toggle = false;
      if (!firstInverted && noneInverted) partKind = NodeKind::Intersection;
      else if (firstInverted && othersInverted) partKind = NodeKind::Merge;
      else if (!firstInverted && othersInverted) partKind = NodeKind::Difference;
      else toggle = true;
      std::vector<std::unique_ptr<Node>> parts;
      for (size_t j : solids) {
        if (toggle && inverted[j] != !all) operands[j]->inverse = !operands[j]->inverse;
        parts.push_back(std::move(operands[j]));
      }
      part = operation(partKind, std::move(parts), csg, false);
    }
    bool keep = true;
    for (size_t j = 0; j < operands.size() && keep; ++j)
      if (!solid[j]) keep = clipByOperand(*part, j);
    if (keep) kept.push_back(std::move(part));
  }
  // Every other operand's surface where all the others' insides say. An inverted union is
  // POV-Ray's intersection of its parts inverted: each part's surface only where the others
  // are inside inverted.
  for (size_t i = 0; i < operands.size(); ++i) {
    if (solid[i]) continue;
    if (inverted[i] && !invertSurfaces(*operands[i])) continue;
    bool keep = true;
    for (size_t j = 0; j < operands.size() && keep; ++j)
      if (j != i) keep = clipByOperand(*operands[i], j);
    if (keep) kept.push_back(std::move(operands[i]));
  }

  // The operation's own insides, for an operation around it: of all, inside where all
  // are and, inverted, where any is inverted; of any, the reverse.
  PovInsides whole;
  {
    std::vector<std::unique_ptr<Node>> ins, inverteds;
    bool inEverywhereNeeded = true;  // all: every in given; any: every inverted given
    for (PovInsides& e : insides) {
      std::unique_ptr<Node>& needed = all ? e.in : e.inverted;
      std::unique_ptr<Node>& either = all ? e.inverted : e.in;
      if (needed) (all ? ins : inverteds).push_back(std::move(needed));
      else inEverywhereNeeded = false;
      if (either) (all ? inverteds : ins).push_back(std::move(either));
    }
    std::unique_ptr<Node>& allOf = all ? whole.in : whole.inverted;
    std::unique_ptr<Node>& anyOf = all ? whole.inverted : whole.in;
    allOf = inEverywhereNeeded
                ? operation(NodeKind::Intersection, std::move(all ? ins : inverteds), csg, true)
                : nullptr;
    anyOf = operation(NodeKind::Union, std::move(all ? inverteds : ins), csg, true);
  }

  csg.kind = NodeKind::Union;
  csg.element = nodeKindName(kind);  // marks it rewritten (see rewritten())
  csg.inverse = false;               // its pieces are what the inverse kept
  for (auto& k : kept) csg.children.push_back(std::move(k));
  for (auto& l : lights) csg.children.push_back(std::move(l));
  if (csg.children.empty()) return false;
  rewritten_[&csg] = Rewritten{std::move(whole), box};
  return true;
}

bool OpenOperands::clipByInside(std::unique_ptr<Node>& clip) const {
  if (clip->isSolid() && !rewritten(*clip)) return true;
  PovInsides in;
  if (!insidesOf(*clip, in)) return true;
  if (!in.in) return false;
  clip = std::move(in.in);
  return true;
}

}  // namespace lucent::sdl
