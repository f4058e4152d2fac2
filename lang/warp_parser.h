// <warp> children of a pattern element: the steps of its placement between its transform
// and its turbulence (scenegraph/pattern_warp.h), in the order written.
#pragma once

#include "element_reader.h"

#include "scenegraph/pattern.h"

namespace lucent {

// Every <warp> child of r, appended to `warps` in document order.
void parseWarps(ElementReader& r, std::vector<PatternWarp>& warps);

// Whether n is a <warp> (which parseWarps reads): the other child loops skip it.
inline bool isWarpElement(const pugi::xml_node& n) { return std::string_view(n.name()) == "warp"; }

}  // namespace lucent
