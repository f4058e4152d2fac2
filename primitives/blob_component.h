// One component of a blob (primitives/blob.h), as the scene gives it.
#pragma once

#include "math.h"

namespace lucent {

struct BlobComponent {
  enum Kind { Sphere, Cylinder } kind = Sphere;
  Vec3 a{0.0};            // the sphere's centre, or the cylinder's base
  Vec3 b{0.0, 1.0, 0.0};  // the cylinder's cap (unused for a sphere)
  double radius = 1.0;    // > 0
  double strength = 1.0;  // may be negative
  // From the component's own space, where the fields above describe it, to the blob's:
  // an ellipsoid is a sphere scaled unevenly (POV-Ray's transformed components). Affine
  // and invertible.
  Mat4 transform{1.0};
};

}  // namespace lucent
