// <fog> (docs/scene-language.md, "<fog>"): at most one, at the top level. Constant fog
// (the default) or ground fog (type="ground": offset, altitude, up), as POV-Ray's fog with
// fog_type 1 or 2; filter and transmit are those of POV-Ray's rgbft fog colour.
#include "element_parsers.h"

namespace lucent {

namespace {

const std::vector<std::string_view> kGroundOnly{"offset", "altitude", "up"};

}  // namespace

void parseFog(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  if (ctx.scene.fog) {
    r.error("<fog> is given twice (first at " + ctx.scene.fog->loc.str() +
            "); a scene has at most one fog");
    return;
  }
  Fog fog;
  fog.loc = r.loc();
  fog.type = r.choice("type", FogType::Constant,
                      {{"constant", FogType::Constant}, {"ground", FogType::Ground}});
  std::vector<std::string_view> allowed{"type", "color", "distance", "filter", "transmit"};
  if (fog.type == FogType::Ground)
    allowed.insert(allowed.end(), kGroundOnly.begin(), kGroundOnly.end());
  r.checkAttributes(allowed, [&](std::string_view attr) -> std::string {
    for (std::string_view a : kGroundOnly)
      if (a == attr) return "belongs to ground fog; this fog is constant (set type=\"ground\")";
    return {};
  });
  if (!r.has("color")) r.error("<fog> needs 'color', the fog's colour");
  if (!r.has("distance"))
    r.error(
        "<fog> needs 'distance': a stretch of length t keeps exp(-t/distance) of the colour beyond "
        "it");
  fog.color = r.color("color", fog.color);
  fog.distance = r.number("distance", fog.distance, NumberRule::positive());
  const NumberRule unit = NumberRule::between(0.0, 1.0, "a number from 0 to 1");
  fog.filter = static_cast<float>(r.number("filter", fog.filter, unit));
  fog.transmit = static_cast<float>(r.number("transmit", fog.transmit, unit));
  if (fog.type == FogType::Ground) {
    fog.offset = r.number("offset", fog.offset);
    fog.altitude = r.number("altitude", fog.altitude, NumberRule::positive());
    fog.up = r.direction("up", fog.up);
  }
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(ctx, r.file(), n)
        .error("<fog> takes no child elements, got <" + std::string(n.name()) + ">");
  });
  ctx.scene.fog = fog;
}

}  // namespace lucent
