// Repairing triangle soups into meshes (soup_repair.cpp, through CGAL's polygon mesh
// processing): coincident points merged, degenerate and duplicate faces dropped, faces
// oriented to agree, and a closed mesh turned to bound its volume (then it is a solid).
#pragma once

#include "mesh_error.h"

#include "primitives/mesh_data.h"

namespace lucent {

// For meshes built in memory (inline <mesh>): repairs and orients the triangles where that
// is possible and sets `closed`. Throws MeshError if no usable triangle remains.
void finishMesh(MeshData& mesh);

}  // namespace lucent
