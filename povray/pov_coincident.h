// Where two operands of a CSG operation have surfaces in one place, found before POV-Ray
// renders. There POV-Ray compares two distances that are equal up to rounding, so each
// pixel takes one surface or the other (speckles); Lucent decides such places by its rule
// (docs/csg.md, "Coincident surfaces"), so the two images differ there. `export-pov` and
// `compare` say where.
//
// Found exactly for the common case, faces of axis-aligned boxes (and planes along an
// axis) lying in one plane with overlapping area; for other shapes, two operands with the
// same bounding box (such as the same sphere written twice). Surfaces that coincide in other
// ways (a sphere touching a tilted box face) are not found.
#pragma once

#include "pov_writer.h"

#include "scenegraph/node.h"

namespace lucent {

// Warns through `issues`, at the CSG node, naming the first pair of operands found (the
// operands are compared in the node's own space: where the node is placed does not matter).
void warnCoincidentSurfaces(const Node& csg, PovIssues& issues);

}  // namespace lucent
