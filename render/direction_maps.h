// Sphere-of-directions maps shared by the panoramic cameras (octahedral, cube map, Fibonacci)
// in both directions: image position -> direction and direction -> image position, so images
// rendered with these cameras can be read back as reflection probes and light maps.
//
// Everything here works in CAMERA-LOCAL coordinates, x = right, y = up, z = forward (the
// CameraFrame's axes), and in NORMALISED image coordinates uv in [0,1]^2 with u from the
// left edge and v from the TOP edge (film position divided by the image size). The camera
// classes (octahedral.h, cubemap.h, fibonacci.h) add the frame and the pixel grid.
#pragma once

#include "camera_frame.h"

#include "scenegraph/camera.h"

#include <cstdint>

namespace lucent {

// A world direction in the frame's local coordinates (x right, y up, z forward).
inline Vec3 frameLocal(const CameraFrame& f, const Vec3& world) {
  return Vec3(glm::dot(world, f.right), glm::dot(world, f.up), glm::dot(world, f.forward));
}

// ---- Octahedral map (Engelhardt & Dachsbacher 2008; Cigolle et al. 2014, "A Survey of
// Efficient Representations for Independent Unit Vectors", JCGT 3(2)). The sphere is
// projected onto the octahedron |x|+|y|+|z| = 1, whose front half (z >= 0) is the diamond
// |p.x|+|p.y| <= 1 in the middle of the square and whose back half is folded out into the
// four corners. Centre of the image = forward, right edge midpoint = right, top edge
// midpoint = up, the four image corners = backward.
Vec3 octahedralDirection(const Vec2& uv);  // unit length
Vec2 octahedralUV(const Vec3& direction);  // direction need not be unit; never zero

// ---- Cube map: six 90-degree faces, each the image a 90-degree pinhole camera at the
// camera position would see (seen from inside, never mirrored).
enum class CubeFace { Right, Left, Up, Down, Back, Front };

struct CubeFaceAxes {
  Vec3 forward, right, up;  // local axes of the face's own pinhole view
};
// Side faces (right, left, back, front) are upright (image up = camera up). The up face
// has the back face above it in its image (its image up is -forward); the down face has
// the front face above it (image up = +forward). So in the cross the faces unfold without
// seams: the middle row is a 360-degree panorama left, front, right, back.
CubeFaceAxes cubeFaceAxes(CubeFace face);

// Grid size (columns x rows) of a layout, and which face sits in cell (col, row), row 0 at
// the top:
//   cross (4x3):   .     Up     .      .        strip (6x1):
//                 Left  Front  Right  Back      Right Left Up Down Back Front
//                  .    Down    .      .
// The strip is OpenGL's +X -X +Y -Y +Z -Z order for the default camera (looking down -z,
// +y up), with the orientations above.
int cubeLayoutColumns(CubemapLayout layout);
int cubeLayoutRows(CubemapLayout layout);
bool cubeFaceAt(CubemapLayout layout, int col, int row, CubeFace& face);  // false: empty cell
void cubeFaceCell(CubemapLayout layout, CubeFace face, int& col, int& row);

// The face a direction falls on: the largest |component| decides; exact ties (the cube's
// edges and corners) go to the first of x, y, z, so every direction has exactly one face.
CubeFace cubeFaceOf(const Vec3& direction);

// uv -> direction; false on an empty cell of the cross.
bool cubemapDirection(CubemapLayout layout, const Vec2& uv, Vec3& direction);
// Where a direction meets its face: st in [0,1]^2, s from the face image's left edge, t
// from its top edge.
struct CubeFacePoint {
  CubeFace face;
  Vec2 st;
};
CubeFacePoint cubeFacePoint(const Vec3& direction);
// direction -> uv; always inside (or on the border of) a face's cell, never on an empty one.
Vec2 cubemapUV(CubemapLayout layout, const Vec3& direction);

// ---- Fibonacci sphere (the spherical Fibonacci point set of Swinbank & Purser 2006 and
// Keinert et al. 2015, "Spherical Fibonacci Mapping"). Point k of n, k = 0 .. n-1:
//   y_k = 1 - (2k + 1) / n                    (height along camera up: equal-area bands)
//   phi_k = 2 pi frac(k (sqrt(5) - 1) / 2)     (golden-angle turns, measured from forward
//                                             towards right)
//   direction_k = (sqrt(1 - y_k^2) sin phi_k, y_k, sqrt(1 - y_k^2) cos phi_k)   (x right, y up, z
//   forward)
Vec3 fibonacciDirection(uint64_t k, uint64_t n);
// The index of the point nearest to a direction (smallest chord; ties go to the smaller
// index). Exact: the points are sorted by height, so it scans outwards from the band of
// the direction's height and stops once the height difference alone exceeds the best
// distance found, about 2 sqrt(n) points.
uint64_t nearestFibonacciIndex(const Vec3& direction, uint64_t n);

}  // namespace lucent
