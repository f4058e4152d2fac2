// POV-Ray 3.7's block patterns, hexagon and brick (pattern.cpp): each point takes one of a
// few colours, never a blend.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The hexagon index 0, 1 or 2 of a pattern-space point in POV-Ray's tiling of the x-z
// plane (y is ignored): hexagons one unit across the flats, built on a 6×6 grid of
// half-triangles 0.5 wide and √3/2 high.
int hexagonIndex(const Vec3& patternPoint);

// 1 inside a brick, 0 in the mortar: rows `size.y` high in y, bricks `size.x` long in x
// and `size.z` deep in z, every other row shifted by half a brick, mortar `mortar` thick
// (POV-Ray keeps it in single precision, less 2e-10).
int brickIndex(const BrickSpec& brick, const Vec3& patternPoint);

// The colours at a pattern-space point; warpPoint (pattern_point.h) gives that point from
// an object point with the pattern's placement and turbulence.
Color hexagonColor(const HexagonSpec& hexagon, const Vec3& patternPoint);
Color brickColor(const BrickSpec& brick, const Vec3& patternPoint);

}  // namespace lucent
