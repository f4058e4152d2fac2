// <rainbow> (docs/scene-language.md, "<rainbow>"): any number, at the top level, all
// applied, as POV-Ray's rainbow: a <color-map> laid across a ring of angles around the
// antisolar `direction`, `arc-angle` and `falloff-angle` its part drawn and its fade.
#include "element_parsers.h"
#include "pattern_parser.h"

#include "values.h"

namespace lucent {

void parseRainbow(ElementReader& r) {
  ParseContext& ctx = r.ctx();
  Rainbow rainbow;
  rainbow.loc = r.loc();
  r.checkAttributes(
      {"direction", "angle", "width", "distance", "jitter", "up", "arc-angle", "falloff-angle"});
  if (!r.has("direction")) r.error("<rainbow> needs 'direction', the antisolar direction");
  if (!r.has("angle")) r.error("<rainbow> needs 'angle', the ring's angle from 'direction'");
  if (!r.has("width")) r.error("<rainbow> needs 'width', the ring's width in degrees");
  rainbow.direction = r.vector("direction", rainbow.direction);
  if (!(glm::length(rainbow.direction) > 0.0))
    r.attrError("direction", "'direction' must not be zero");
  rainbow.angle =
      r.number("angle", rainbow.angle, NumberRule::between(0.0, 180.0, "an angle from 0 to 180"));
  rainbow.width = r.number("width", rainbow.width, NumberRule::positive());
  rainbow.distance = r.number("distance", rainbow.distance, NumberRule::positive());
  rainbow.jitter = r.number("jitter", rainbow.jitter, NumberRule::nonNegative());
  rainbow.up = r.vector("up", rainbow.up);
  if (!(glm::length(rainbow.up) > 0.0)) r.attrError("up", "'up' must not be zero");
  const NumberRule degrees = NumberRule::between(0.0, 360.0, "an angle from 0 to 360");
  rainbow.arcAngle = r.number("arc-angle", rainbow.arcAngle, degrees);
  rainbow.falloffAngle = r.number("falloff-angle", rainbow.arcAngle, degrees);
  if (rainbow.falloffAngle > rainbow.arcAngle)
    r.attrError("falloff-angle",
                "the fade starts within the arc: 'falloff-angle' must not exceed "
                "'arc-angle' (" +
                    formatNumber(rainbow.arcAngle) + ")");
  // Up made square to the direction, as POV-Ray makes it.
  const bool zero = !(glm::length(rainbow.direction) > 0.0) || !(glm::length(rainbow.up) > 0.0);
  if (!zero) {
    const Vec3 right = glm::cross(glm::normalize(rainbow.up), glm::normalize(rainbow.direction));
    if (!(glm::length(right) > 1e-5)) r.attrError("up", "'up' must not lie along 'direction'");
    else rainbow.setFrame();
  }
  bool mapRead = false;
  r.forEachChild([&](pugi::xml_node n) {
    ElementReader c(ctx, r.file(), n);
    if (std::string_view(n.name()) != "color-map") {
      c.error("<rainbow> holds one <color-map>, not <" + std::string(n.name()) + ">");
      return;
    }
    if (mapRead) {
      c.error("<rainbow> holds one <color-map>");
      return;
    }
    mapRead = true;
    rainbow.map = parseColorMap(c);
  });
  if (!mapRead && !r.failed())
    r.error(
        "<rainbow> needs a <color-map>: its colours run across the ring, from its inner edge "
        "(0) to its outer (1)");
  ctx.scene.rainbows.push_back(rainbow);
}

}  // namespace lucent
