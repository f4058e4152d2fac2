// POV-Ray 3.7's `pavement` pattern: the x-z plane paved with tiles made of 1 to 6
// triangles, squares or hexagons (docs/scene-language.md, "pavement"). The value is 0 deep
// inside a tile and rises to 1 on its border.
#pragma once

#include "primitives/math.h"
#include "scenegraph/pattern.h"

namespace lucent {

// How many arrangements POV-Ray has of tiles of `tiles` cells with `sides` sides (0 for
// combinations it refuses).
int pavementCount(int sides, int tiles);

// The pavement's value at p (y is ignored); p's x and z in cells of side 1.
double pavementValue(const PavementParams& params, const Vec3& p);

// The pavements of 3 and 6 sides (pavement_triangles.cpp), which pavementValue calls.
double pavementTrianglesValue(const PavementParams& params, const Vec3& p);

}  // namespace lucent
