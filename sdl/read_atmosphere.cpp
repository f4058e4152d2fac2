// What surrounds the objects: fog, rainbow and sky_sphere (its pigments, layered).
#include "pov_space.h"
#include "read_support.h"
#include "scene_reader.h"

#include <algorithm>

namespace lucent::sdl {

void SceneReader::readFog(const SourceLoc& loc, TokenStream& in) {
  PovFog fog;
  fog.loc = loc;
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (readTransform(t, in, fog.transform)) continue;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "fog_type") {
      fog.type = static_cast<int>(in.parseFloat());
    } else if (w == "distance") {
      fog.distance = in.parseFloat();
    } else if (w == "fog_offset") {
      fog.offset = in.parseFloat();
    } else if (w == "fog_alt") {
      fog.altitude = in.parseFloat();
    } else if (w == "up") {
      fog.up = toVec3(in.parseVector());
    } else if (w == "turbulence") {
      fog.turbulent = true;
      fog.turbulence = toVec3(in.parseVector());
    } else if (w == "octaves") {
      fog.turbulent = true;
      fog.octaves = std::clamp(static_cast<int>(in.parseFloat()), 1, 10);
    } else if (w == "omega") {
      fog.turbulent = true;
      fog.omega = in.parseFloat();
    } else if (w == "lambda") {
      fog.turbulent = true;
      fog.lambda = in.parseFloat();
    } else if (w == "turb_depth") {
      fog.turbDepth = in.parseFloat();
    } else if (w == "color" || w == "colour" ||
               (t.kind == TokenKind::Keyword && isColourKey(t.kw)) || startsNumber(t)) {
      in.unget();
      const PovColour c = readColour(in);
      fog.color = c.rgb;
      fog.filter = c.filter;
      fog.transmit = c.transmit;
    } else {
      unreadInBlock(t, in);
      return;
    }
  }
  const FogImport imported = importFog(fog);
  if (!imported.error.empty()) {
    keepError(in, loc, imported.error);
    return;
  }
  for (const std::string& d : imported.differences) warn(in, loc, d);
  scene_.fogs.push_back(*imported.fog);
}

// `rainbow { ... }`, checked as POV-Ray's Parse_Rainbow checks it. The angles stay in
// degrees as written (Lucent's <rainbow> takes them so); direction and up are carried into
// Lucent's space.
void SceneReader::readRainbow(const SourceLoc& loc, TokenStream& in) {
  Rainbow rainbow;
  rainbow.loc = loc;
  Vec3 direction(0.0), up(0.0, 1.0, 0.0);
  std::optional<double> arc, falloff;
  std::vector<PovColorMapEntry> map;
  double width = 0.0;
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    const std::string_view w = t.kind == TokenKind::Keyword ? t.text() : "";
    if (w == "angle") {
      rainbow.angle = in.parseFloat();
    } else if (w == "width") {
      width = in.parseFloat();
    } else if (w == "distance") {
      rainbow.distance = in.parseFloat();
    } else if (w == "jitter") {
      rainbow.jitter = in.parseFloat();
    } else if (w == "direction") {
      direction = toVec3(in.parseVector());
    } else if (w == "up") {
      up = toVec3(in.parseVector());
    } else if (w == "arc_angle" || w == "falloff_angle") {
      const double a = in.parseFloat();
      if (!(a >= 0.0 && a <= 360.0))
        in.error(t, "illegal " + std::string(w) + " in rainbow: use a value from 0 to 360 degrees");
      (w == "arc_angle" ? arc : falloff) = a;
    } else if (w == "color_map" || w == "colour_map") {
      SourceLoc mapLoc = t.loc();
      map = readColorMap(in, mapLoc);
    } else {
      unreadInBlock(t, in);
      return;
    }
  }
  // POV-Ray's arc angle without arc_angle is 180 radians (its default is not converted
  // from degrees): the whole ring, and with falloff_angle alone a fade below 0.001, which
  // 360 degrees and no fade stand for.
  rainbow.arcAngle = arc.value_or(360.0);
  rainbow.falloffAngle = arc ? falloff.value_or(*arc) : rainbow.arcAngle;
  if (rainbow.arcAngle < rainbow.falloffAngle)
    in.error(loc, "arc angle is smaller than falloff angle in rainbow");
  if (!(glm::length(direction) > 1e-5)) in.error(loc, "rainbow's direction vector is zero");
  if (!(glm::length(up) > 1e-5)) in.error(loc, "rainbow's up vector is zero");
  if (std::abs(1.0 - std::abs(glm::dot(glm::normalize(direction), glm::normalize(up)))) < 1e-10)
    in.error(loc, "rainbow's up and direction vector are co-linear");
  // POV-Ray draws nothing of a rainbow without a colour map, a width or a distance.
  if (map.empty() || width == 0.0 || rainbow.distance == 0.0) {
    warn(in, loc,
         "this rainbow draws nothing (it needs a colour map, a width and a distance), as in "
         "POV-Ray");
    return;
  }
  if (width < 0.0 || rainbow.distance < 0.0) {
    keepError(in, loc, "a rainbow's width and distance must be positive for Lucent's <rainbow>");
    return;
  }
  rainbow.width = width;
  rainbow.jitter = std::max(rainbow.jitter, 0.0);  // POV-Ray jitters only by a positive amount
  rainbow.direction = lucentFromPov(direction);
  rainbow.up = lucentFromPov(up);
  rainbow.setFrame();
  for (const PovColorMapEntry& e : unitMap(ascendingMap(map)))
    rainbow.map.entries.push_back({e.at, e.color, {e.filter, e.transmit}});
  scene_.rainbows.push_back(rainbow);
}

PovSkySphere SceneReader::readSkySphereBlock(const SourceLoc& loc, TokenStream& in) {
  PovSkySphere sky;
  in.expect("{");
  if (const auto* item = use<SkySphereItem>(in.peek(), in)) {
    in.next();
    sky = item->sky;  // its pigments and transforms; what follows adds to them
  }
  sky.loc = loc;
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (readTransform(t, in, sky.transform)) continue;
    if (isWord(t, "pigment")) {
      // POV-Ray's sky pigments start from its plain black pigment, not the #default.
      const SourceLoc at = in.peek().loc();
      sky.pigments.push_back(readPigment(in, PovPigment{}));
      if (textureHoldsImage(sky.pigments.back().pattern))
        keepError(in, at,
                  "'image_map' in a sky_sphere is not supported by Lucent (a sky's pigments are "
                  "patterns; an image is read on a shape)");
      if (sky.pigments.back().uv || textureUsesUv(sky.pigments.back().pattern))
        keepError(in, at,
                  "'uv_mapping' in a sky_sphere is not supported by Lucent (a sky, seen at a "
                  "direction, has no (u, v))");
      continue;
    }
    unreadInBlock(t, in);
    break;
  }
  return sky;
}

void SceneReader::readSkySphere(const SourceLoc& loc, TokenStream& in) {
  const PovSkySphere sky = readSkySphereBlock(loc, in);
  const SkyImport imported = importSkySphere(sky);
  if (!imported.error.empty()) {
    keepError(in, loc, imported.error);
    return;
  }
  for (const std::string& d : imported.differences) warn(in, loc, d);
  scene_.sky = imported.sky;
}

}  // namespace lucent::sdl
