// `warp { ... }` in pigments, normals and the patterns of maps: POV-Ray 3.7's warp list
// (parstxtr.cpp: Parse_Warp), whose transforms and warps apply in one order. Each warp
// becomes a step of the pattern's placement after the transforms written before it.
#include "read_support.h"
#include "scene_reader.h"

#include "lang/expression.h"

#include <algorithm>

namespace lucent::sdl {

namespace {

TurbulenceWarp readTurbulenceWarp(TokenStream& in) {
  TurbulenceWarp w;
  w.strength = toVec3(in.parseVector());
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) return w;
    if (isWord(k, "octaves")) w.octaves = std::clamp(static_cast<int>(in.parseFloat()), 1, 10);
    else if (isWord(k, "omega")) w.omega = in.parseFloat();
    else if (isWord(k, "lambda")) w.lambda = in.parseFloat();
    else in.error(k, "unexpected " + k.describe() + " in a turbulence warp");
  }
}

RepeatWarp readRepeatWarp(const Token& kind, TokenStream& in) {
  RepeatWarp w;
  const Vec3 d = toVec3(in.parseVector());
  const int axes = (d.x != 0.0) + (d.y != 0.0) + (d.z != 0.0);
  if (axes > 1) in.error(kind, "a repeat warp repeats along one axis only (POV-Ray's error)");
  if (axes == 0) in.error(kind, "a repeat warp needs an axis (POV-Ray's error)");
  w.axis = d.x != 0.0 ? 0 : d.y != 0.0 ? 1 : 2;
  w.width = d[w.axis];
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) return w;
    if (isWord(k, "offset")) {
      w.offset = toVec3(in.parseVector());
    } else if (isWord(k, "flip")) {
      const Vec3 f = toVec3(in.parseVector());
      for (int i = 0; i < 3; ++i) w.flip[i] = f[i] != 0.0;
    } else {
      in.error(k, "unexpected " + k.describe() + " in a repeat warp");
    }
  }
}

// POV-Ray's black hole of a type other than 0 moves nothing: nullopt.
std::optional<BlackHoleWarp> readBlackHoleWarp(TokenStream& in) {
  BlackHoleWarp w;
  w.center = toVec3(in.parseVector());
  in.allow(",");
  w.radius = in.parseFloat();
  int type = 0;
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) break;
    if (isWord(k, "strength")) w.strength = in.parseFloat();
    else if (isWord(k, "falloff")) w.falloff = in.parseFloat();
    else if (isWord(k, "inverse")) w.inverse = true;
    else if (isWord(k, "type")) type = static_cast<int>(in.parseFloat());
    else if (isWord(k, "repeat")) w.repeat = toVec3(in.parseVector());
    else if (isWord(k, "turbulence")) w.turbulence = toVec3(in.parseVector());
    else in.error(k, "unexpected " + k.describe() + " in a black hole warp");
  }
  if (type != 0) return std::nullopt;
  return w;
}

MappingWarp readMappingWarp(MappingWarpKind kind, TokenStream& in) {
  MappingWarp w;
  w.kind = kind;
  if (kind == MappingWarpKind::planar) {
    // `planar [<normal>, distance]`
    if (startsNumber(in.peek())) {
      w.orientation = glm::normalize(toVec3(in.parseVector()));
      in.allow(",");
      w.distance = in.parseFloat();
    }
    in.expect("}");
    return w;
  }
  for (;;) {
    const Token k = in.next();
    if (k.is("}")) return w;
    if (kind != MappingWarpKind::cubic && isWord(k, "orientation"))
      w.orientation = glm::normalize(toVec3(in.parseVector()));
    else if (kind != MappingWarpKind::cubic && isWord(k, "dist_exp")) w.distExp = in.parseFloat();
    else if (kind == MappingWarpKind::toroidal && isWord(k, "major_radius"))
      w.majorRadius = in.parseFloat();
    else
      in.error(k, "unexpected " + k.describe() + " in a " + std::string(mappingWarpName(kind)) +
                      " warp");
  }
}

}  // namespace

bool SceneReader::readWarp(const Token& t, TokenStream& in, PatternPlacement* placement,
                           PovTransform& transform) {
  if (!isWord(t, "warp")) return false;
  in.expect("{");
  const Token kind = in.next();
  std::optional<PatternWarp> warp;
  if (isWord(kind, "turbulence")) {
    warp = readTurbulenceWarp(in);
  } else if (isWord(kind, "repeat")) {
    warp = readRepeatWarp(kind, in);
  } else if (isWord(kind, "black_hole")) {
    if (std::optional<BlackHoleWarp> hole = readBlackHoleWarp(in)) {
      bool changed[3];
      settleBlackHole(*hole, changed);
      for (int a = 0; a < 3; ++a)
        if (changed[a])
          warn(in, kind.loc(),
               std::string("the black hole's repeat along ") + "xyz"[a] +
                   " is too small: increased to " + formatNumber(hole->repeat[a]) +
                   ", as POV-Ray does");
      warp = *hole;
    }
  } else {
    for (const MappingWarpName& m : kMappingWarpNames)
      if (isWord(kind, m.name)) warp = readMappingWarp(m.kind, in);
    if (!warp)
      in.error(kind,
               "a warp type expected (turbulence, repeat, black_hole, planar, spherical, "
               "cylindrical, toroidal or cubic), not " +
                   kind.describe());
  }
  if (!placement) {  // POV-Ray takes it, and a colour the same everywhere shows no move
    warn(in, t.loc(),
         "'warp { " + std::string(kind.text()) +
             " }' on a solid colour changes nothing (a warp moves a pattern): ignored");
    return true;
  }
  if (!warp) return true;
  // The transforms written so far come before the warp: a step of their own.
  if (!transform.isIdentity()) {
    placement->warps.push_back(TransformWarp{glm::inverse(transform.povMatrix())});
    transform = PovTransform();
  }
  placement->warps.push_back(*warp);
  return true;
}

}  // namespace lucent::sdl
