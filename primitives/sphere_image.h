// A sphere carried into world space whole: what a similarity transform (uniform scale,
// rotation, mirror, translation) makes of a sphere is again a sphere. The world's
// top-level BVH keeps such spheres inline in world space, so a ray test needs neither a
// virtual call nor a matrix product nor a pointer to follow (aggregate.h).
#pragma once

#include "transform.h"

#include <optional>

namespace lucent {

struct SphereImage {
  Vec3 center;  // in the world
  double radius;
  // A bound (world units) on the distance between this sphere's surface and the exact
  // image of the object's sphere under the transform's stored matrix: the rounding of
  // the centre and the radius, and how far the matrix is from a true similarity. 0 for
  // the identity, whose image is the object's sphere itself.
  double error;
};

// The largest distortion accepted as a similarity: ‖LᵀL − s²I‖ ≤ kMaxDistortion·s², L the
// transform's linear part. Matrices composed of rotations, uniform scales and
// translations are within a few units of rounding of that (cos and sin are rounded); a
// sphere's image under such an L is an ellipsoid whose semi-axes differ from s·r by at
// most about kMaxDistortion/2 relative, a few times the rounding error of a ray's hit
// distance, and `error` accounts for it.
constexpr double kMaxDistortion = 64.0 * 2.0 * kMachineEps;

// The image of the sphere (center, radius) under worldFromObject, or nullopt when the
// transform is not a similarity to within kMaxDistortion or the image is not finite.
std::optional<SphereImage> sphereImage(const Transform& worldFromObject, const Vec3& center,
                                       double radius);

}  // namespace lucent
