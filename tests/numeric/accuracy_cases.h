// The hard cases of the accuracy suite, one function per family. Each returns one
// CaseResult per (setting, shape) row of docs/accuracy.md's table, with the bounds the
// tests assert. `effort` multiplies the ray counts (1 in the tests, more for the table);
// the 10^6 rays from inside the tessellated sphere are always 10^6.
#pragma once

#include <vector>

#include "accuracy_harness.h"

namespace lucent::accuracy {

std::vector<CaseResult> baselineCases(double effort);  // random rays at unit scale, for comparison
std::vector<CaseResult> grazingCases(double effort);   // grazing and tangent rays, torus hole/axis
std::vector<CaseResult> farAndScaledCases(double effort);   // at 1e5; scaled by 1e-4 and 1e4
std::vector<CaseResult> secondaryRayCases(double effort);   // rays leaving a surface
std::vector<CaseResult> zeroDirectionCases(double effort);  // direction components exactly 0
std::vector<CaseResult> nearSingularCases(double effort);   // scale(1e-7 1 1), strong shear
// Meshes (accuracy_mesh_cases.cpp, the suite's one CGAL translation unit): 10^6 rays from
// inside a closed tessellated sphere, rays through shared edges and vertices and along
// edges, rays leaving the mesh, degenerate triangles.
std::vector<CaseResult> meshCases(double effort);
// Rays lying along a convex mesh's edges (they only touch it): a known defect, kept apart
// so its test can be marked as expected to fail (docs/accuracy.md).
std::vector<CaseResult> meshAlongEdgeCases(double effort);

// Superellipsoids (accuracy_superellipsoid_cases.cpp): nearly a cube, rays grazing its
// edges and corners and along its faces; tangent rays on convex and pinched ones; rays
// leaving the surface.
std::vector<CaseResult> superellipsoidCases(double effort);

// Quadrics and polys (accuracy_quadric_cases.cpp): a cylinder, a double cone and a plane
// written as quadrics; a torus as a quartic poly, the tangle cube, an ellipsoid of order 2.
std::vector<CaseResult> quadricCases(double effort);
// Blobs (accuracy_blob_cases.cpp): sphere and cylinder components, random and tangent rays;
// a strength just above the threshold; two spheres whose fields just merge; a carved hole;
// rays leaving the surface.
std::vector<CaseResult> blobCases(double effort);
// Prisms (accuracy_prism_cases.cpp): a star with a hole, rays through its vertices, along
// its side faces and grazing its caps' edges.
std::vector<CaseResult> prismCases(double effort);
// Lathes (accuracy_lathe_cases.cpp): a Bézier vase and a linear goblet, rays tangent to the
// silhouette, through the axis and at the rims where pieces meet.
std::vector<CaseResult> latheCases(double effort);

// Isosurfaces (accuracy_isosurface_cases.cpp): a sphere and a torus as functions, random
// and tangent rays; thin shells; a function steeper than its max-gradient; secondary rays.
std::vector<CaseResult> isosurfaceCases(double effort);
// Text (accuracy_text_cases.cpp): DejaVu Sans' o, 8 and e (holes), random rays, rays into the
// holes, along a glyph's edge and through the joins of its segments.
std::vector<CaseResult> textCases(double effort);
// Surfaces of revolution (accuracy_sor_cases.cpp): a vase, random rays, rays tangent to its
// silhouette, along and parallel to its axis, through its caps' rims; a bulb's poles.
std::vector<CaseResult> sorCases(double effort);
// Sphere sweeps (accuracy_sweep_cases.cpp): linear, Catmull-Rom and B-spline sweeps through
// the same spheres, random rays and rays tangent to the surface.
std::vector<CaseResult> sweepCases(double effort);
// Ovuses (accuracy_ovus_cases.cpp): POV-Ray's two forms, random rays, rays tangent to the
// surface, rays through the seams where the arc meets the spheres.
std::vector<CaseResult> ovusCases(double effort);
// Height fields (accuracy_height_field_cases.cpp): a 9 x 7 grid with a water level, random
// rays, rays edge-on along its grid lines and diagonals, rays along its grid edges.
std::vector<CaseResult> heightFieldCases(double effort);

// Every family, in the table's order.
std::vector<CaseResult> allCases(double effort);

}  // namespace lucent::accuracy
