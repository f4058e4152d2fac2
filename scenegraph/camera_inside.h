// Which cameras stand inside an opaque solid. The rays of such a camera start inside it, so
// each of its surfaces they meet is seen from inside, where the contract multiplies the
// ambient term by k_t: 0 for an opaque material. A common POV-Ray idiom (the camera on
// the inner side of a plane) thus darkens a scene without an error, so the parser warns.
#pragma once

#include "scene.h"

#include <vector>

namespace lucent {

struct CameraInSolid {
  const Camera* camera = nullptr;
  // The top-level object the renderer tests, as written: a shape, or a CSG node taken
  // whole (groups and <use> are looked through, as the world builder does).
  const Node* solid = nullptr;
};

// For every camera, each top-level solid that contains its position (after the camera's
// transform), whose surfaces are all opaque (no transmissive material: a camera inside
// glass or water is meant) and have an ambient term to lose (some material with a non-zero
// ambient, under a non-zero global ambient: a sky dome that only emits loses nothing). In
// the order of the cameras, then of the scene.
std::vector<CameraInSolid> camerasInsideOpaqueSolids(const Scene& scene);

}  // namespace lucent
