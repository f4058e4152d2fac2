#include "pattern_point.h"

#include "scenegraph/turbulence.h"
#include "warp.h"

namespace lucent {

Vec3 toPatternSpace(const Mat4& m, const Vec3& p) {
  Vec3 q;
  for (int i = 0; i < 3; ++i) q[i] = p.x * m[0][i] + p.y * m[1][i] + p.z * m[2][i] + m[3][i];
  return q;
}

Vec3 warpPoint(const PatternPlacement& placement, const Vec3& objectPoint, bool displace) {
  Vec3 p = toPatternSpace(placement.patternFromObject, objectPoint);
  if (!placement.warps.empty()) p = applyWarps(placement.warps, p);
  const Vec3& t = placement.turbulence;
  if (displace && (t.x != 0.0 || t.y != 0.0 || t.z != 0.0)) {
    const Vec3 d = dturbulence(p, placement);
    p.x += d.x * t.x;
    p.y += d.y * t.y;
    p.z += d.z * t.z;
  }
  return p;
}

}  // namespace lucent
