// <warp type="transform|turbulence|repeat|black-hole|planar|spherical|cylindrical|toroidal|cubic">
// with the attributes of its type (docs/scene-language.md, "Warps").
#include "warp_parser.h"

#include "pattern_parser.h"

#include <cmath>

namespace lucent {

namespace {

enum class WarpKind { transform, turbulence, repeat, blackHole, mapping };

struct WarpTypeName {
  std::string_view name;
  WarpKind kind;
  std::vector<std::string_view> attributes;  // besides `type`
};

const std::vector<WarpTypeName>& warpTypes() {
  static const std::vector<WarpTypeName> types = [] {
    std::vector<WarpTypeName> t{
        {"transform", WarpKind::transform, {"transform"}},
        {"turbulence", WarpKind::turbulence, {"turbulence", "octaves", "omega", "lambda"}},
        {"repeat", WarpKind::repeat, {"direction", "offset", "flip"}},
        {"black-hole",
         WarpKind::blackHole,
         {"center", "radius", "strength", "falloff", "inverse", "repeat", "turbulence"}}};
    for (const MappingWarpName& m : kMappingWarpNames) {
      std::vector<std::string_view> a;
      if (m.kind == MappingWarpKind::planar) a = {"normal", "distance"};
      else if (m.kind != MappingWarpKind::cubic) a = {"orientation", "dist-exp"};
      if (m.kind == MappingWarpKind::toroidal) a.push_back("major-radius");
      t.push_back({m.name, WarpKind::mapping, a});
    }
    return t;
  }();
  return types;
}

// A vector of three numbers >= 0 (turbulences), or nullopt when absent or wrong (reported).
Vec3 nonNegativeVector(ElementReader& r, const char* attr) {
  const Vec3 v = r.vector(attr, Vec3(0.0));
  if (v.x < 0 || v.y < 0 || v.z < 0) {
    r.attrError(attr, "expected numbers >= 0");
    return Vec3(0.0);
  }
  return v;
}

PatternWarp parseRepeat(ElementReader& r) {
  RepeatWarp w;
  if (!r.has("direction")) r.error("<warp type=\"repeat\"> needs a 'direction' (e.g. \"2 0 0\")");
  const Vec3 d = r.vector("direction", Vec3(1.0, 0.0, 0.0));
  const int axes = (d.x != 0.0) + (d.y != 0.0) + (d.z != 0.0);
  if (axes != 1)
    r.attrError("direction",
                "expected one non-zero component (the axis and the width of the repeat, as "
                "POV-Ray's repeat x*2), got " +
                    std::to_string(axes));
  w.axis = d.x != 0.0 ? 0 : d.y != 0.0 ? 1 : 2;
  w.width = axes == 1 ? d[w.axis] : 1.0;
  w.offset = r.vector("offset", w.offset);
  const Vec3 flip = r.vector("flip", Vec3(0.0));
  for (int i = 0; i < 3; ++i) w.flip[i] = flip[i] != 0.0;
  return w;
}

PatternWarp parseBlackHole(ElementReader& r) {
  BlackHoleWarp w;
  if (!r.has("radius")) r.error("<warp type=\"black-hole\"> needs a 'radius'");
  w.center = r.vector("center", w.center);
  w.radius = r.number("radius", w.radius, NumberRule::positive());
  w.strength = r.number("strength", w.strength);
  w.falloff = r.number("falloff", w.falloff);
  w.inverse = r.boolean("inverse", w.inverse);
  w.repeat = nonNegativeVector(r, "repeat");
  w.turbulence = nonNegativeVector(r, "turbulence");
  if (w.turbulence != Vec3(0.0) && w.repeat == Vec3(0.0))
    r.attrError("turbulence", "a black hole's turbulence moves its repeated copies: give 'repeat'");
  // POV-Ray would move a repeated hole's centre and repeat (Check_BH_Parameters): Lucent
  // asks for values it keeps as they are.
  BlackHoleWarp settled = w;
  bool changed[3];
  settleBlackHole(settled, changed);
  for (int a = 0; a < 3; ++a) {
    if (w.repeat[a] == 0.0) continue;
    const char* axis[] = {"x", "y", "z"};
    if (settled.center[a] != w.center[a])
      r.attrError("center", std::string("with a repeat along ") + axis[a] + ", the centre's " +
                                axis[a] + " must be at least the radius");
    else if (changed[a])
      r.attrError("repeat", std::string("the repeat's ") + axis[a] +
                                " must be at least the centre's + radius + turbulence's (" +
                                formatNumber(settled.repeat[a]) + ")");
  }
  return w;
}

PatternWarp parseMapping(ElementReader& r, MappingWarpKind kind) {
  MappingWarp w;
  w.kind = kind;
  if (kind == MappingWarpKind::planar) {
    w.orientation = r.direction("normal", w.orientation);
    w.distance = r.number("distance", w.distance);
  } else {
    w.orientation = r.direction("orientation", w.orientation);
    w.distExp = r.number("dist-exp", w.distExp);
  }
  w.majorRadius = r.number("major-radius", w.majorRadius);
  return w;
}

}  // namespace

void parseWarps(ElementReader& r, std::vector<PatternWarp>& warps) {
  for (pugi::xml_node n : r.element().children("warp")) {
    ElementReader c(r.ctx(), r.file(), n);
    std::vector<std::pair<std::string_view, const WarpTypeName*>> names;
    for (const WarpTypeName& t : warpTypes()) names.emplace_back(t.name, &t);
    if (!c.has("type")) {
      std::string list;
      for (const auto& [name, t] : names) list += (list.empty() ? "" : ", ") + std::string(name);
      c.error("<warp> needs a 'type' (" + list + ")");
      continue;
    }
    const WarpTypeName* type = c.choice("type", static_cast<const WarpTypeName*>(nullptr), names);
    if (!type) continue;
    std::vector<std::string_view> allowed = type->attributes;
    allowed.push_back("type");
    c.checkAttributes(allowed, [&](std::string_view a) -> std::string {
      for (const WarpTypeName& t : warpTypes())
        for (std::string_view x : t.attributes)
          if (x == a)
            return "a " + std::string(type->name) + " <warp> does not take '" + std::string(a) +
                   "' (a " + std::string(t.name) + " warp does)";
      return "";
    });
    c.forEachChild([&](pugi::xml_node g) {
      ElementReader(c.ctx(), c.file(), g).error("<warp> takes no child elements");
    });
    switch (type->kind) {
      case WarpKind::transform:
        if (!c.has("transform")) c.error("<warp type=\"transform\"> needs a 'transform'");
        warps.push_back(TransformWarp{glm::inverse(c.transform("transform"))});
        break;
      case WarpKind::turbulence: {
        TurbulenceWarp t;
        if (!c.has("turbulence")) c.error("<warp type=\"turbulence\"> needs a 'turbulence'");
        if (auto v = parseTurbulenceStrength(c)) t.strength = *v;
        t.octaves = static_cast<int>(c.integer("octaves", t.octaves, 1, 10));
        t.omega = c.number("omega", t.omega, NumberRule::positive());
        t.lambda = c.number("lambda", t.lambda, NumberRule::positive());
        warps.push_back(t);
        break;
      }
      case WarpKind::repeat:
        warps.push_back(parseRepeat(c));
        break;
      case WarpKind::blackHole:
        warps.push_back(parseBlackHole(c));
        break;
      case WarpKind::mapping:
        for (const MappingWarpName& m : kMappingWarpNames)
          if (m.name == type->name) warps.push_back(parseMapping(c, m.kind));
        break;
    }
    if (c.failed()) r.markFailed();
  }
}

}  // namespace lucent
