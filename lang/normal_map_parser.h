// The maps a <normal> may hold: <normal-map> (POV-Ray's normal_map), <normal-list> (a
// block pattern's normals) and <slope-map> (POV-Ray's slope_map).
#pragma once

#include "element_reader.h"

#include "scenegraph/pattern.h"

namespace lucent {

// <normal-map><entry at><normal/></entry>...</normal-map>: entries in ascending `at`.
std::vector<NormalMapEntry> parseNormalMap(ElementReader& r);

// <normal-list><entry><normal/></entry> or <entry/>...</normal-list>: `count` entries at
// 0, 1, 2...; an empty <entry/> leaves the normal unperturbed.
std::vector<NormalMapEntry> parseNormalList(ElementReader& r, size_t count);

// <slope-map><entry at height slope/>...</slope-map>: entries in ascending `at`.
std::vector<SlopeMapEntry> parseSlopeMap(ElementReader& r);

}  // namespace lucent
