#include "offset.h"

#include <cmath>

namespace lucent {

Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& ng, const Vec3& w) {
  // d is the distance along ng to the plane through the corner of the error box that lies
  // farthest along ng (pbrt-v3 §3.9.5, OffsetRayOrigin).
  double d = glm::dot(glm::abs(ng), pError);
  Vec3 side = glm::dot(w, ng) < 0.0 ? -ng : ng;
  Vec3 po = p + d * side;
  // The addition above may round back towards the surface: step one ulp further away.
  // Stepping by the sign of the side rather than of the offset (as pbrt does) also moves
  // the point when pError is 0 along the normal (a box face is exact), so the new origin
  // never lies on the surface it leaves.
  for (int i = 0; i < 3; ++i) {
    if (side[i] > 0.0)
      po[i] = std::nextafter(po[i], kInf);
    else if (side[i] < 0.0)
      po[i] = std::nextafter(po[i], -kInf);
  }
  return po;
}

}  // namespace lucent
