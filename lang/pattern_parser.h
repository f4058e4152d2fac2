// Parsers of the contract's colour patterns (<pattern>, <hexagon>, <brick>, textures of a
// <material>) and of <normal> and <bump-map>: the elements, their placement attributes and
// <color-map>.
#pragma once

#include "element_reader.h"

#include "scenegraph/material.h"

#include <optional>

namespace lucent {

Texture parsePatternTexture(ElementReader& r);
Texture parseHexagonTexture(ElementReader& r);
Texture parseBrickTexture(ElementReader& r);
NormalSpec parseNormal(ElementReader& r);
// An error at r's `mapping` when the normal read from r, an entry of a map, list or average,
// is uv-mapped (its map's point reaches it, not the shape's (u,v)).
void refuseNormalUvMapping(ElementReader& r, const NormalSpec& n);
// turbulence="s" or "x y z", each >= 0 (POV-Ray's vector): the strength per axis, shared by
// patterns and fog; nullopt when absent or wrong (reported).
std::optional<Vec3> parseTurbulenceStrength(ElementReader& r);
// The placement attributes every pattern element takes (transform, turbulence, octaves,
// omega, lambda), and their names.
PatternPlacement parsePlacement(ElementReader& r);
// A colour's filter and transmit from the attributes "filter" + n and "transmit" + n (any
// number each, default 0).
FilterTransmit parseFilterTransmit(ElementReader& r, const std::string& n);
// <color-map><entry at color filter transmit/>...</color-map>.
ColorMap parseColorMap(ElementReader& r);

const std::vector<std::string_view>& placementAttributes();

// The attributes <image> and <bump-map> share: `projection` (uv, planar, spherical,
// cylindrical, torus), a projected one's placement (placementAttributes; an error at (u,v)),
// `once` and `interpolate`.
const std::vector<std::string_view>& imageReadingAttributes();
void parseImageReading(ElementReader& r, ImageProjection& projection, PatternPlacement& placement,
                       bool& once, ImageInterpolation& interpolation);
// A block pattern's (checker, hexagon, brick) optional <pigment-list> child of `count`
// entries; an element with one must not have the attributes `colours` too.
std::vector<TextureMapEntry> parseBlockPigments(ElementReader& r, size_t count,
                                                const std::vector<std::string_view>& colours);
// The child loop of <image> and <bump-map>: a projected one's <warp>s only (and the
// children named `alsoAllowed`, which the caller reads).
void noChildrenButWarps(ElementReader& r, ImageProjection projection,
                        std::string_view alsoAllowed = {});
// <bump-map src depth>: src is resolved by the file-access rules, as <image>'s.
BumpMapSpec parseBumpMap(ElementReader& r);

}  // namespace lucent
