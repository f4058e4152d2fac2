// A ray o + t·d searched over the parameter range [tmin, tmax] (the seeds' "ray intervals").
#pragma once

#include "interval.h"
#include "math.h"

namespace lucent {

// The direction is not required to be unit length: rays carried into object space keep
// the world's parameter t, so hit distances never need converting between spaces.
struct Ray {
  Vec3 o{0.0};
  Vec3 d{0.0, 0.0, -1.0};
  double tmin = 0.0;
  double tmax = kInf;

  Ray() = default;
  Ray(const Vec3& origin, const Vec3& direction, double tmin_ = 0.0, double tmax_ = kInf)
      : o(origin), d(direction), tmin(tmin_), tmax(tmax_) {}

  Vec3 at(double t) const { return o + t * d; }
  Interval range() const { return {tmin, tmax}; }
};

// A copy read member by member. A ray written member by member just before (spawned,
// transformed) and read back whole, in one 64-byte load, cannot take its bytes from the
// stores still in flight, and the load waits until they reach the cache; a per-member
// copy does not wait. The searches of the ray path copy their ray with this
// (docs/performance-history.md, "The world split by job").
inline Ray copyByMembers(const Ray& r) { return Ray(r.o, r.d, r.tmin, r.tmax); }

}  // namespace lucent
