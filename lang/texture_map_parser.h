// Maps and lists of whole textures: <pigment-map> (a <pattern>'s, POV-Ray's pigment_map),
// <pigment-list> (a block pattern's pigments), <average> (a texture kind) and
// <normal type="average">'s entries. Each <entry> holds a plain colour (color, filter,
// transmit) or one texture element, which may itself hold maps.
#pragma once

#include "element_reader.h"

#include "scenegraph/material.h"

#include <memory>
#include <string_view>

namespace lucent {

// <pigment-map><entry at>...</entry>...</pigment-map>: at from 0 to 1, never decreasing.
std::vector<TextureMapEntry> parsePigmentMap(ElementReader& r);

// <pigment-list> of exactly `count` entries (without at), for the block pattern `owner`.
std::vector<TextureMapEntry> parsePigmentList(ElementReader& r, size_t count);

// <pigment color filter transmit/> or <pigment> holding one texture element: the pigment
// of <pattern type="pigment-pattern"> and of such a <normal>.
std::shared_ptr<const TextureMapEntry> parsePatternPigment(ElementReader& r);

// <average transform turbulence...><entry weight>...</entry>...</average>.
Texture parseAverageTexture(ElementReader& r);

// The <entry weight><normal .../></entry> children of <normal type="average">.
std::vector<WeightedNormal> parseNormalAverage(ElementReader& r);

}  // namespace lucent
