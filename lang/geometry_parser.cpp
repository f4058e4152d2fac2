// Geometry nodes (contract, "Geometry nodes"): shapes, <group>, <union>, <merge>,
// <intersection>, <difference> and <use ref>. Every one accepts id, transform and
// material (an id attribute or one inline <material> child, not both). A node without a
// material leaves Node::material empty and inherits its nearest ancestor's (World does it).
#include "element_parsers.h"
#include "expansion.h"
#include "povray_names.h"

#include "scenegraph/shape_registry.h"

#include <algorithm>
#include <unordered_map>

namespace lucent {

namespace {

struct GroupEntry {
  std::string_view element;
  NodeKind kind;
};
const std::vector<GroupEntry> kGroups{{"group", NodeKind::Group},
                                      {"light-group", NodeKind::Group},
                                      {"union", NodeKind::Union},
                                      {"merge", NodeKind::Merge},
                                      {"intersection", NodeKind::Intersection},
                                      {"difference", NodeKind::Difference}};

const GroupEntry* findGroup(std::string_view name) {
  for (const GroupEntry& g : kGroups)
    if (g.element == name) return &g;
  return nullptr;
}

const std::vector<std::string_view> kTopLevelOnly{"render",    "camera", "defs",   "include",
                                                  "animation", "fog",    "rainbow"};

// A child element that is not allowed where it stands: say where it belongs, or suggest
// the closest allowed name.
void reportUnexpectedChild(ElementReader& parent, pugi::xml_node child,
                           const std::vector<std::string_view>& allowed) {
  ElementReader c(parent.ctx(), parent.file(), child);
  std::string_view name = child.name();
  bool topLevel =
      std::find(kTopLevelOnly.begin(), kTopLevelOnly.end(), name) != kTopLevelOnly.end();
  if (topLevel)
    c.error("<" + std::string(name) + "> is not allowed inside " + parent.tag() +
            "; it belongs at the top level of <scene>");
  else if (name == "light")
    c.error(
        "<light> is not allowed inside " + parent.tag() +
        "; a light stands at the top level or in a group, CSG operation, <defs>, <repeat> or <if>");
  else if (isGeometryElement(name) || name == "material")
    c.error("<" + std::string(name) + "> is not allowed inside " + parent.tag());
  else if (std::string pov = povrayElementHint(parent.name(), name); !pov.empty())
    c.error("unknown element <" + std::string(name) + "> inside " + parent.tag() + pov);
  else
    c.error("unknown element <" + std::string(name) + "> inside " + parent.tag() +
            didYouMean(name, allowed));
}

// The material of a geometry node: the material="id" attribute or one inline child.
void readNodeMaterial(ElementReader& r, Node& node, pugi::xml_node inlineMaterial) {
  if (inlineMaterial && r.has("material")) {
    r.attrError("material",
                "give either a 'material' attribute or an inline <material> child (at " +
                    r.file().loc(inlineMaterial).str() + "), not both");
    return;
  }
  if (r.has("interior-material")) node.interiorMaterial = lookupMaterial(r, "interior-material");
  if (r.has("material")) {
    node.material = lookupMaterial(r, "material");
  } else if (inlineMaterial) {
    ElementReader m(r.ctx(), r.file(), inlineMaterial);
    node.material = parseInlineMaterial(m);
    if (m.failed()) r.ctx().broken.insert(&node);
  }
}

}  // namespace

void registerNodeId(ElementReader& r, Node& node) {
  auto id = r.text("id");
  if (!id) return;
  if (!isValidId(*id)) {
    r.attrError("id", "an id must be non-empty and contain no spaces, got '" + *id + "'");
    return;
  }
  node.id = *id;
  ParseContext& ctx = r.ctx();
  if (!ctx.registerIds) return;  // a copy made by a <use> with parameters
  auto [it, inserted] = ctx.nodeIds.try_emplace(
      *id, ParseContext::IdEntry{&node, node.loc, &r.file(), r.element(), ctx.scope});
  if (!inserted) {
    const ParseContext::IdEntry& first = it->second;
    std::string firstNote = instanceNote(first.scope.get());
    r.attrError("id", "the id '" + *id + "' is already used (first defined at " + first.loc.str() +
                          firstNote + ")" +
                          (ctx.scope && instanceNote(ctx.scope.get()).size()
                               ? "; an id inside a <repeat> must "
                                 "differ per instance, as in id=\"post${i}\""
                               : ""));
  }
}

namespace {

// shadows="false", image="false" or reflection="false" on a part of a merge, intersection or
// difference changes nothing: the operation is seen and casts its shadow as a whole, as in
// POV-Ray (whose no_shadow there counts on the whole object only; its no_image and
// no_reflection count on the whole, and on a merge's parts, which Lucent does not follow).
// Nested operations have warned about their own parts.
void warnFlaggedOperands(ParseContext& ctx, const Node& csg) {
  std::vector<const Node*> stack;
  for (const auto& c : csg.children) stack.push_back(c.get());
  auto warn = [&](const Node& n, const std::string& attr, const std::string& what) {
    ctx.diags.warning(n.loc, "<" + n.element + "> " + attr + "=\"false\" has no effect inside <" +
                                 csg.element + "> (at " + csg.loc.str() + "), which " + what +
                                 " as a whole, as in POV-Ray; put " + attr + "=\"false\" on the <" +
                                 csg.element + ">");
  };
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    if (!n->shadows) warn(*n, "shadows", "casts its shadow");
    if (!n->image) warn(*n, "image", "is seen");
    if (!n->reflection) warn(*n, "reflection", "is seen");
    if (n->kind == NodeKind::Group || n->kind == NodeKind::Union)
      for (const auto& c : n->children) stack.push_back(c.get());
  }
}

// The attributes a geometry element accepts, made once per element name (a scene of a
// million spheres reads them a million times).
const std::vector<std::string_view>& nodeAttributes(std::string_view element) {
  static std::unordered_map<std::string_view, std::vector<std::string_view>> cache;
  auto it = cache.find(element);
  if (it != cache.end()) return it->second;
  std::vector<std::string_view> allowed{"id",      "transform", "material",   "interior-material",
                                        "shadows", "image",     "reflection", "double-illuminate",
                                        "inverse"};
  if (element == "use") allowed.push_back("ref");
  if (element == "light-group") allowed.push_back("global-lights");
  for (auto a : shapeAttributes(element)) allowed.push_back(a);
  // The key must outlive the call: the registry's and this file's names are static.
  std::string_view key = element;
  for (std::string_view n : geometryElementNames())
    if (n == element) key = n;
  return cache.emplace(key, std::move(allowed)).first->second;
}

}  // namespace

