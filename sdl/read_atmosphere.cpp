// What surrounds the objects: fog and sky_sphere (its pigments, layered).
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
