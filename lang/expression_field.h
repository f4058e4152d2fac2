// A function expression (expression.h, compileFunction) as a ScalarField for the
// primitives: f(x, y, z) evaluated by muParser. A muParser parser is not reentrant, so each
// render thread compiles its own copy the first time it evaluates the field, and reuses it
// after: an evaluation allocates nothing.
#pragma once

#include "expression.h"

#include "primitives/scalar_field.h"

#include <memory>

namespace lucent {

// `f` has the variables x, y and z (in that order), or two, u and v (a parametric's
// coordinate functions), which take the point's x and y. A non-finite result is returned
// as it is (the isosurface takes NaN for outside).
std::shared_ptr<const ScalarField> makeExpressionField(FunctionText f);

}  // namespace lucent
