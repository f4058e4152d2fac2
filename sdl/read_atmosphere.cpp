// What surrounds the objects: fog and sky_sphere (a gradient pigment with a colour map).
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

void SceneReader::readSkySphere(const SourceLoc& loc, TokenStream& in) {
  PovSkySphere sky;
  sky.loc = loc;
  in.expect("{");
  for (;;) {
    const Token t = in.next();
    if (t.is("}")) break;
    if (readTransform(t, in, sky.transform)) continue;
    if (!isWord(t, "pigment")) {
      unreadInBlock(t, in);
      return;
    }
    PovSkyGradient g;
    in.expect("{");
    bool gradient = false;
    for (;;) {
      const Token k = in.next();
      if (k.is("}")) break;
      if (readTransform(k, in, g.transform)) continue;
      if (isWord(k, "gradient")) {
        gradient = true;
        g.axis = toVec3(in.parseVector());
      } else if (isColourStart(k)) {
        // A solid colour: the same colour along any gradient (a one-entry map).
        in.unget();
        gradient = true;
        g.colorMap = {{0.0, readColour(in).rgb}};
      } else if (isWord(k, "color_map") || isWord(k, "colour_map")) {
        SourceLoc mapLoc = k.loc();
        g.colorMap.clear();
        for (const PovColorMapEntry& e : readColorMap(in, mapLoc))
          g.colorMap.push_back({e.at, e.color});
      } else {
        unreadInBlock(k, in);  // said, and read to the pigment's '}'
        skipToClose(in, 1);    // and the sky_sphere's
        return;
      }
    }
    if (!gradient)
      keepError(in, t.loc(), "a sky_sphere's pigment other than a gradient is not read yet");
    sky.pigments.push_back(g);
  }
  const SkyImport imported = importSkySphere(sky);
  if (!imported.error.empty()) {
    keepError(in, loc, imported.error);
    return;
  }
  for (const std::string& d : imported.differences) warn(in, loc, d);
  scene_.sky = imported.sky;
}

}  // namespace lucent::sdl
