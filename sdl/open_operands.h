// POV-Ray's CSG of objects that have no inside (triangle, polygon, bicubic_patch, parametric,
// a mesh without inside_vector): POV-Ray's Inside of such an object is always false, even
// inverted (as a difference's later operands are), and an operation keeps each operand's
// surface where the others' memberships say. So in an intersection or a difference with
// one open operand only that operand's surface shows, cut by the solids (with two, nothing);
// in a merge the solids merge and each open operand shows outside them. Lucent's CSG takes
// solids only: the operation is rewritten as a union of those pieces, each open operand
// clipped by the solids (inside them, or outside: inverse).
#pragma once

#include "scenegraph/node.h"

namespace lucent::sdl {

// Rewrites `csg` (a merge, intersection or difference read from POV-Ray) in place when some
// of its operands have no inside and the others are solids; leaves it as it is otherwise.
// False when nothing of it is left (the object is then dropped: an empty union is no
// scene's).
bool rewriteOpenOperands(Node& csg);

}  // namespace lucent::sdl
