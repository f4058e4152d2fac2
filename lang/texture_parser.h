// The texture child of a <material>: the element names of the texture table
// (scenegraph/texture_spec.h) and the reader of each kind.
#pragma once

#include "element_reader.h"

#include "scenegraph/material.h"

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// The texture elements, in the table's order: what <material> takes as its colour child.
std::vector<std::string_view> textureElements();

// Reads the texture element t (its name is one of textureElements()).
Texture parseTexture(ElementReader& t);

// An error at t's `mapping` when `texture` (read from t) is uv-mapped where no (u,v) reach
// it (`where`: an entry of a map, a sky's layer, a pigment function's pigment).
void refuseUvMapping(ElementReader& t, const Texture& texture, const std::string& where);

}  // namespace lucent
