// <light> (contract, "<light>"): point (default), directional, spot and area lights.
// Every light has color (1), intensity (1), shadows (true), id and transform; directions
// are normalised. An area light that has a spot attribute (direction, look-at, angle,
// inner) is spot-shaped: its cone is seen from its centre. An attribute of another light
// type is an error that says which types it belongs to. A light is a node of the hierarchy
// (NodeKind::Light) wherever it stands, in its parent's frame; placeLights puts the scene's lights
// in the world once it is read.
#include "element_parsers.h"
#include "expansion.h"

#include <fmt/format.h>

#include <algorithm>

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

// The cone of a spot light or a spot-shaped area light: its axis (direction, or look-at
// from the position) and its outer and inner half-angles.
void readCone(ElementReader& r, Light& light) {
  if (r.has("direction") && r.has("look-at")) {
    r.attrError("look-at", "give either 'direction' or 'look-at', not both");
  } else if (r.has("look-at")) {
    Vec3 target = r.vector("look-at", light.position + light.direction);
    Vec3 d = target - light.position;
    double len = glm::length(d);
    if (!(len > 0.0)) r.attrError("look-at", "'look-at' must differ from 'position'");
    else light.direction = d / len;
  } else {
    light.direction = r.direction("direction", light.direction);
  }
  light.angle = r.number("angle", light.angle,
                         NumberRule::between(0.0, 90.0, "an angle above 0 and at most 90", true));
  light.inner =
      r.number("inner", light.angle, NumberRule::between(0.0, 90.0, "an angle from 0 to 90"));
  if (light.inner > light.angle)
    r.attrError("inner", "'inner' (" + fmt::format("{}", light.inner) +
                             ") must not exceed 'angle' (" + fmt::format("{}", light.angle) + ")");
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
    return "belongs to " + list + " lights; this light is " +
           std::string(lightTypeInfo(light.type).name) + " (set type=\"" + owners[0] + "\")";
  });

  registerNodeId(r, *node);
  node->parentFromNode = r.transform("transform");
  light.color = r.color("color", light.color);
  light.intensity = r.number("intensity", light.intensity, NumberRule::nonNegative());
  light.shadows = r.boolean("shadows", light.shadows);

  if (light.type != LightType::Directional) {
    light.position = r.vector("position", light.position);
    if (auto t = r.text("attenuation")) {
      auto v = parseVector(*t);
      if (!v) r.attrError("attenuation", v.error);
      else if (v->x < 0.0 || v->y < 0.0 || v->z < 0.0 ||
               (v->x == 0.0 && v->y == 0.0 && v->z == 0.0))
        r.attrError("attenuation", "expected 3 numbers a b c >= 0, not all zero, got '" + *t + "'");
      else light.attenuation = *v;
    }
  }

  switch (light.type) {
    case LightType::Directional:
      light.direction = r.direction("direction", light.direction);
      break;
    case LightType::Spot:
      readCone(r, light);
      break;
    case LightType::Area: {
      // Any spot attribute makes the area light spot-shaped.
      light.cone = r.has("direction") || r.has("look-at") || r.has("angle") || r.has("inner");
      if (light.cone) readCone(r, light);
      light.u = r.vector("u", light.u);
      light.v = r.vector("v", light.v);
      if (!(glm::length(glm::cross(light.u, light.v)) > 0.0))
        r.error(
            "<light type=\"area\">: 'u' and 'v' must be non-zero and not parallel (they span the "
            "rectangle)");
      if (auto t = r.text("samples")) {
        auto list = parseIntegerList(*t);
        if (!list) r.attrError("samples", list.error);
        else if (list->size() != 2 && list->size() != 1)
          r.attrError("samples",
                      "expected 2 whole numbers (nu nv), got " + std::to_string(list->size()));
        else {
          long long nu = (*list)[0], nv = list->size() == 2 ? (*list)[1] : nu;
          if (nu < 2 || nv < 2 || nu > 1024 || nv > 1024)
            r.attrError("samples",
                        "each count must be from 2 to 1024 (the grid includes the edges), got '" +
                            *t + "'");
          else {
            light.samplesU = static_cast<int>(nu);
            light.samplesV = static_cast<int>(nv);
          }
        }
      }
      light.jitter = r.boolean("jitter", light.jitter);
      // Levels of forced subdivision; a 1024-point axis is fully split within 10, so larger
      // values are all alike and are clamped to fit an int.
      if (r.has("adaptive")) {
        long long n = r.integer("adaptive", -1, 0);
        if (n >= 0) light.adaptive = static_cast<int>(std::min(n, 1LL << 20));
      }
      break;
    }
    case LightType::Point:
      break;
  }
  r.forEachChild([&](pugi::xml_node n) {
    if (std::string_view(n.name()) == "param")
      return;  // a local parameter (the caller's LocalScope)
    ElementReader(r.ctx(), r.file(), n)
        .error("<light> takes no child elements but <param>, got <" + std::string(n.name()) + ">");
  });
  node->light = std::make_unique<Light>(light);
  if (r.failed()) ctx.broken.insert(node.get());
  return node;
}

}  // namespace lucent
