#include "aabb.h"

#include <algorithm>

namespace lucent {

double AABB::surfaceArea() const {
  if (empty()) return 0.0;
  Vec3 e = extent();
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Interval AABB::slab(const Ray& ray, const Vec3& invDir) const {
  double t0 = ray.tmin, t1 = ray.tmax;
  for (int a = 0; a < 3; ++a) {
    // A zero direction component makes invDir infinite. The product (lo - o)·inf is NaN
    // only when the origin lies exactly on the slab plane; the ray then runs inside
    // the plane, which we count as inside the slab (closed box) by skipping the axis.
    if (ray.d[a] == 0.0) {
      if (ray.o[a] < lo[a] || ray.o[a] > hi[a]) return {};
      continue;
    }
    double tNear = (lo[a] - ray.o[a]) * invDir[a];
    double tFar = (hi[a] - ray.o[a]) * invDir[a];
    if (tNear > tFar) std::swap(tNear, tFar);
    tFar += std::abs(tFar) * 2.0 * gamma(3);
    // Written so that a NaN (from an infinite box side) never narrows the interval.
    t0 = tNear > t0 ? tNear : t0;
    t1 = tFar < t1 ? tFar : t1;
    if (t0 > t1) return {};
  }
  return {t0, t1};
}

AABB transformBounds(const Mat4& m, const AABB& b) {
  if (b.empty()) return b;
  if (!b.isBounded()) {
    // Interval arithmetic row by row, a zero entry leaving its (maybe infinite) input out:
    // a half-space or an infinite cylinder stays bounded across its axis under a scale or a
    // turn that keeps the axis, and under any other map it becomes unbounded where it must.
    AABB out;
    for (int i = 0; i < 3; ++i) {
      double lo = m[3][i], hi = m[3][i];
      for (int j = 0; j < 3; ++j) {
        const double e = m[j][i];
        if (e == 0.0) continue;
        const double a = e * b.lo[j], c = e * b.hi[j];
        lo += std::min(a, c);
        hi += std::max(a, c);
      }
      out.lo[i] = lo;
      out.hi[i] = hi;
    }
    return out;
  }
  AABB out;
  for (int i = 0; i < 8; ++i) {
    Vec3 c((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
    out.expand(Vec3(m * Vec4(c, 1.0)));
  }
  return out;
}

}  // namespace lucent
