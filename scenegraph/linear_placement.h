// The linear part of a pattern's placement, shared by the renderer, the importer and the
// POV-Ray writer: a map's entries are placed by it (render/map_entries.h).
#pragma once

#include "pattern.h"

namespace lucent {

// patternFromObject and then every transform between the warps (POV-Ray's Warp_Normal
// uses only the transforms): for normals, error bounds and a map's entries.
inline Mat4 linearPatternFromObject(const PatternPlacement& placement) {
  Mat4 m = placement.patternFromObject;
  for (auto w = placement.warps.rbegin(); w != placement.warps.rend(); ++w)
    if (const auto* t = std::get_if<TransformWarp>(&*w)) m = t->patternFromPrevious * m;
  return m;
}

}  // namespace lucent
