// The contract's `transform` attribute syntax: a list of operations applied in the order
// written (the first is applied first, as in POV-Ray and Mitsuba), so M = Tn·…·T2·T1.
//
//   translate(x y z)   scale(s)   scale(x y z)   rotate(angle, x y z)   (degrees, right-handed)
//   rotate-x(a)  rotate-y(a)  rotate-z(a)
//   matrix(12 numbers: 3 rows of 4, column-vector convention p' = A p + t)
//   matrix(16 numbers, row-major; the last row must be 0 0 0 1)
//
// Arguments are separated by spaces and/or commas; operations by spaces (a comma between
// operations is tolerated). An empty attribute is the identity.
#pragma once

#include "primitives/math.h"

#include <string>
#include <string_view>
#include <vector>

namespace lucent {

struct TransformSyntaxResult {
  Mat4 matrix{1.0};  // glm: column-major, matrix[col][row]
  bool ok = true;
  std::string error;       // without location; empty when ok
  size_t errorOffset = 0;  // byte offset of the problem inside the attribute value
  // Set when the error is an unknown operation name, so the caller can add a
  // "did you mean" hint among transformOperationNames().
  std::string unknownOperation;
};

TransformSyntaxResult parseTransformSyntax(std::string_view text);

// "translate", "scale", "rotate", "rotate-x", "rotate-y", "rotate-z", "matrix".
const std::vector<std::string>& transformOperationNames();

// Building blocks, exposed for tests and for the camera's look-at frame.
Mat4 translationMatrix(const Vec3& t);
Mat4 scaleMatrix(const Vec3& s);
// Right-handed rotation by `degrees` about the unit `axis` through the origin. Multiples
// of 90 degrees give exact 0/±1 entries (sin/cos of radians(90) are not exact).
Mat4 rotationMatrix(double degrees, const Vec3& axis);

}  // namespace lucent
