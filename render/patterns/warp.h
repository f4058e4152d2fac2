// POV-Ray 3.7's warps (warps.cpp: Warp_EPoint) applied to a pattern-space point.
#pragma once

#include "scenegraph/linear_placement.h"
#include "scenegraph/pattern.h"

namespace lucent {

// The point carried through the warps, the last written first (POV-Ray's list order).
Vec3 applyWarps(const std::vector<PatternWarp>& warps, Vec3 p);

}  // namespace lucent
