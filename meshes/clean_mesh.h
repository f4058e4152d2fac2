// The fast path of mesh loading: a triangle soup that is already a clean, closed solid
// needs none of CGAL's repairs, and checking that takes a few sorted arrays where CGAL's
// pipeline (repair, orient, halfedge mesh, triangulate, orient to bound a volume) holds
// several copies of the mesh in larger structures. soup_repair.cpp tries this first and falls
// back to CGAL whenever the check cannot vouch for the soup.
#pragma once

#include "primitives/mesh_data.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace lucent {

// The mesh CGAL's pipeline would make of the soup, when the soup is (after merging points
// with identical coordinates) a single connected, closed, edge- and vertex-manifold
// surface whose triangles are consistently oriented and certainly of nonzero area: then
// the repairs change nothing and only the global orientation is left, which the sign of
// the enclosed volume decides (outward: positive). Positions are numbered in the order
// the triangles first use them, as soup_repair.cpp numbers CGAL's result. Returns nullopt
// (the caller runs CGAL) for anything else: open or non-manifold surfaces, several
// shells (their nesting decides their orientation), triangles whose area a double
// filter cannot prove nonzero, a volume too small to have a certain sign.
// Indices must be < points.size() (checked by the caller).
std::optional<MeshData> cleanClosedMesh(const std::vector<Vec3>& points,
                                        const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace lucent
