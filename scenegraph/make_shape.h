// Builds the primitive for a geometry element's parameters.
#pragma once

#include "shape_spec.h"

#include "primitives/shape.h"

#include <memory>

namespace lucent {

std::shared_ptr<const Shape> makeShape(const ShapeSpec& spec);

}  // namespace lucent
