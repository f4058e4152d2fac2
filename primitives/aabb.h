// Axis-aligned bounding box and the Kay–Kajiya slab test.
#pragma once

#include "interval.h"
#include "math.h"
#include "ray.h"

namespace lucent {

struct AABB {
  Vec3 lo{kInf};
  Vec3 hi{-kInf};

  AABB() = default;
  AABB(const Vec3& lo_, const Vec3& hi_) : lo(lo_), hi(hi_) {}

  static AABB everything() { return {Vec3(-kInf), Vec3(kInf)}; }

  bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
  bool isBounded() const { return isFinite(lo) && isFinite(hi); }
  Vec3 center() const { return 0.5 * (lo + hi); }
  Vec3 extent() const { return hi - lo; }
  double surfaceArea() const;

  void expand(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void expand(const AABB& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  static AABB join(const AABB& a, const AABB& b) {
    AABB r = a;
    r.expand(b);
    return r;
  }
  static AABB meet(const AABB& a, const AABB& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
  }
  bool contains(const Vec3& p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  }

  // Slab test: the part of [ray.tmin, ray.tmax] inside the box, or an empty interval.
  // invDir = 1/ray.d componentwise (±inf for ±0 components: IEEE division keeps the sign).
  // Correct for zero direction components, origins inside the box and on a slab plane,
  // and robust against rounding (Ize 2013, "Robust BVH Ray Traversal": the far distance
  // is widened by 1 + 2·gamma(3), so no ray slips between boxes that share a face).
  Interval slab(const Ray& ray, const Vec3& invDir) const;
  bool hit(const Ray& ray, const Vec3& invDir) const { return !slab(ray, invDir).empty(); }
};

// Bounds of a box after an affine transform (the box of its eight transformed corners).
AABB transformBounds(const Mat4& m, const AABB& b);

}  // namespace lucent
