// POV-Ray 3.7's slope pattern (pattern.cpp, slope_pattern, as facts): the surface normal's
// angle to a direction, optionally mixed with the height along another.
#pragma once

#include "pattern_surface.h"
#include "scenegraph/pattern.h"

namespace lucent {

// The raw value at pattern-space point p (the altitude's height) on `surface` (null: no
// surface, 0 as POV-Ray's). In [0, 1).
double slopeValue(const SlopeParams& slope, const Vec3& p, const PatternSurface* surface);

}  // namespace lucent
