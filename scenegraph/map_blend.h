// Where a value falls in a material map (scenegraph/material.h): POV-Ray's blend map
// search (its BlendMap::Search, as facts) over entries in ascending order. At or above the
// last entry's value: the last entry alone; at or below the first's: the first alone;
// between two entries: both, weighted linearly (the nearer the more); exactly at an
// entry's value: the first entry with that value alone.
#pragma once

#include "image_pattern.h"
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

// A map whose pattern is an image read by index (POV-Ray's material_map): its image, or null.
inline const ImagePattern* mapIndexImage(const Material& m) {
  const auto* p = std::get_if<PatternTexture>(&m.mapPattern);
  return p && p->pattern.image && p->pattern.image->byIndex ? p->pattern.image.get() : nullptr;
}

// The entry POV-Ray 3.7's material_map shows for material number `number` among `count`
// entries (imageutil.cpp, as facts): a number above the count is taken modulo the count,
// then the list is walked that far, stopping at its last entry; a negative number (a bicubic
// blend's undershoot) stays at the first. So with 3 entries 3 shows the last and 4 the second.
inline MapBlend mapIndexEntry(int number, size_t count) {
  const auto n = static_cast<long long>(count);
  long long k = number;
  if (k > n) k %= n;
  k = k < 0 ? 0 : k >= n ? n - 1 : k;
  return {static_cast<uint32_t>(k), static_cast<uint32_t>(k), 1.0f, 0.0f};
}

}  // namespace lucent
