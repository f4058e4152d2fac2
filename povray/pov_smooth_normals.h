// Where Lucent's smooth shading and POV-Ray 3.7's part ways, found before POV-Ray renders.
//
// Near a silhouette the normal interpolated from vertex normals can face away from the
// viewer while the triangle itself faces the viewer. Lucent then shades with the
// triangle's own normal (render/tracer.cpp: the face stays lit); POV-Ray turns the
// interpolated normal towards the viewer, so light from the viewer's side falls behind it
// and a thin sliver goes dark. Lucent keeps its rule (the dark sliver is an artifact);
// `export-pov` and `compare` say where the two can differ.
#pragma once

#include "pov_writer.h"

#include "scenegraph/node.h"

#include <array>
#include <vector>

namespace lucent {

// The largest angle (radians) between the normal interpolated over triangle `p` from the
// vertex normals `n` and the triangle's own normal, each turned to the same side as
// Lucent turns them (either may be flipped to the other's side, so an inward normal is
// as good as an outward one). pi/2 when the vertex normals lie on both sides of the face:
// the interpolated normal then lies in the face's plane (or vanishes) somewhere.
double smoothNormalDeviation(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n);

// Warns through `issues`, at the node, when `node` is a <triangle> with vertex normals or
// a <mesh> whose rendering uses vertex normals, and the rule above can tell Lucent's image
// from POV-Ray's on it. PovIssues keeps one warning per node however often it is written.
void warnSmoothNormalRule(const Node& node, PovIssues& issues);

}  // namespace lucent
