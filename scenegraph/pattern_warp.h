// The steps of a pattern's placement besides its transform and turbulence: POV-Ray 3.7's
// warp list (warps.cpp: Warp_EPoint), in which a pattern's transforms and its `warp { }`
// blocks form one ordered list. The renderer applies them in render/patterns/warp.cpp.
#pragma once

#include "primitives/math.h"

#include <string_view>
#include <variant>
#include <vector>

namespace lucent {

// A transform between warps: the point is carried by patternFromPrevious (the inverse of
// the transform written).
struct TransformWarp {
  Mat4 patternFromPrevious{1.0};
};

// POV-Ray's `warp { turbulence V octaves omega lambda }`: the point displaced by the vector
// turbulence times V (per axis), on every pattern, wood and marble included.
struct TurbulenceWarp {
  Vec3 strength{0.0};
  int octaves = 6;
  double omega = 0.5;
  double lambda = 2.0;
};

// `repeat <dir> offset flip`: the slab [0, width) along `axis` repeated; every odd slab
// mirrored on the axes whose flip is set and each slab n moved by n·offset.
struct RepeatWarp {
  int axis = 0;        // 0, 1, 2: x, y, z
  double width = 1.0;  // the direction's component along the axis (may be negative)
  Vec3 offset{0.0};
  bool flip[3] = {false, false, false};
};

// `black_hole <center>, radius strength falloff inverse repeat turbulence`: a point at
// distance d < radius from the centre moves away from it by s = min(1, strength·((radius −
// d)/radius)^falloff) times its offset (towards it when inverse), so the pattern looks
// sucked in (pushed out); with a repeat, one hole in every cell of that size (axes whose
// repeat is 0 are not repeated), each centre moved by a random fraction of `turbulence`
// (POV-Ray's table, the same for the same cell).
struct BlackHoleWarp {
  Vec3 center{0.0};
  double radius = 1.0;
  double strength = 1.0;
  double falloff = 2.0;
  bool inverse = false;
  Vec3 repeat{0.0};
  Vec3 turbulence{0.0};
};

// The mapping warps: a surface's 2-D coordinates laid on the x-y plane (z the distance),
// then turned so that z becomes `orientation` (POV-Ray's orientation vector, unit length).
enum class MappingWarpKind { planar, spherical, cylindrical, toroidal, cubic };
struct MappingWarp {
  MappingWarpKind kind = MappingWarpKind::spherical;
  Vec3 orientation{0.0, 0.0, 1.0};
  double distExp = 0.0;      // spherical, cylindrical, toroidal: the coordinates times d^distExp
  double distance = 0.0;     // planar: the z every point gets
  double majorRadius = 1.0;  // toroidal
};

using PatternWarp =
    std::variant<TransformWarp, TurbulenceWarp, RepeatWarp, BlackHoleWarp, MappingWarp>;

// The names of the mapping warps in Lucent's language and in POV-Ray's.
struct MappingWarpName {
  MappingWarpKind kind;
  std::string_view name;
};
inline constexpr MappingWarpName kMappingWarpNames[] = {
    {MappingWarpKind::planar, "planar"},
    {MappingWarpKind::spherical, "spherical"},
    {MappingWarpKind::cylindrical, "cylindrical"},
    {MappingWarpKind::toroidal, "toroidal"},
    {MappingWarpKind::cubic, "cubic"}};

constexpr std::string_view mappingWarpName(MappingWarpKind kind) {
  for (const MappingWarpName& n : kMappingWarpNames)
    if (n.kind == kind) return n.name;
  return "";
}

// POV-Ray's parser raises a repeated black hole's centre to at least its radius and its
// repeat to at least centre + radius + turbulence on each repeated axis (Check_BH_Parameters);
// the axes it changed are set in `changed` (x, y, z).
void settleBlackHole(BlackHoleWarp& hole, bool changed[3]);

}  // namespace lucent
