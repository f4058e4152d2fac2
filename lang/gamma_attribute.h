// An attribute that names a transfer curve: `srgb` or a number above 0 (<render
// working-gamma>, <image gamma>).
#pragma once

#include "element_reader.h"

#include "scenegraph/gamma_curve.h"

#include <optional>

namespace lucent {

// The curve the attribute names; none when absent or wrong (reported).
std::optional<GammaCurve> readGammaAttribute(ElementReader& r, const char* attr);

}  // namespace lucent
