// Where a value falls in a material map (scenegraph/material.h): POV-Ray's blend map
// search (its BlendMap::Search, as facts) over entries in ascending order. At or above the
// last entry's value: the last entry alone; at or below the first's: the first alone;
// between two entries: both, weighted linearly (the nearer the more); exactly at an
// entry's value: the first entry with that value alone.
#pragma once

#include "material.h"

#include <cstdint>
#include <vector>

namespace lucent {

struct MapBlend {
  uint32_t a = 0, b = 0;  // the entries, a == b when one alone
  float wa = 1.0f, wb = 0.0f;
};

MapBlend mapBlend(const std::vector<MaterialMapEntry>& entries, double v);

// A map whose pattern is an <average>: every entry is shaded and the colours averaged, each
// entry's `at` its weight (POV-Ray's average of textures), instead of a blend by value.
inline bool mapAverages(const Material& m) {
  return std::holds_alternative<AverageTexture>(m.mapPattern);
}

}  // namespace lucent
