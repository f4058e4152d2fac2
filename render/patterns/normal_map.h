// POV-Ray 3.7's maps in a normal (normal.cpp, Perturb_Normal and Do_Slope_Map; the search
// is its Search_Blend_Map, taken as facts): a normal_map's or a block pattern's entries
// picked by the pattern's value, and a slope_map's heights.
#pragma once

#include "scenegraph/pattern.h"

#include <cstddef>
#include <vector>

namespace lucent {

// Where a value falls among entries in ascending `at` (each rounded to single precision,
// as POV-Ray stores a map's values): at or above the last, the last alone; at or below
// the first, the first alone; exactly at an entry's value, the first entry with it alone;
// else the two around it, `t` the upper one's share, (v − a)/(b − a).
struct MapSearch {
  size_t prev = 0, cur = 0;
  double t = 0.0;
};

template <class Entries>
MapSearch searchMap(const Entries& entries, double v) {
  auto at = [&](size_t i) { return static_cast<double>(static_cast<float>(entries[i].at)); };
  const size_t last = entries.size() - 1;
  MapSearch s;
  if (v >= at(last)) {
    s.prev = s.cur = last;
  } else {
    while (v > at(s.cur)) s.prev = s.cur++;
  }
  if (v == at(s.cur)) s.prev = s.cur;
  if (s.prev != s.cur) s.t = (v - at(s.prev)) / (at(s.cur) - at(s.prev));
  return s;
}

// A slope map's height at a pattern value: between entries (a, <h0, s0>) and (b, <h1, s1>)
// the Hermite cubic of t = (v − a)/(b − a) with end values h0, h1 and end slopes s0, s1
// (the slopes per unit of t, not of v); beyond the ends, the end entry's height.
double slopeMapHeight(const std::vector<SlopeMapEntry>& map, double value);

// The cell of a block pattern at a pattern-space point: checker 0 or 1 (POV-Ray's
// ⌊x + 1e-10⌋ + ⌊y + 1e-10⌋ + ⌊z + 1e-10⌋, odd 1), hexagon 0 to 2, brick 0 or 1.
int normalBlockIndex(const NormalSpec& normal, const Vec3& patternPoint);

}  // namespace lucent
