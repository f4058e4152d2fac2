// Colours from pattern values: POV-Ray 3.7's colour map (pattern.cpp Search_Blend_Map,
// pigment.cpp Compute_Pigment).
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The colour at value v: linear between the two entries around v, the first or last
// entry's colour beyond the ends, an entry's own colour at its position. Two entries at
// one position make a sharp step: the first one's colour at the position itself, the
// second one's just above. Entries must be sorted by `at`. POV-Ray keeps
// the positions in single precision and blends in float; so does this. An empty map is
// [0 black][1 white]: the grey level of v, clamped.
Color lookupColorMap(const ColorMap& map, double v);

// The same lookup with the entries' filter and transmit, interpolated as the colour (as
// POV-Ray blends all five channels of its colours).
PigmentColor lookupColorMapFT(const ColorMap& map, double v);

// lookupColorMap of patternValue(spec, objectPoint).
Color patternColor(const PatternSpec& spec, const ColorMap& map, const Vec3& objectPoint);

}  // namespace lucent
