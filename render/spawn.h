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

}  // namespace lucent
