// <fog> (docs/scene-language.md, "<fog>"): any number, at the top level, all applied.
// Constant fog (the default) or ground fog (type="ground": offset, altitude, up), as
// POV-Ray's fog with fog_type 1 or 2; filter and transmit are those of POV-Ray's rgbft fog
// colour; `turbulence` and its parameters are POV-Ray's fog turbulence.
#include "element_parsers.h"
#include "pattern_parser.h"

#include "values.h"

namespace lucent {

namespace {

const std::vector<std::string_view> kGroundOnly{"offset", "altitude", "up"};
const std::vector<std::string_view> kTurbulenceOnly{"octaves",    "omega",     "lambda",
                                                    "turb-depth", "transform", "noise-generator"};

FogTurbulence parseTurbulence(ElementReader& r) {
  FogTurbulence t;
  // A mirrored noise is the transform's, not the strength's.
  if (auto s = parseTurbulenceStrength(r)) t.strength = *s;
  t.octaves = static_cast<int>(r.integer("octaves", t.octaves, 1, 10));
  t.omega = r.number("omega", t.omega);
  t.lambda = r.number("lambda", t.lambda);
  t.depth = r.number("turb-depth", t.depth);
  t.noiseGenerator = static_cast<int>(r.integer("noise-generator", t.noiseGenerator, 1, 3));
  t.noiseFromWorld = glm::inverse(r.transform("transform"));
  return t;
}

}  // namespace

void parseFog(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  Fog fog;
  fog.loc = r.loc();
  fog.type = r.choice("type", FogType::Constant,
                      {{"constant", FogType::Constant}, {"ground", FogType::Ground}});
  std::vector<std::string_view> allowed{"type",   "color",    "distance",
                                        "filter", "transmit", "turbulence"};
  if (fog.type == FogType::Ground)
    allowed.insert(allowed.end(), kGroundOnly.begin(), kGroundOnly.end());
  const bool turbulent = r.has("turbulence");
  if (turbulent) allowed.insert(allowed.end(), kTurbulenceOnly.begin(), kTurbulenceOnly.end());
  r.checkAttributes(allowed, [&](std::string_view attr) -> std::string {
    for (std::string_view a : kGroundOnly)
      if (a == attr) return "belongs to ground fog; this fog is constant (set type=\"ground\")";
    for (std::string_view a : kTurbulenceOnly)
      if (a == attr) return "belongs to the fog's turbulence; this fog has none (set 'turbulence')";
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
  if (turbulent) fog.turbulence = parseTurbulence(r);
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader(ctx, r.file(), n)
        .error("<fog> takes no child elements, got <" + std::string(n.name()) + ">");
  });
  ctx.scene.fogs.push_back(fog);
}

}  // namespace lucent
