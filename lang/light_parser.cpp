// <light> (contract, "<light>"), read through the light table (scenegraph/light.h): the
// type names, the attributes each type takes with their readers, and each type's checks
// between attributes. This file knows no type and no attribute but the three every element
// has (type, id, transform); an attribute of another light type is an error that says
// which types it belongs to. A light is a node of the hierarchy (NodeKind::Light) wherever
// it stands, in its parent's frame; placeLights puts the scene's lights in the world once
// it is read. Its <projected-through> objects stand in its own frame.
#include "element_input.h"
#include "element_parsers.h"
#include "expansion.h"
#include "povray_names.h"

namespace lucent {

namespace {

// The names of type="..." (scenegraph/light.cpp's table).
std::vector<std::pair<std::string_view, LightType>> typeChoices() {
  std::vector<std::pair<std::string_view, LightType>> choices;
  for (const LightTypeInfo& t : lightTypes()) choices.emplace_back(t.name, t.type);
  return choices;
}

// The attributes a light of type t takes.
std::vector<std::string_view> attributesOf(LightType t) {
  std::vector<std::string_view> names;
  for (const LightAttribute& a : lightAttributes())
    if (a.takenBy(t)) names.push_back(a.info.name);
  return names;
}

}  // namespace

std::unique_ptr<Node> parseLightNode(ParseContext& ctx, const SourceFile& file,
                                     pugi::xml_node element, int depth) {
  ElementReader r(ctx, file, element);
  if (!withinElementDepth(r, depth)) return nullptr;
  if (!countNode(ctx)) return nullptr;
  LocalScope scope(ctx, file, element);
  auto node = std::make_unique<Node>();
  node->kind = NodeKind::Light;
  node->element = "light";
  node->loc = r.loc();

  Light light;
  light.loc = r.loc();
  light.type = r.choice("type", LightType::Point, typeChoices());

  r.checkAttributes(attributesOf(light.type), [&](std::string_view attr) -> std::string {
    std::vector<std::string> owners;
    for (const LightAttribute& a : lightAttributes())
      if (a.info.name == attr)
        for (const LightTypeInfo& t : lightTypes())
          if (a.takenBy(t.type)) owners.emplace_back(t.name);
    if (owners.empty()) return {};
    std::string list = owners[0];
    for (size_t i = 1; i < owners.size(); ++i)
      list += (i + 1 == owners.size() ? " and " : ", ") + owners[i];
    // POV-Ray's word may be another attribute here (a spotlight's radius is 'inner').
    return "belongs to " + list + " lights; this light is " +
           std::string(lightTypeInfo(light.type).name) + " (set type=\"" + owners[0] + "\")" +
           povrayAttributeHint("light", attr);
  });

  registerNodeId(r, *node);
  node->parentFromNode = r.transform("transform");
  // Every other attribute of the type through its reader, in the table's order; then the
  // type's checks between them.
  ElementInput in(r);
  for (const LightAttribute& a : lightAttributes())
    if (a.read && a.takenBy(light.type)) a.read(light, in);
  if (const LightReader& finish = lightTypeInfo(light.type).finish) finish(light, in);

  pugi::xml_node through;  // the first <projected-through>
  r.forEachChild([&](pugi::xml_node n) {
    const std::string_view name = n.name();
    if (name == "param") return;  // a local parameter (the caller's LocalScope)
    if (name == "projected-through") {
      if (through) {
        ElementReader(r.ctx(), r.file(), n)
            .error("<light> holds one <projected-through> at most; the first is at " +
                   file.loc(through).str());
        return;
      }
      through = n;
      auto group = std::make_shared<Node>();
      group->kind = NodeKind::Group;
      group->element = "projected-through";
      group->loc = file.loc(n);
      readObjectList(ctx, file, n, depth + 1, group->children);
      light.projectedThrough = std::move(group);
      return;
    }
    ElementReader(r.ctx(), r.file(), n)
        .error("<light> takes no child elements but <param> and <projected-through>, got <" +
               std::string(name) + ">");
  });
  node->light = std::make_unique<Light>(light);
  if (r.failed()) ctx.broken.insert(node.get());
  return node;
}

}  // namespace lucent
