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

// POV-Ray's search of a map (Search_Blend_Map), for any entries with a position `at`: the
// first entry at or above v (the last if v is past it) and the one before it; at an
// entry's own position both are that entry. `fraction` is how far v lies from the first
// towards the second. The positions are taken in single precision, as POV-Ray keeps them.
struct MapSpan {
  size_t a = 0, b = 0;
  double fraction = 0.0;
};
template <class Entry>
MapSpan mapSpanAt(const Entry* e, size_t n, double v) {
  auto position = [&](size_t i) { return static_cast<double>(static_cast<float>(e[i].at)); };
  size_t prev, cur;
  if (v >= position(n - 1)) {
    prev = cur = n - 1;
  } else {
    prev = cur = 0;
    while (v > position(cur)) prev = cur++;
  }
  if (v == position(cur)) prev = cur;
  if (prev == cur) return {cur, cur};
  // The span is a difference of two floats, so POV-Ray computes it in float.
  const float span = static_cast<float>(e[cur].at) - static_cast<float>(e[prev].at);
  return {prev, cur, (v - position(prev)) / static_cast<double>(span)};
}

// a + (b − a)·fraction for the colour, the filter and the transmit: the float difference
// scaled in double and rounded back to float, as POV-Ray's colours.
PigmentColor blendPigments(const PigmentColor& a, const PigmentColor& b, double fraction);

// lookupColorMap of patternValue(spec, objectPoint).
Color patternColor(const PatternSpec& spec, const ColorMap& map, const Vec3& objectPoint);

}  // namespace lucent
