// <pigment-function name component> children of an element whose function expression may
// call them (an <isosurface>, a <pattern type="function">): POV-Ray's
// `#declare F = function { pigment { P } }` with the component its `F(x, y, z).red` takes.
#pragma once

#include "element_reader.h"

#include "scenegraph/pigment_function.h"

#include <memory>
#include <vector>

namespace lucent {

// The <pigment-function> children of r's element, each with its texture child read; errors
// located at the child, and `failed` set when there was one.
std::vector<std::shared_ptr<const PigmentFunction>> parsePigmentFunctions(ElementReader& r,
                                                                          bool& failed);

}  // namespace lucent
