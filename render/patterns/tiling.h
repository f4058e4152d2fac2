// POV-Ray 3.7's `tiling N` pattern: 27 tilings of the x-z plane (docs/scene-language.md,
// "tiling"). Each returns a value in [0, 1]: with one kind of tile, 1 on the tiles' edges
// falling towards their middles; with several kinds, each kind (or orientation) its own
// band of values, so a colour map tells the tiles apart.
#pragma once

#include "primitives/math.h"

namespace lucent {

inline constexpr int kTilingCount = 27;

// The value of tiling `number` (1..kTilingCount; others give tiling 1, as POV-Ray) at p.
double tilingValue(int number, const Vec3& p);

}  // namespace lucent