// A <clip>, <bound> or <projected-through>: no attributes, one or more geometry elements
// (<repeat> and <if> around them) in the frame of the node that holds it.
void readObjectList(ParseContext& ctx, const SourceFile& file, pugi::xml_node element, int depth,
                    std::vector<std::unique_ptr<Node>>& out) {
  ElementReader r(ctx, file, element);
  r.checkAttributes({});
  bool anyChild = false;  // a wrong child is its own error, not also an empty <clip>
  forEachExpandedChild(r, depth + 1, [&](pugi::xml_node c) {
    anyChild = true;
    if (!isGeometryElement(c.name())) {
      std::vector<std::string_view> names = geometryElementNames();
      names.push_back("repeat");
      names.push_back("if");
      reportUnexpectedChild(r, c, names);
      return;
    }
    if (auto child = parseGeometryNode(ctx, file, c, depth + 1)) out.push_back(std::move(child));
  });
  if (!out.empty() || anyChild || r.failed()) return;
  const std::string_view name = element.name();
  if (name == "clip")
    r.error(r.tag() +
            " needs at least one solid: the surface is kept only inside all of them (POV-Ray's "
            "clipped_by)");
  else if (name == "bound")
    r.error(r.tag() +
            " needs at least one solid: the object is searched only along rays that meet all of "
            "them (POV-Ray's bounded_by)");
  else
    r.error(r.tag() +
            " needs at least one object: the light reaches a point only through them (POV-Ray's "
            "projected_through)");
}

// The shapes of the registry, then the groups, CSG operations and <use>.
const std::vector<std::string_view>& geometryElementNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n = shapeElementNames();
    for (const GroupEntry& g : kGroups) n.push_back(g.element);
    n.push_back("use");
    return n;
  }();
  return names;
}

