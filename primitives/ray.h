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

}  // namespace lucent
