// Secondary rays leaving a surface without re-hitting it: the primitives' robust origin
// offset (primitives/offset.h), or, when the scene sets <render epsilon>, a fixed offset
// of epsilon along the normal, as the user asked.
#pragma once

#include "primitives/hit.h"
#include "primitives/offset.h"
#include "primitives/ray.h"

#include <optional>

namespace lucent {

// A shadow ray stops this fraction of its length short of its light, so a light lying on
// a surface (an area light on its ceiling) is not hidden by that surface.
constexpr double kShadowRayEnd = 1.0 - 1e-6;

inline Vec3 spawnOrigin(const SurfaceInfo& s, const Vec3& dir, const std::optional<double>& eps) {
  if (eps) return s.p + (glm::dot(dir, s.ng) < 0.0 ? -*eps : *eps) * s.ng;
  return offsetRayOrigin(s.p, s.pError, s.ng, dir);
}

// A ray from the surface in direction dir (tmin 0, tmax ∞).
inline Ray spawnRay(const SurfaceInfo& s, const Vec3& dir, const std::optional<double>& eps) {
  return Ray(spawnOrigin(s, dir, eps), dir, 0.0, kInf);
}

// A shadow ray from the surface to the point `target`: d = target − origin, so t ∈ (0, 1)
// covers the segment.
inline Ray spawnRayTo(const SurfaceInfo& s, const Vec3& target, const std::optional<double>& eps) {
  Vec3 o = spawnOrigin(s, target - s.p, eps);
  return Ray(o, target - o, 0.0, kShadowRayEnd);
}

// spawnRayTo's rays from one surface point to many targets (the samples of an area
// light), the origin chosen from two computed once: spawnOrigin depends on the direction
// only through the side of the surface it points to (the sign of dir·ng). The same rays
// to the last bit, without an offset computed per ray.
class ShadowRays {
 public:
  ShadowRays(const SurfaceInfo& s, const std::optional<double>& eps)
      : p_(s.p), ng_(s.ng), front_(spawnOrigin(s, s.ng, eps)), back_(spawnOrigin(s, -s.ng, eps)) {}

  // Two returns rather than a selected origin: a branch (the side rarely changes between
  // the samples of one light) lets the ray's origin be read at once, where a conditional
  // move would make it wait for the dot product.
  Ray to(const Vec3& target) const {
    if (glm::dot(target - p_, ng_) < 0.0) return Ray(back_, target - back_, 0.0, kShadowRayEnd);
    return Ray(front_, target - front_, 0.0, kShadowRayEnd);
  }

 private:
  Vec3 p_, ng_;
  Vec3 front_, back_;  // the origins for targets on the side ng points to, and the other
};

}  // namespace lucent