bool isGeometryElement(std::string_view name) {
  const auto& n = geometryElementNames();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::unique_ptr<Node> parseGeometryNode(ParseContext& ctx, const SourceFile& file,
                                        pugi::xml_node element, int depth) {
  if (std::string_view(element.name()) == "light") return parseLightNode(ctx, file, element, depth);
  ElementReader r(ctx, file, element);
  if (!withinElementDepth(r, depth)) return nullptr;
  if (!countNode(ctx)) return nullptr;
  LocalScope scope(ctx, file, element);
  std::string_view name = element.name();
  auto node = std::make_unique<Node>();
  node->element = std::string(name);
  node->loc = r.loc();

  const GroupEntry* group = findGroup(name);
  const ShapeType* shapeType = findShapeType(name);
  bool isUse = name == "use";
  r.checkAttributes(nodeAttributes(name));

  registerNodeId(r, *node);
  node->parentFromNode = r.transform("transform");
  node->shadows = r.boolean("shadows", true);
  node->image = r.boolean("image", true);
  node->reflection = r.boolean("reflection", true);
  node->doubleIlluminate = r.boolean("double-illuminate", false);
  node->inverse = r.boolean("inverse", false);
  if (name == "light-group") {
    node->lightGroup = true;
    node->globalLights = r.boolean("global-lights", false);
  }

  // Children: geometry (groups and CSG only), at most one inline <material>, one <clip>
  // and one <bound>.
  pugi::xml_node inlineMaterial, clip, bound;
  auto readChild = [&](pugi::xml_node c) {
    std::string_view cn = c.name();
    if (cn == "clip" || cn == "bound") {
      pugi::xml_node& seen = cn == "clip" ? clip : bound;
      if (seen) {
        ElementReader(ctx, file, c)
            .error(r.tag() + " holds one <" + std::string(cn) + "> at most; the first is at " +
                   file.loc(seen).str());
        return;
      }
      seen = c;
      readObjectList(ctx, file, c, depth + 1, cn == "clip" ? node->clip : node->bound);
    } else if (cn == "material") {
      if (inlineMaterial) {
        ElementReader(ctx, file, c)
            .error(r.tag() + " holds one <material> at most; the first is at " +
                   file.loc(inlineMaterial).str());
        return;
      }
      inlineMaterial = c;
    } else if (group && (isGeometryElement(cn) || cn == "light")) {
      if (auto child = parseGeometryNode(ctx, file, c, depth + 1))
        node->children.push_back(std::move(child));
    } else if (shapeType && shapeType->child(cn)) {
      // The shape's own child (a blob's <component>): its entry reads it in parseShape.
    } else {
      std::vector<std::string_view> childNames{"material", "param", "clip", "bound"};
      if (shapeType)
        for (const ChildElementInfo& ch : shapeType->children) childNames.push_back(ch.name);
      if (group) {
        childNames.insert(childNames.end(), geometryElementNames().begin(),
                          geometryElementNames().end());
        childNames.push_back("light");
        childNames.push_back("repeat");
        childNames.push_back("if");
      }
      reportUnexpectedChild(r, c, childNames);
    }
  };
  if (group) {
    forEachExpandedChild(r, depth + 1, readChild);
  } else {
    r.forEachChild([&](pugi::xml_node c) {
      if (std::string_view(c.name()) != "param") readChild(c);
    });
  }
  readNodeMaterial(r, *node, inlineMaterial);

  if (group) {
    node->kind = group->kind;
    if (node->isCsg() && !r.failed() &&
        std::all_of(node->children.begin(), node->children.end(),
                    [](const auto& c) { return c->isLight(); }))
      r.error(r.tag() + " needs at least one child shape");
    if (node->kind == NodeKind::Merge || node->kind == NodeKind::Intersection ||
        node->kind == NodeKind::Difference)
      warnFlaggedOperands(ctx, *node);
  } else if (isUse) {
    node->kind = NodeKind::Use;
    if (!r.has("ref")) {
      r.error("<use> needs a 'ref' attribute naming the id of the node to instantiate");
    } else if (auto ref = r.text("ref")) {
      bool hasParams = false;
      for (pugi::xml_node c = element.child("param"); c && !hasParams; c = c.next_sibling("param"))
        hasParams = true;
      // With parameters the target is read again with them (an instance of its own); without,
      // the <use> shares the target's built geometry.
      if (hasParams)
        ctx.instances.push_back(
            {node.get(), *ref, r.valueLoc("ref"), ctx.scope, ctx.instanceChain});
      else ctx.uses.push_back({node.get(), *ref, r.valueLoc("ref")});
    }
  } else {
    node->kind = NodeKind::Shape;
    node->shape = parseShape(r);
  }
  if (!node->clip.empty() || !node->bound.empty()) ctx.clipped.push_back(node.get());
  if (r.failed()) ctx.broken.insert(node.get());
  // A <use> without a target cannot be resolved: treat it as broken from the start.
  if (isUse && (!r.has("ref") || r.failed())) ctx.broken.insert(node.get());
  return node;
}

void parseDefs(ElementReader& r) {
  r.checkAttributes({});
  forEachExpandedChild(r, 2, [&](pugi::xml_node c) {
    if (!isGeometryElement(c.name()) && std::string_view(c.name()) != "light") {
      reportUnexpectedChild(r, c, geometryElementNames());
      return;
    }
    auto node = parseGeometryNode(r.ctx(), r.file(), c, 2);
    if (!node) return;
    if (node->id.empty() && !r.ctx().broken.count(node.get()))
      r.ctx().diags.warning(
          node->loc, "<" + node->element + "> in <defs> has no id, so no <use> can instantiate it");
    r.ctx().scene.defs.push_back(std::move(node));
  });
}

}  // namespace lucent
