// Helpers shared by the primitives tests: seeded random geometry and the contract checks
// every shape must pass (shape.h).
#pragma once

#include "primitives/shape.h"

#include <random>
#include <string>

namespace lucent::test {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline Vec3 randomUnit(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    Vec3 v(n(rng), n(rng), n(rng));
    double l = glm::length(v);
    if (l > 1e-6) return v / l;
  }
}

inline Vec3 randomInBox(Rng& rng, const Vec3& lo, const Vec3& hi) {
  return {uniform(rng, lo.x, hi.x), uniform(rng, lo.y, hi.y), uniform(rng, lo.z, hi.z)};
}

// A ray from a random point on a sphere around `box` (radius `spread` times the box's
// half-diagonal) towards a random point of the box, with a random non-unit speed.
inline Ray randomRayAt(Rng& rng, const AABB& box, double spread = 3.0) {
  Vec3 c = box.center();
  double r = 0.5 * glm::length(box.extent());
  Vec3 o = c + spread * r * randomUnit(rng);
  Vec3 target = randomInBox(rng, box.lo, box.hi);
  return Ray(o, (target - o) * uniform(rng, 0.25, 4.0));
}

// Describes the first way `out` breaks the crossings contract for `ray`, or "" when it
// keeps it: sorted by t, within [tmin, tmax], each naming `shape`; for solids alternating
// from startsInside; for surfaces all entering with startsInside false.
inline std::string crossingsViolation(const Shape& shape, const Ray& ray, const CrossingList& out) {
  bool in = out.startsInside;
  if (!shape.isSolid() && in) return "a surface starts inside";
  double last = -kInf;
  for (const Crossing& c : out.items) {
    if (!(ray.tmin <= c.hit.t && c.hit.t <= ray.tmax)) return "crossing outside [tmin, tmax]";
    if (c.hit.t < last) return "crossings not sorted";
    if (c.hit.shape != &shape) return "crossing names another shape";
    last = c.hit.t;
    if (!shape.isSolid()) {
      if (!c.entering) return "a surface crossing marked leaving";
      continue;
    }
    if (c.entering == in) return in ? "entering while inside" : "leaving while outside";
    in = c.entering;
  }
  return "";
}

// The closest hit must be the first crossing strictly inside (tmin, tmax).
inline std::string intersectAgreesWithCrossings(const Shape& shape, const Ray& ray) {
  CrossingList cl;
  shape.crossings(ray, cl);
  std::string v = crossingsViolation(shape, ray, cl);
  if (!v.empty()) return v;
  const Crossing* first = nullptr;
  for (const Crossing& c : cl.items)
    if (ray.tmin < c.hit.t && c.hit.t < ray.tmax) {
      first = &c;
      break;
    }
  Hit h;
  bool hit = shape.intersect(ray, h);
  if (hit != (first != nullptr)) return hit ? "intersect hits, no crossing" : "crossing, no hit";
  if (hit && (h.t != first->hit.t || h.part != first->hit.part))
    return "intersect != first crossing";
  if (hit != shape.occluded(ray)) return "occluded disagrees with intersect";
  if (hit && h.shape != &shape) return "hit names another shape";
  return "";
}

}  // namespace lucent::test
