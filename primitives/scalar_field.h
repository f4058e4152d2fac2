// A scalar function of a point in object space, for shapes defined by one (the isosurface).
// primitives/ knows only this interface: the scene language implements it over its
// expressions (lang/expression_field.h), the tests over plain C++ functions.
#pragma once

#include "math.h"

namespace lucent {

class ScalarField {
 public:
  virtual ~ScalarField() = default;
  // The value at p. Called concurrently from the render threads: it must be thread-safe and
  // should allocate nothing.
  virtual double value(const Vec3& p) const = 0;
};

}  // namespace lucent
